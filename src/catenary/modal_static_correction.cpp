#include "modal_static_correction.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cstdio>
#include <functional>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/newton/interface_schur.hpp"
#include "catena/solvers/newton/mumps_status.hpp"

namespace catena::catenary::detail {
namespace {

using KspHandle = catena::KspHandle;

// Right-hand sides per block solve: MUMPS and PETSc's LU solve a block of columns at once
// several times faster per column than one by one.
constexpr PetscInt kBlock = 64;

// The catenary's stiffness factored once: K with the pantographs' rows and columns replaced by
// the identity (they are not coupled to the catenary by K: the contact is not in it). On one
// rank PETSc's LU (nested dissection; K is positive definite, no pivoting needed; 4–5 times
// faster than MUMPS on lines, docs/performance.md); on more, the same LU on each rank's
// interior and the partition interface's Schur complement (solvers/newton/interface_schur:
// 1.85 s for EN 50318's 4893 site solves at np 2, against 10.3 s with MUMPS's LDLᵀ).
class CatenarySolver {
 public:
  CatenarySolver(Mat K, const std::vector<PetscInt>& held) {
    CATENA_PETSC(MatDuplicate(K, MAT_COPY_VALUES, K_.out()));
    PetscInt first = 0, end = 0;
    CATENA_PETSC(MatGetOwnershipRange(K_.get(), &first, &end));
    std::vector<PetscInt> owned;
    for (PetscInt g : held)
      if (g >= first && g < end) owned.push_back(g);
    CATENA_PETSC(MatZeroRowsColumns(K_.get(), static_cast<PetscInt>(owned.size()), owned.data(),
                                    1.0, nullptr, nullptr));
    CATENA_PETSC(MatSetOption(K_.get(), MAT_SYMMETRIC, PETSC_TRUE));
    MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(K));
    int size = 1;
    MPI_Comm_size(comm, &size);
    ksp_ = solvers::create_direct_ksp(
        comm, "modal_correction_",
        size == 1 ? solvers::JacobianSymmetry::general : solvers::JacobianSymmetry::symmetric,
        solvers::Pivoting::not_needed);
    CATENA_PETSC(KSPSetOperators(ksp_.get(), K_.get(), K_.get()));
    if (solvers::use_interface_split(comm, "modal_correction_", solvers::Pivoting::not_needed))
      solvers::use_interface_schur(ksp_.get(), K_.get());
    CATENA_PETSC(KSPSetUp(ksp_.get()));
    check("factor");
    first_ = first;
    end_ = end;
  }

  // Solves K x = b for each load in `loads` (a site, or the vector `load` where the site is
  // null), a block at a time, and calls use(k, x) with the local part of solution k, in order.
  void solve_each(const std::vector<const SiteVector*>& loads, Vec load,
                  const std::function<void(std::size_t, const double*)>& use) {
    MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(K_.get()));
    const PetscInt n_local = end_ - first_;
    PetscInt n_global = 0;
    CATENA_PETSC(MatGetSize(K_.get(), &n_global, nullptr));
    for (std::size_t begin = 0; begin < loads.size(); begin += kBlock) {
      const auto count = static_cast<PetscInt>(std::min<std::size_t>(kBlock, loads.size() - begin));
      MatHandle B, X;
      CATENA_PETSC(MatCreateDense(comm, n_local, PETSC_DECIDE, n_global, count, nullptr, B.out()));
      CATENA_PETSC(MatCreateDense(comm, n_local, PETSC_DECIDE, n_global, count, nullptr, X.out()));
      double* b = nullptr;
      PetscInt ld = 0;
      CATENA_PETSC(MatDenseGetLDA(B.get(), &ld));
      CATENA_PETSC(MatDenseGetArrayWrite(B.get(), &b));
      std::fill(b, b + ld * count, 0.0);
      for (PetscInt c = 0; c < count; ++c) {
        double* column = b + ld * c;
        if (const SiteVector* site = loads[begin + static_cast<std::size_t>(c)]) {
          for (std::size_t k = 0; k < site->dofs.size(); ++k)
            if (site->dofs[k] >= first_ && site->dofs[k] < end_)
              column[site->dofs[k] - first_] += site->weights[k];
        } else {
          const double* a = nullptr;
          CATENA_PETSC(VecGetArrayRead(load, &a));
          std::copy(a, a + n_local, column);
          CATENA_PETSC(VecRestoreArrayRead(load, &a));
        }
      }
      CATENA_PETSC(MatDenseRestoreArrayWrite(B.get(), &b));
      CATENA_PETSC(KSPMatSolve(ksp_.get(), B.get(), X.get()));
      check("solve");
      const double* x = nullptr;
      CATENA_PETSC(MatDenseGetLDA(X.get(), &ld));
      CATENA_PETSC(MatDenseGetArrayRead(X.get(), &x));
      for (PetscInt c = 0; c < count; ++c) use(begin + static_cast<std::size_t>(c), x + ld * c);
      CATENA_PETSC(MatDenseRestoreArrayRead(X.get(), &x));
    }
  }

  // This rank's part of site·x (x: a solution's local part).
  double local_dot(const SiteVector& site, const double* x) const {
    double s = 0.0;
    for (std::size_t k = 0; k < site.dofs.size(); ++k)
      if (site.dofs[k] >= first_ && site.dofs[k] < end_)
        s += site.weights[k] * x[site.dofs[k] - first_];
    return s;
  }

 private:
  void check(const char* what) const {
    if (const solvers::DirectSolveStatus s = solvers::direct_solve_status(ksp_.get()); s.failed())
      throw NumericalError(std::string("modal model: the static correction's ") + what +
                           " of the catenary's stiffness failed (" + s.describe() + ")");
  }

  MatHandle K_;
  KspHandle ksp_;
  PetscInt first_ = 0, end_ = 0;
};

// Σ_m a_m b_m / ω_m²: the retained modes' part of the flexibility between two sites.
double modal_part(const double* a, const double* b, const std::vector<double>& omega) {
  double s = 0.0;
  for (std::size_t m = 0; m < omega.size(); ++m) s += a[m] * b[m] / (omega[m] * omega[m]);
  return s;
}

void sum_all(std::vector<double>& v, MPI_Comm comm) {
  if (!v.empty())
    MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, comm);
}

}  // namespace

int add_static_correction(Mat K, Vec f0, const std::vector<PetscInt>& held,
                          const std::vector<ContactSites>& contact_sites,
                          const std::vector<SiteVector>& dropper_sites,
                          solvers::ModalModel& model) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(K));
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  solvers::ModalDynamics& d = model.dynamics;
  const std::vector<double>& omega = d.omega;
  const std::size_t n = omega.size(), nd = dropper_sites.size();
  CatenarySolver solver(K, held);
  int solves = 0;
  const auto dropper_row = [&](std::size_t j) { return d.droppers[j].elongation.data(); };
  // Every site's load vector dotted with x (a solution's local part): the droppers, then
  // each contact's path sites, summed over the ranks.
  const auto every_site = [&](const double* x) {
    std::vector<double> dots;
    for (std::size_t i = 0; i < nd; ++i) dots.push_back(solver.local_dot(dropper_sites[i], x));
    for (const ContactSites& cs : contact_sites)
      for (const SiteVector& s : cs.node_sites) dots.push_back(solver.local_dot(s, x));
    sum_all(dots, comm);
    return dots;
  };

  // Droppers' columns: R between each dropper and every site.
  d.dropper_residual =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(nd), static_cast<Eigen::Index>(nd));
  for (std::size_t c = 0; c < d.contacts.size(); ++c)
    d.contacts[c].residual_dropper.assign(contact_sites[c].node_sites.size() * nd, 0.0);
  std::vector<const SiteVector*> columns;
  for (const SiteVector& site : dropper_sites) columns.push_back(&site);
  solver.solve_each(columns, nullptr, [&](std::size_t j, const double* x) {
    const std::vector<double> dots = every_site(x);
    ++solves;
    std::size_t k = 0;
    for (std::size_t i = 0; i < nd; ++i, ++k)
      d.dropper_residual(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          dots[k] - modal_part(dropper_row(i), dropper_row(j), omega);
    for (std::size_t c = 0; c < d.contacts.size(); ++c) {
      solvers::ModalContact& mc = d.contacts[c];
      for (std::size_t s = 0; s < contact_sites[c].node_sites.size(); ++s, ++k)
        mc.residual_dropper[s * nd + j] =
            dots[k] - modal_part(mc.rows.data() + s * n, dropper_row(j), omega);
    }
  });

  // Each contact's path sites: R within each path element (the sites of its two nodes).
  for (std::size_t c = 0; c < d.contacts.size(); ++c) {
    solvers::ModalContact& mc = d.contacts[c];
    const std::vector<SiteVector>& sites = contact_sites[c].node_sites;
    const std::size_t n_elements = mc.node_a.size();
    mc.residual.assign(16 * n_elements, 0.0);
    // Per path node: the elements touching it.
    std::vector<std::vector<std::size_t>> touching(sites.size() / 2);
    for (std::size_t e = 0; e < n_elements; ++e) {
      touching[static_cast<std::size_t>(mc.node_a[e])].push_back(e);
      touching[static_cast<std::size_t>(mc.node_b[e])].push_back(e);
    }
    columns.clear();
    for (const SiteVector& site : sites) columns.push_back(&site);
    solver.solve_each(columns, nullptr, [&](std::size_t col, const double* x) {
      const std::size_t node = col / 2;
      ++solves;
      std::vector<double> dots;  // per touching element: its four sites
      for (std::size_t e : touching[node])
        for (int b = 0; b < 4; ++b) {
          const std::size_t row =
              2 * static_cast<std::size_t>(b < 2 ? mc.node_a[e] : mc.node_b[e]) + (b % 2);
          dots.push_back(solver.local_dot(sites[row], x));
        }
      sum_all(dots, comm);
      std::size_t k = 0;
      for (std::size_t e : touching[node]) {
        const int col_in_e =
            (static_cast<std::size_t>(mc.node_a[e]) == node ? 0 : 2) + static_cast<int>(col % 2);
        for (int b = 0; b < 4; ++b, ++k) {
          const std::size_t row =
              2 * static_cast<std::size_t>(b < 2 ? mc.node_a[e] : mc.node_b[e]) + (b % 2);
          mc.residual[16 * e + 4 * static_cast<std::size_t>(b) +
                      static_cast<std::size_t>(col_in_e)] =
              dots[k] - modal_part(mc.rows.data() + row * n, mc.rows.data() + col * n, omega);
        }
      }
      if (col % 1000 == 999 && rank == 0) {
        std::printf("modal model: static correction, %zu of %zu sites of '%s'\n", col + 1,
                    sites.size(), mc.name.c_str());
        std::fflush(stdout);
      }
    });
  }

  // The constant load's residual static displacement at every site.
  VecHandle load;
  CATENA_PETSC(VecDuplicate(f0, load.out()));
  CATENA_PETSC(VecCopy(f0, load.get()));
  CATENA_PETSC(VecScale(load.get(), -1.0));
  {
    PetscInt first = 0, end = 0;
    CATENA_PETSC(VecGetOwnershipRange(load.get(), &first, &end));
    for (PetscInt g : held)
      if (g >= first && g < end) CATENA_PETSC(VecSetValue(load.get(), g, 0.0, INSERT_VALUES));
    CATENA_PETSC(VecAssemblyBegin(load.get()));
    CATENA_PETSC(VecAssemblyEnd(load.get()));
  }
  solver.solve_each({nullptr}, load.get(), [&](std::size_t, const double* x) {
    const std::vector<double> dots = every_site(x);
    ++solves;
    std::size_t k = 0;
    d.dropper_residual_static.resize(static_cast<Eigen::Index>(nd));
    for (std::size_t i = 0; i < nd; ++i, ++k)
      d.dropper_residual_static(static_cast<Eigen::Index>(i)) =
          dots[k] - modal_part(dropper_row(i), d.constant_load.data(), omega);
    for (std::size_t c = 0; c < d.contacts.size(); ++c) {
      solvers::ModalContact& mc = d.contacts[c];
      mc.residual_static.assign(contact_sites[c].node_sites.size(), 0.0);
      for (std::size_t s = 0; s < contact_sites[c].node_sites.size(); ++s, ++k)
        mc.residual_static[s] =
            dots[k] - modal_part(mc.rows.data() + s * n, d.constant_load.data(), omega);
    }
  });
  d.static_correction = true;
  return solves;
}

}  // namespace catena::catenary::detail

#include "catena/solvers/static_solver.hpp"

#include <petscsnes.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/solvers/mumps_status.hpp"

namespace catena::solvers {

struct StaticSolver::Impl {
  assembly::SecondOrderSystem& system;
  model::StaticOptions options;
  SnesHandle snes;
  VecHandle residual;
  MatHandle jacobian;
  CallbackGuard guard;
  double load_factor = 0.0;
  int n_jacobians = 0;  // in the current SNESSolve: only then has MUMPS factored

  Impl(assembly::SecondOrderSystem& s, const model::StaticOptions& o) : system(s), options(o) {}

  static PetscErrorCode form_function(SNES, Vec q, Vec f, void* ctx) {
    auto* self = static_cast<Impl*>(ctx);
    return self->guard.run([&] {
      self->system.force({q, nullptr, self->load_factor}, f);
    });
  }
  static PetscErrorCode form_jacobian(SNES, Vec q, Mat J, Mat, void* ctx) {
    auto* self = static_cast<Impl*>(ctx);
    ++self->n_jacobians;
    return self->guard.run([&] {
      self->system.jacobian({q, nullptr, self->load_factor}, {1.0, 0.0, 0.0}, J);
    });
  }
};

StaticSolver::StaticSolver(assembly::SecondOrderSystem& system, const model::StaticOptions& options)
    : impl_(std::make_unique<Impl>(system, options)) {
  Impl& s = *impl_;
  s.residual = system.create_vector();
  s.jacobian = system.create_matrix();
  CATENA_PETSC(SNESCreate(system.comm(), s.snes.out()));
  CATENA_PETSC(SNESSetOptionsPrefix(s.snes.get(), "static_"));
  CATENA_PETSC(SNESSetFunction(s.snes.get(), s.residual.get(), Impl::form_function, &s));
  CATENA_PETSC(SNESSetJacobian(s.snes.get(), s.jacobian.get(), s.jacobian.get(),
                               Impl::form_jacobian, &s));
  CATENA_PETSC(SNESSetType(s.snes.get(), SNESNEWTONLS));
  // Converge on the residual only: a small Newton step alone proves nothing.
  CATENA_PETSC(SNESSetTolerances(s.snes.get(), options.atol, options.rtol, 0.0,
                                 options.max_newton_iterations, 100000));
  KSP ksp = nullptr;
  PC pc = nullptr;
  CATENA_PETSC(SNESGetKSP(s.snes.get(), &ksp));
  CATENA_PETSC(KSPSetType(ksp, KSPPREONLY));
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  CATENA_PETSC(PCSetType(pc, PCLU));
  CATENA_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  enable_mumps_null_pivot_detection("static_");
  CATENA_PETSC(SNESSetFromOptions(s.snes.get()));
}

StaticSolver::~StaticSolver() = default;

namespace {

// "node 17 (id 4017), component y" for the largest |f| entry.
std::string largest_residual_location(const assembly::SecondOrderSystem& system, Vec f) {
  PetscInt where = -1;
  PetscReal value = 0.0;
  VecHandle abs_f;
  if (VecDuplicate(f, abs_f.out()) || VecCopy(f, abs_f.get()) || VecAbs(abs_f.get()) ||
      VecMax(abs_f.get(), &where, &value) || where < 0)
    return "unknown";
  static const char* names[12] = {"x",    "y",    "z",    "rx_x", "rx_y", "rx_z",
                                  "ry_x", "ry_y", "ry_z", "rz_x", "rz_y", "rz_z"};
  const auto& dofs = system.dof_map();
  const int node = dofs.node_of_global(where);
  const int comp = dofs.component_of_global(where);
  std::ostringstream os;
  os << "node id " << system.model().nodes[node].id << " (" << (comp >= 0 ? names[comp] : "?")
     << "), |f| = " << value << " N";
  return os.str();
}

}  // namespace

StaticReport StaticSolver::solve(Vec q) {
  Impl& s = *impl_;
  StaticReport report;
  VecHandle q_trial;
  CATENA_PETSC(VecDuplicate(q, q_trial.out()));

  double lambda = 0.0;
  double step = std::clamp(s.options.initial_load_step, s.options.min_load_step, 1.0);
  int attempts = 0;
  while (lambda < 1.0) {
    if (attempts++ >= s.options.max_load_steps) break;
    const double target = std::min(1.0, lambda + step);
    s.load_factor = target;
    CATENA_PETSC(VecCopy(q, q_trial.get()));
    s.n_jacobians = 0;
    const PetscErrorCode ierr = SNESSolve(s.snes.get(), nullptr, q_trial.get());
    s.guard.rethrow_if_any();
    CATENA_PETSC(ierr);

    SNESConvergedReason reason;
    PetscInt its = 0;
    CATENA_PETSC(SNESGetConvergedReason(s.snes.get(), &reason));
    CATENA_PETSC(SNESGetIterationNumber(s.snes.get(), &its));
    report.n_newton_iterations += static_cast<int>(its);
    KSP ksp = nullptr;
    CATENA_PETSC(SNESGetKSP(s.snes.get(), &ksp));
    const MumpsStatus mumps = s.n_jacobians > 0 ? mumps_status(ksp) : MumpsStatus{};
    if (mumps.null_pivots > 0 || mumps.infog1 == -10)
      throw NumericalError(
          "static solve: the stiffness matrix is singular at load factor " +
          std::to_string(target) + " (MUMPS found " + std::to_string(mumps.null_pivots) +
          " null pivots, INFOG(1) = " + std::to_string(mumps.infog1) +
          "): the structure is a mechanism. Check supports (a pinned cable end also needs "
          "the other end held) and that every node is connected.");
    if (mumps.infog1 < 0)
      throw NumericalError("static solve: MUMPS failed with INFOG(1) = " +
                           std::to_string(mumps.infog1) + ", INFOG(2) = " +
                           std::to_string(mumps.infog2) + " at load factor " +
                           std::to_string(target));

    if (reason > 0) {
      CATENA_PETSC(VecCopy(q_trial.get(), q));
      lambda = target;
      ++report.n_load_steps;
      if (its <= 4) step = std::min(1.0, 2.0 * step);
    } else {
      ++report.n_rejected_steps;
      step *= 0.5;
      if (step < s.options.min_load_step) break;
    }
  }

  // Residual at the returned state (the last converged load level).
  s.load_factor = lambda;
  s.system.force({q, nullptr, lambda}, s.residual.get());
  PetscReal norm = 0.0;
  CATENA_PETSC(VecNorm(s.residual.get(), NORM_2, &norm));
  report.load_factor = lambda;
  report.residual_norm = norm;
  if (lambda < 1.0) {
    // Report where the failed attempt left the largest residual.
    s.load_factor = std::min(1.0, lambda + step);
    s.system.force({q_trial.get(), nullptr, s.load_factor}, s.residual.get());
    std::ostringstream os;
    os << "static solve did not converge: reached load factor " << lambda << " of 1 after "
       << report.n_load_steps << " accepted and " << report.n_rejected_steps
       << " rejected load steps (" << report.n_newton_iterations
       << " Newton iterations); at the last attempt (load factor " << s.load_factor
       << ") the largest residual is at " << largest_residual_location(s.system, s.residual.get())
       << ". Try a smaller analysis.load_steps.initial or more analysis.newton.max_iterations.";
    throw NumericalError(os.str());
  }
  return report;
}

}  // namespace catena::solvers

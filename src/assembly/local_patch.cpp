// SecondOrderSystem's local patches (catena/assembly/local_patch.hpp): building them and
// evaluating forces, mass products and Newton-matrix blocks on a few couplings.
#include <algorithm>
#include <stdexcept>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/mpi_comm.hpp"
#include "local_array.hpp"

namespace catena::assembly {
namespace {

using couplings::PatchRole;

PetscInt position_in(const std::vector<PetscInt>& sorted, PetscInt value) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), value);
  return it != sorted.end() && *it == value ? static_cast<PetscInt>(it - sorted.begin()) : -1;
}

// Marks added at the owner of a DOF: by a coupling excluded from patches, and by a coupling
// active at patch time (which blocks the DOF unless it is the owner's own).
constexpr double kExcluded = 1e9;

}  // namespace

void SecondOrderSystem::prepare_local_patches() {
  const PetscInt n = dofs_.n_owned();
  auto role = [&](size_t i) { return couplings_[i]->patch_role(); };
  // Kernel couplings per owned DOF (CSR), and the kernel couplings that reach a ghost.
  std::vector<size_t> count(static_cast<size_t>(n) + 1, 0);
  std::vector<char> reaches_ghost(couplings_.size(), 0);
  for (size_t k = 0; k < couplings_.size(); ++k) {
    if (role(k) != PatchRole::kernel) continue;
    for (size_t i = offset_[k]; i < offset_[k + 1]; ++i) {
      const PetscInt l = local_index_[i];
      if (l >= n)
        reaches_ghost[k] = 1;
      else if (l >= 0)
        ++count[static_cast<size_t>(l) + 1];
    }
  }
  for (size_t l = 0; l < static_cast<size_t>(n); ++l) count[l + 1] += count[l];
  dof_kernel_start_ = count;
  dof_kernels_.assign(count.back(), 0);
  for (size_t k = 0; k < couplings_.size(); ++k)
    if (role(k) == PatchRole::kernel)
      for (size_t i = offset_[k]; i < offset_[k + 1]; ++i)
        if (const PetscInt l = local_index_[i]; l >= 0 && l < n)
          dof_kernels_[count[static_cast<size_t>(l)]++] = k;

  // Kernel couplings of every rank per DOF, summed at the owner: a DOF that other ranks'
  // kernels touch too cannot be changed by this rank alone.
  VecHandle touches = create_vector();
  {
    detail::LocalArrayWrite local(touches.get());
    CATENA_PETSC(VecSet(local.local(), 0.0));  // ghosts too (create_vector zeroes the owned part)
    for (size_t k = 0; k < couplings_.size(); ++k)
      if (role(k) == PatchRole::kernel)
        for (size_t i = offset_[k]; i < offset_[k + 1]; ++i)
          if (const PetscInt l = local_index_[i]; l >= 0) local.data()[l] += 1.0;
  }
  CATENA_PETSC(VecGhostUpdateBegin(touches.get(), ADD_VALUES, SCATTER_REVERSE));
  CATENA_PETSC(VecGhostUpdateEnd(touches.get(), ADD_VALUES, SCATTER_REVERSE));

  // Every DOF of the nodes an excluded coupling acts on, and of the nodes a coupling active
  // at patch time may reach (unless that coupling is the owner's own: local_patch checks
  // those at the patch's time), marked at the owner.
  VecHandle marks = create_vector();
  std::vector<double> own(static_cast<size_t>(n), 0.0);
  for (size_t k = 0; k < couplings_.size(); ++k) {
    if (role(k) != PatchRole::excluded && role(k) != PatchRole::at_patch_time) continue;
    const double mark = role(k) == PatchRole::excluded ? kExcluded : 1.0;
    std::vector<int> nodes;
    for (const couplings::DofKey& key : couplings_[k]->dofs())
      if (key.kind == couplings::DofKey::Kind::node) nodes.push_back(key.index);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (int node : nodes)
      for (int c = 0; c < dofs_.node_dofs(node); ++c) {
        const PetscInt g = dofs_.global_dof(node, c);
        if (g < 0) continue;
        CATENA_PETSC(VecSetValue(marks.get(), g, mark, ADD_VALUES));
        if (mark == 1.0 && g >= dofs_.first_owned() && g < dofs_.first_owned() + n)
          own[static_cast<size_t>(g - dofs_.first_owned())] += 1.0;
      }
  }
  CATENA_PETSC(VecAssemblyBegin(marks.get()));
  CATENA_PETSC(VecAssemblyEnd(marks.get()));

  patch_eligible_.assign(static_cast<size_t>(n), 0);
  {
    const detail::LocalArrayRead all(touches.get());
    const detail::LocalArrayRead marked(marks.get());
    for (PetscInt l = 0; l < n; ++l) {
      const size_t here = dof_kernel_start_[l + 1] - dof_kernel_start_[l];
      patch_eligible_[l] = here > 0 && all.data()[l] == static_cast<double>(here) &&
                           marked.data()[l] == own[static_cast<size_t>(l)];
    }
  }
  for (size_t k = 0; k < couplings_.size(); ++k)
    if (reaches_ghost[k])
      for (size_t i = offset_[k]; i < offset_[k + 1]; ++i)
        if (const PetscInt l = local_index_[i]; l >= 0 && l < n) patch_eligible_[l] = 0;
  patch_mark_.assign(static_cast<size_t>(n), 0);
}

LocalPatch SecondOrderSystem::local_patch(const std::vector<PetscInt>& seeds, int layers,
                                          double t) {
  if (patch_mark_.size() != static_cast<size_t>(dofs_.n_owned()))
    throw std::logic_error("SecondOrderSystem::local_patch before prepare_local_patches");
  const PetscInt n = dofs_.n_owned();
  // This rank's couplings active at t (contacts on their paths): each couples its active
  // DOFs like a kernel.
  std::vector<size_t> timed;
  std::vector<std::vector<PetscInt>> timed_local;
  for (size_t k : timed_) {
    const ActiveDofs dofs = active(k, t, nullptr, work_);  // contacts: by time
    if (dofs.n == 0) continue;
    timed.push_back(k);
    timed_local.emplace_back(dofs.local, dofs.local + dofs.n);
  }
  auto touches = [](const std::vector<PetscInt>& local, PetscInt l) {
    return std::find(local.begin(), local.end(), l) != local.end();
  };

  std::vector<PetscInt> reached, frontier;
  auto reach = [&](PetscInt m, std::vector<PetscInt>& into) {
    if (m >= 0 && m < n && !patch_mark_[m]) {
      patch_mark_[m] = 1;
      into.push_back(m);
    }
  };
  for (PetscInt l : seeds) reach(l, reached);
  frontier = reached;
  for (int layer = 0; layer < layers && !frontier.empty(); ++layer) {
    std::vector<PetscInt> next;
    for (PetscInt l : frontier) {
      for (size_t j = dof_kernel_start_[l]; j < dof_kernel_start_[l + 1]; ++j) {
        const size_t k = dof_kernels_[j];
        for (size_t i = offset_[k]; i < offset_[k + 1]; ++i) reach(local_index_[i], next);
      }
      for (const auto& local : timed_local)
        if (touches(local, l))
          for (PetscInt m : local) reach(m, next);
    }
    reached.insert(reached.end(), next.begin(), next.end());
    frontier = std::move(next);
  }
  LocalPatch patch;
  patch.t = t;
  for (PetscInt l : reached) {
    patch_mark_[l] = 0;
    if (patch_eligible_[l]) patch.unknowns.push_back(l);
  }
  std::sort(patch.unknowns.begin(), patch.unknowns.end());
  auto is_unknown = [&](PetscInt l) {
    return std::binary_search(patch.unknowns.begin(), patch.unknowns.end(), l);
  };
  // A timed coupling that reaches another rank's DOFs changes rows this rank does not own:
  // its DOFs stay fixed. The others acting on the unknowns join the patch.
  for (const auto& local : timed_local)
    if (std::any_of(local.begin(), local.end(), [&](PetscInt l) { return l >= n; }))
      patch.unknowns.erase(std::remove_if(patch.unknowns.begin(), patch.unknowns.end(),
                                          [&](PetscInt l) { return touches(local, l); }),
                           patch.unknowns.end());
  std::vector<const std::vector<PetscInt>*> joined;  // active local DOFs of each joined one
  std::vector<size_t> joined_couplings;
  for (size_t i = 0; i < timed.size(); ++i)
    if (std::any_of(timed_local[i].begin(), timed_local[i].end(), is_unknown)) {
      joined_couplings.push_back(timed[i]);
      joined.push_back(&timed_local[i]);
    }

  for (PetscInt l : patch.unknowns)
    for (size_t j = dof_kernel_start_[l]; j < dof_kernel_start_[l + 1]; ++j)
      patch.couplings.push_back(dof_kernels_[j]);
  std::sort(patch.couplings.begin(), patch.couplings.end());
  patch.couplings.erase(std::unique(patch.couplings.begin(), patch.couplings.end()),
                        patch.couplings.end());
  const size_t n_kernels = patch.couplings.size();
  for (size_t k : patch.couplings)
    for (size_t i = offset_[k]; i < offset_[k + 1]; ++i)
      if (local_index_[i] >= 0) patch.rows.push_back(local_index_[i]);  // owned: eligibility
  for (const auto* local : joined)
    for (PetscInt l : *local)
      if (l >= 0) patch.rows.push_back(l);
  std::sort(patch.rows.begin(), patch.rows.end());
  patch.rows.erase(std::unique(patch.rows.begin(), patch.rows.end()), patch.rows.end());
  for (size_t c = 0; c < n_kernels; ++c)
    for (size_t i = offset_[patch.couplings[c]]; i < offset_[patch.couplings[c] + 1]; ++i)
      patch.coupling_rows.push_back(local_index_[i] >= 0 ? position_in(patch.rows, local_index_[i])
                                                         : -1);
  for (const auto* local : joined)
    for (PetscInt l : *local)
      patch.coupling_rows.push_back(l >= 0 ? position_in(patch.rows, l) : -1);
  patch.couplings.insert(patch.couplings.end(), joined_couplings.begin(), joined_couplings.end());
  patch.n_timed = joined_couplings.size();
  for (PetscInt r : patch.rows) patch.unknown_of_row.push_back(position_in(patch.unknowns, r));
  return patch;
}

void SecondOrderSystem::patch_force(const LocalPatch& patch, const double* q, const double* v,
                                    double* f_rows) const {
  std::fill(f_rows, f_rows + patch.rows.size(), 0.0);
  Buffers b;
  const PetscInt* row = patch.coupling_rows.data();
  for (size_t k : patch.couplings) {
    const ActiveDofs dofs = active(k, patch.t, q, b);
    b.f.resize(std::max(b.f.size(), dofs.n));
    evaluate(k, dofs, q, v, {}, patch.t, b.f.data(), {}, b);
    const double* f = scale_force(dofs, b.f.data(), b.scaled);
    for (size_t i = 0; i < dofs.n; ++i)
      if (row[i] >= 0) f_rows[row[i]] += f[i];
    row += dofs.n;
  }
}

void SecondOrderSystem::patch_mass_product(const LocalPatch& patch, const double* d,
                                           double* out_rows) const {
  std::fill(out_rows, out_rows + patch.rows.size(), 0.0);
  Buffers b;
  std::vector<double> d_el;
  const PetscInt* row = patch.coupling_rows.data();
  for (size_t k : patch.couplings) {
    const ActiveDofs dofs = active(k, patch.t, nullptr, b);  // kernels and contacts only
    const size_t nd = dofs.n;
    if (couplings_[k]->patch_role() != PatchRole::kernel) {  // only kernels carry mass
      row += nd;
      continue;
    }
    b.block.resize(std::max(b.block.size(), nd * nd));
    const couplings::MatrixRequest mass{{0.0, 0.0, 1.0}, b.block.data()};
    couplings_[k]->evaluate({}, nullptr, {&mass, 1}, b.scratch);
    const double* M = scale_block(dofs, b.block.data(), b.scaled);
    d_el.resize(nd);
    for (size_t i = 0; i < nd; ++i) {
      const PetscInt u = row[i] >= 0 ? patch.unknown_of_row[row[i]] : -1;
      d_el[i] = u >= 0 ? d[u] : 0.0;
    }
    for (size_t i = 0; i < nd; ++i) {
      if (row[i] < 0) continue;
      double sum = 0.0;
      for (size_t j = 0; j < nd; ++j) sum += M[i * nd + j] * d_el[j];
      out_rows[row[i]] += sum;
    }
    row += nd;
  }
}

std::vector<PatchEntry> SecondOrderSystem::patch_matrix(const LocalPatch& patch, const double* q,
                                                        const double* v,
                                                        const JacobianCoefficients& c) const {
  std::vector<PatchEntry> entries;
  Buffers b;
  std::vector<PetscInt> unknown;
  const PetscInt* row = patch.coupling_rows.data();
  for (size_t k : patch.couplings) {
    const ActiveDofs dofs = active(k, patch.t, q, b);
    const size_t nd = dofs.n;
    b.block.resize(std::max(b.block.size(), nd * nd));
    const couplings::MatrixRequest request{c, b.block.data()};
    evaluate(k, dofs, q, v, {}, patch.t, nullptr, {&request, 1}, b);
    unknown.resize(nd);
    for (size_t i = 0; i < nd; ++i) unknown[i] = row[i] >= 0 ? patch.unknown_of_row[row[i]] : -1;
    row += nd;
    const double* J = scale_block(dofs, b.block.data(), b.scaled);
    // A sparse coupling whose block vanishes (a contact out of contact) adds no entries.
    if (!couplings_[k]->dense() && std::all_of(J, J + nd * nd, [](double x) { return x == 0.0; }))
      continue;
    for (size_t i = 0; i < nd; ++i) {
      if (unknown[i] < 0) continue;
      for (size_t j = 0; j < nd; ++j)
        if (unknown[j] >= 0) entries.push_back({unknown[i], unknown[j], J[i * nd + j]});
    }
  }
  return entries;
}

}  // namespace catena::assembly

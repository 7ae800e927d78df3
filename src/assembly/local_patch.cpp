// SecondOrderSystem's local patches (catena/assembly/local_patch.hpp): building them and
// evaluating forces, mass products and Newton-matrix blocks on a few kernels.
#include <algorithm>
#include <stdexcept>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/mpi_comm.hpp"
#include "local_array.hpp"

namespace catena::assembly {
namespace {

PetscInt position_in(const std::vector<PetscInt>& sorted, PetscInt value) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), value);
  return it != sorted.end() && *it == value ? static_cast<PetscInt>(it - sorted.begin()) : -1;
}

}  // namespace

void SecondOrderSystem::prepare_local_patches() {
  const PetscInt n = dofs_.n_owned();
  // Kernels per owned DOF (CSR), and the kernels that reach a ghost.
  std::vector<size_t> count(static_cast<size_t>(n) + 1, 0);
  std::vector<char> reaches_ghost(kernels_.size(), 0);
  for (size_t k = 0; k < kernels_.size(); ++k)
    for (size_t i = kernel_offset_[k]; i < kernel_offset_[k + 1]; ++i) {
      const PetscInt l = local_index_[i];
      if (l >= n) reaches_ghost[k] = 1;
      else if (l >= 0) ++count[static_cast<size_t>(l) + 1];
    }
  for (size_t l = 0; l < static_cast<size_t>(n); ++l) count[l + 1] += count[l];
  dof_kernel_start_ = count;
  dof_kernels_.assign(count.back(), 0);
  for (size_t k = 0; k < kernels_.size(); ++k)
    for (size_t i = kernel_offset_[k]; i < kernel_offset_[k + 1]; ++i)
      if (const PetscInt l = local_index_[i]; l >= 0 && l < n)
        dof_kernels_[count[static_cast<size_t>(l)]++] = k;

  // Kernels of every rank per DOF, summed at the owner: a DOF that other ranks' kernels
  // touch too cannot be changed by this rank alone.
  VecHandle touches = create_vector();
  {
    detail::LocalArrayWrite local(touches.get());
    CATENA_PETSC(VecSet(local.local(), 0.0));  // ghosts too (create_vector zeroes the owned part)
    for (size_t k = 0; k < kernels_.size(); ++k)
      for (size_t i = kernel_offset_[k]; i < kernel_offset_[k + 1]; ++i)
        if (const PetscInt l = local_index_[i]; l >= 0) local.data()[l] += 1.0;
  }
  CATENA_PETSC(VecGhostUpdateBegin(touches.get(), ADD_VALUES, SCATTER_REVERSE));
  CATENA_PETSC(VecGhostUpdateEnd(touches.get(), ADD_VALUES, SCATTER_REVERSE));
  patch_eligible_.assign(static_cast<size_t>(n), 0);
  {
    const detail::LocalArrayRead all(touches.get());
    for (PetscInt l = 0; l < n; ++l) {
      const size_t here = dof_kernel_start_[l + 1] - dof_kernel_start_[l];
      patch_eligible_[l] = here > 0 && all.data()[l] == static_cast<double>(here);
    }
  }
  for (size_t k = 0; k < kernels_.size(); ++k)
    if (reaches_ghost[k])
      for (size_t i = kernel_offset_[k]; i < kernel_offset_[k + 1]; ++i)
        if (const PetscInt l = local_index_[i]; l >= 0 && l < n) patch_eligible_[l] = 0;
  // Constraints act on these nodes with forces patch_force leaves out, and so do moving
  // contacts that another rank evaluates (this rank's own are checked per patch, at the
  // patch's time: local_patch).
  auto exclude_node = [&](int node) {
    for (int c = 0; c < dofs_.node_dofs(node); ++c)
      if (const PetscInt l = dofs_.local_dof(node, c); l >= 0 && l < n) patch_eligible_[l] = 0;
  };
  for (const model::Constraint& c : model_->constraints) {
    exclude_node(c.node_a);
    if (c.node_b >= 0) exclude_node(c.node_b);
  }
  const int rank = mpi_rank(comm_);
  for (const model::MovingContact& c : model_->contacts) {
    if (partition_.node_owner[c.head_node] == rank) continue;
    exclude_node(c.head_node);
    for (int e : model_->paths[static_cast<size_t>(c.path)].elements)
      for (int node : model_->elements[static_cast<size_t>(e)].nodes) exclude_node(node);
  }
  patch_mark_.assign(static_cast<size_t>(n), 0);
}

LocalPatch SecondOrderSystem::local_patch(const std::vector<PetscInt>& seeds, int layers,
                                          double t) {
  if (patch_mark_.size() != static_cast<size_t>(dofs_.n_owned()))
    throw std::logic_error("SecondOrderSystem::local_patch before prepare_local_patches");
  const PetscInt n = dofs_.n_owned();
  // This rank's contacts on their paths at t: each couples its 15 DOFs like a kernel.
  std::vector<ContactGeometry> geometry;
  std::vector<size_t> on_path;
  for (size_t c = 0; c < contacts_.size(); ++c) {
    ContactGeometry g;
    if (!contact_geometry(contacts_[c], t, g)) continue;
    geometry.push_back(g);
    on_path.push_back(c);
  }
  auto touches = [](const ContactGeometry& g, PetscInt l) {
    return std::find(std::begin(g.local), std::end(g.local), l) != std::end(g.local);
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
        for (size_t i = kernel_offset_[k]; i < kernel_offset_[k + 1]; ++i) reach(local_index_[i], next);
      }
      for (const ContactGeometry& g : geometry)
        if (touches(g, l))
          for (PetscInt m : g.local) reach(m, next);
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
  // A contact whose wire element reaches another rank's DOFs changes rows this rank does
  // not own: its DOFs stay fixed. The others acting on the unknowns join the patch.
  for (const ContactGeometry& g : geometry)
    if (std::any_of(std::begin(g.local), std::end(g.local), [&](PetscInt l) { return l >= n; }))
      patch.unknowns.erase(std::remove_if(patch.unknowns.begin(), patch.unknowns.end(),
                                          [&](PetscInt l) { return touches(g, l); }),
                           patch.unknowns.end());
  std::vector<const ContactGeometry*> joined;  // geometry of each of patch.contacts
  for (size_t i = 0; i < geometry.size(); ++i)
    if (std::any_of(std::begin(geometry[i].local), std::end(geometry[i].local), is_unknown)) {
      patch.contacts.push_back(on_path[i]);
      joined.push_back(&geometry[i]);
    }

  for (PetscInt l : patch.unknowns)
    for (size_t j = dof_kernel_start_[l]; j < dof_kernel_start_[l + 1]; ++j)
      patch.kernels.push_back(dof_kernels_[j]);
  std::sort(patch.kernels.begin(), patch.kernels.end());
  patch.kernels.erase(std::unique(patch.kernels.begin(), patch.kernels.end()), patch.kernels.end());
  for (size_t k : patch.kernels)
    for (size_t i = kernel_offset_[k]; i < kernel_offset_[k + 1]; ++i)
      if (local_index_[i] >= 0) patch.rows.push_back(local_index_[i]);  // owned: eligibility
  for (const ContactGeometry* g : joined)
    for (PetscInt l : g->local)
      if (l >= 0) patch.rows.push_back(l);
  std::sort(patch.rows.begin(), patch.rows.end());
  patch.rows.erase(std::unique(patch.rows.begin(), patch.rows.end()), patch.rows.end());
  for (size_t k : patch.kernels)
    for (size_t i = kernel_offset_[k]; i < kernel_offset_[k + 1]; ++i)
      patch.kernel_rows.push_back(local_index_[i] >= 0 ? position_in(patch.rows, local_index_[i]) : -1);
  for (const ContactGeometry* g : joined)
    for (PetscInt l : g->local) patch.contact_rows.push_back(l >= 0 ? position_in(patch.rows, l) : -1);
  for (PetscInt r : patch.rows) patch.unknown_of_row.push_back(position_in(patch.unknowns, r));
  return patch;
}

size_t SecondOrderSystem::evaluate_owned(size_t k, const double* q, const double* v,
                                         elements::Request request, elements::LocalOutput out,
                                         double* q_el, double* v_el) const {
  const elements::Element& el = *kernels_[k].element;
  const size_t nd = static_cast<size_t>(el.n_dofs());
  gather(k, q, v, q_el, v_el);
  elements::LocalState s{{q_el, nd}, {}, {}};
  if (v) s.v = {v_el, nd};
  el.evaluate(s, request, out);
  return nd;
}

void SecondOrderSystem::patch_force(const LocalPatch& patch, const double* q, const double* v,
                                    double* f_rows) const {
  std::fill(f_rows, f_rows + patch.rows.size(), 0.0);
  const size_t m = max_kernel_dofs_;
  std::vector<double> q_el(m), v_el(m), f_el(m);
  const PetscInt* row = patch.kernel_rows.data();
  for (size_t k : patch.kernels) {
    const size_t nd = evaluate_owned(k, q, v, {true, false, false},
                                     {f_el.data(), nullptr, nullptr}, q_el.data(), v_el.data());
    for (size_t i = 0; i < nd; ++i)
      if (row[i] >= 0) f_rows[row[i]] += f_el[i];
    row += nd;
  }
  const PetscInt* contact_row = patch.contact_rows.data();
  ContactGeometry g;
  for (size_t ci : patch.contacts) {
    contact_geometry(contacts_[ci], patch.t, g);  // on its path: local_patch checked
    const double F = contact_force(model_->contacts[static_cast<size_t>(contacts_[ci].index)], g, q, v);
    for (int j = 0; j < 15; ++j)
      if (contact_row[j] >= 0) f_rows[contact_row[j]] += F * g.N[j];
    contact_row += 15;
  }
}

void SecondOrderSystem::patch_mass_product(const LocalPatch& patch, const double* d,
                                           double* out_rows) const {
  std::fill(out_rows, out_rows + patch.rows.size(), 0.0);
  const size_t m = max_kernel_dofs_;
  std::vector<double> M(m * m), d_el(m);
  const PetscInt* row = patch.kernel_rows.data();
  for (size_t k : patch.kernels) {
    const elements::Element& el = *kernels_[k].element;
    const size_t nd = static_cast<size_t>(el.n_dofs());
    el.mass(M.data());
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
  const size_t m = max_kernel_dofs_;
  std::vector<double> q_el(m), v_el(m), f_el(m), K(m * m), C(m * m), M(m * m);
  std::vector<PetscInt> unknown(m);
  const elements::Request request{false, c.c_K != 0.0, c.c_C != 0.0};
  const PetscInt* row = patch.kernel_rows.data();
  for (size_t k : patch.kernels) {
    const size_t nd = evaluate_owned(k, q, v, request, {f_el.data(), K.data(), C.data()},
                                     q_el.data(), v_el.data());
    if (c.c_M != 0.0) kernels_[k].element->mass(M.data());
    for (size_t i = 0; i < nd; ++i) unknown[i] = row[i] >= 0 ? patch.unknown_of_row[row[i]] : -1;
    for (size_t i = 0; i < nd; ++i) {
      if (unknown[i] < 0) continue;
      for (size_t j = 0; j < nd; ++j) {
        if (unknown[j] < 0) continue;
        double value = 0.0;
        if (request.stiffness) value += c.c_K * K[i * nd + j];
        if (request.damping) value += c.c_C * C[i * nd + j];
        if (c.c_M != 0.0) value += c.c_M * M[i * nd + j];
        entries.push_back({unknown[i], unknown[j], value});
      }
    }
    row += nd;
  }
  // Contacts in contact: K_ij = N_i (k N_j + c D_j), C_ij = c N_i N_j (add_contact_entries).
  const PetscInt* contact_row = patch.contact_rows.data();
  ContactGeometry g;
  for (size_t ci : patch.contacts) {
    const model::MovingContact& mc = model_->contacts[static_cast<size_t>(contacts_[ci].index)];
    contact_geometry(contacts_[ci], patch.t, g);
    PetscInt contact_unknown[15];
    for (int j = 0; j < 15; ++j)
      contact_unknown[j] = contact_row[j] >= 0 ? patch.unknown_of_row[contact_row[j]] : -1;
    contact_row += 15;
    if (contact_force(mc, g, q, v) == 0.0) continue;
    for (int i = 0; i < 15; ++i) {
      if (contact_unknown[i] < 0) continue;
      for (int j = 0; j < 15; ++j)
        if (contact_unknown[j] >= 0)
          entries.push_back({contact_unknown[i], contact_unknown[j],
                             g.N[i] * (c.c_K * (mc.stiffness * g.N[j] + mc.damping * g.D[j]) +
                                       c.c_C * mc.damping * g.N[j])});
    }
  }
  return entries;
}

}  // namespace catena::assembly

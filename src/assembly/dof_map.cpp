#include "catena/assembly/dof_map.hpp"

#include <algorithm>
#include <variant>

#include "catena/model/node_kinds.hpp"

namespace catena::assembly {

DofMap::DofMap(const model::Model& model, const Partition& partition, int rank,
               std::vector<int> touched)
    : partition_(&partition), rank_(rank) {
  const int n_nodes = static_cast<int>(model.nodes.size());
  node_kinds_ = model::node_kinds(model);
  std::vector<int> counts(n_nodes);
  node_offset_.assign(n_nodes + 1, 0);
  for (int n = 0; n < n_nodes; ++n) {
    counts[n] = model::kind_info(node_kinds_[n]).size;
    node_offset_[n + 1] = node_offset_[n] + counts[n];
  }

  std::vector<unsigned> fixed_mask(n_nodes, 0u);
  for (const auto& s : model.supports) fixed_mask[s.node] |= s.fixed_mask;
  // Slopes held in direction: the three slots of r_x share one unknown s, r_x = s·t.
  for (const auto& s : model.supports) {
    const int first = model::kind_info(node_kinds_[s.node]).gradients;
    if (!s.slope_direction || first < 0) continue;
    for (int d = 0; d < 3; ++d)
      linked_slots_.push_back(
          {node_offset_[s.node] + first + d, model.nodes[s.node].tangent[d], d == 0});
  }
  std::sort(linked_slots_.begin(), linked_slots_.end(),
            [](const LinkedSlot& a, const LinkedSlot& b) { return a.slot < b.slot; });

  // Global numbering: ranks in order, owned nodes ascending, DOFs in layout order.
  global_.assign(node_offset_.back(), -1);
  std::vector<std::vector<int>> nodes_of_rank(partition.n_parts);
  for (int n = 0; n < n_nodes; ++n) nodes_of_rank[partition.node_owner[n]].push_back(n);
  const int n_constraints = static_cast<int>(model.constraints.size());
  constraint_owner_.resize(n_constraints);
  multiplier_offset_.assign(1, 0);
  for (int c = 0; c < n_constraints; ++c) {
    constraint_owner_[c] = partition.node_owner[model.constraints[c].node_a];
    constraint_node_a_.push_back(model.constraints[c].node_a);
    multiplier_offset_.push_back(multiplier_offset_.back() + model.constraints[c].equations);
  }
  multiplier_.assign(static_cast<std::size_t>(multiplier_offset_.back()), -1);
  PetscInt next = 0;
  for (int r = 0; r < partition.n_parts; ++r) {
    if (r == rank) first_owned_ = next;
    for (int n : nodes_of_rank[r])
      for (int k = 0; k < counts[n]; ++k) {
        const int slot = node_offset_[n] + k;
        const LinkedSlot* link = linked_slot(n, k);
        if (link && !link->own) {
          global_[slot] = global_[slot - 1];
        } else if (!(fixed_mask[n] >> k & 1u)) {
          global_[slot] = next++;
        }
      }
    for (int c = 0; c < n_constraints; ++c)
      if (constraint_owner_[c] == r)
        for (int k = 0; k < n_multipliers(c); ++k)
          multiplier_[static_cast<std::size_t>(multiplier_offset_[c] + k)] = next++;
    if (r == rank) n_owned_ = next - first_owned_;
  }
  n_global_ = next;
  owned_nodes_ = nodes_of_rank[rank];

  // Local indices: owned DOFs first, then ghosts (free DOFs of touched, non-owned nodes),
  // derived from the global ones by local_dof().
  std::erase_if(touched, [&](int n) { return partition.node_owner[n] == rank; });
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (int n : touched)
    for (int k = 0; k < counts[n]; ++k)
      if (global_[node_offset_[n] + k] >= 0) ghosts_.push_back(global_[node_offset_[n] + k]);
  std::sort(ghosts_.begin(), ghosts_.end());
  ghosts_.erase(std::unique(ghosts_.begin(), ghosts_.end()), ghosts_.end());  // linked slots
}

const DofMap::LinkedSlot* DofMap::linked_slot(int node, int k) const {
  if (linked_slots_.empty()) return nullptr;  // most lines: no slope held in direction
  const int slot = node_offset_[node] + k;
  const auto it = std::lower_bound(linked_slots_.begin(), linked_slots_.end(), slot,
                                   [](const LinkedSlot& s, int x) { return s.slot < x; });
  return it != linked_slots_.end() && it->slot == slot ? &*it : nullptr;
}

PetscInt DofMap::local_dof(int node, int k) const {
  const PetscInt g = global_dof(node, k);
  if (g < 0) return -1;
  if (g >= first_owned_ && g < first_owned_ + n_owned_) return g - first_owned_;
  const auto it = std::lower_bound(ghosts_.begin(), ghosts_.end(), g);
  if (it == ghosts_.end() || *it != g) return -1;  // not on this rank
  return n_owned_ + static_cast<PetscInt>(it - ghosts_.begin());
}

int DofMap::constraint_of_global(PetscInt global) const {
  for (int c = 0; c < n_constraints(); ++c)
    for (int k = 0; k < n_multipliers(c); ++k)
      if (multiplier_dof(c, k) == global) return c;
  return -1;
}

int DofMap::node_of_global(PetscInt global) const {
  if (const int c = constraint_of_global(global); c >= 0) return constraint_node_a_[c];
  for (int n = 0; n < n_nodes(); ++n)
    for (int k = 0; k < node_dofs(n); ++k)
      if (global_dof(n, k) == global) return n;
  return -1;
}

int DofMap::component_of_global(PetscInt global) const {
  if (const int c = constraint_of_global(global); c >= 0)
    for (int k = 0; k < n_multipliers(c); ++k)
      if (multiplier_dof(c, k) == global) return k;
  const int n = node_of_global(global);
  for (int k = 0; k < node_dofs(n); ++k)
    if (global_dof(n, k) == global) return k;
  return -1;
}

}  // namespace catena::assembly

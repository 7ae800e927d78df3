#pragma once
// Global numbering of the free degrees of freedom.
//
// Each node's unknowns are a block of its kind (model/unknown_kinds.hpp, chosen by the
// elements attached to it: model/node_kinds.hpp), in the kind's component order. Fixed DOFs
// (supports) are eliminated: they get no global index (−1). Free DOFs are numbered contiguously per
// rank: rank 0's owned nodes in ascending node index, then rank 1's, ...; within a node, in layout
// order. The numbering is computed identically on every rank from the replicated model (one
// global index per nodal DOF kept on every rank; local indices, linked slots and the
// reverse lookups for messages are derived from it, not stored per DOF).
//
// Lagrange multipliers (model::Constraint, a `multiplier` block each) are unknowns too: a
// constraint belongs to the rank owning its node A, and its multipliers are numbered after
// that rank's nodal DOFs (so every rank's block stays contiguous).
//
// A support that holds a slope's direction only (model::Support::slope_direction) links
// the slope's three slots to one unknown s: r_x = s·t, t the node's reference tangent.
// Each slot k of a node has a coefficient c_k (t's component on linked slots, 1 on the
// others), so that the nodal value is c_k times its unknown: couplings gather c_k·q and
// scatter c_k·f and c_i c_j·K (SecondOrderSystem), and values written into a vector add
// up to the projection Σ c_k·value_k on the shared unknown.
//
// Local (ghosted) indices address PETSc's ghosted local form: [owned dofs | ghost dofs],
// ghosts being the free DOFs of the non-owned nodes this rank's couplings act on.
#include <petscsys.h>

#include <vector>

#include "catena/assembly/partition.hpp"
#include "catena/model/model.hpp"
#include "catena/model/unknown_kinds.hpp"

namespace catena::assembly {

class DofMap {
 public:
  // Not collective (deterministic on every rank). `touched`: the nodes this rank's
  // couplings act on (any order, repeats allowed; owned ones are ignored).
  DofMap(const model::Model& model, const Partition& partition, int rank, std::vector<int> touched);

  int n_nodes() const { return static_cast<int>(node_offset_.size()) - 1; }
  int node_dofs(int node) const { return node_offset_[node + 1] - node_offset_[node]; }
  model::UnknownKind node_kind(int node) const { return node_kinds_[node]; }
  // Global index of nodal DOF k, or −1 if it is fixed.
  PetscInt global_dof(int node, int k) const { return global_[node_offset_[node] + k]; }
  // Index into the ghosted local form, −1 if fixed or not present on this rank (owned: its
  // place in the owned block; a ghost: its place after it, found in the sorted ghosts).
  PetscInt local_dof(int node, int k) const;
  // Nodal value of DOF k = coefficient × its unknown (1 unless the slot is linked).
  double coefficient(int node, int k) const {
    const LinkedSlot* s = linked_slot(node, k);
    return s ? s->coefficient : 1.0;
  }
  // True if slot k shares its unknown with the node's other slope slots.
  bool linked(int node, int k) const { return linked_slot(node, k) != nullptr; }

  PetscInt n_global() const { return n_global_; }
  PetscInt n_owned() const { return n_owned_; }
  PetscInt first_owned() const { return first_owned_; }
  const std::vector<PetscInt>& ghosts() const { return ghosts_; }
  const std::vector<int>& owned_nodes() const { return owned_nodes_; }
  int node_owner(int node) const { return partition_->node_owner[node]; }
  const Partition& partition() const { return *partition_; }

  int n_constraints() const { return static_cast<int>(constraint_owner_.size()); }
  int constraint_owner(int c) const { return constraint_owner_[c]; }
  // Multipliers of constraint c (model::Constraint::equations).
  int n_multipliers(int c) const { return multiplier_offset_[c + 1] - multiplier_offset_[c]; }
  // Global index of multiplier k (0 .. n_multipliers(c) − 1) of constraint c.
  PetscInt multiplier_dof(int c, int k) const { return multiplier_[multiplier_offset_[c] + k]; }
  // Index of that multiplier in the ghosted local form (owned: the owner rank only), or −1.
  PetscInt multiplier_local(int c, int k) const {
    return constraint_owner_[c] == rank_ ? multiplier_dof(c, k) - first_owned_ : -1;
  }
  // Constraint a global DOF is a multiplier of, or −1 for a nodal DOF. For messages: a
  // search over the multipliers, no per-DOF table.
  int constraint_of_global(PetscInt global) const;

  // Node holding a global DOF (for messages: "largest residual at node 17"); for a
  // multiplier, the constraint's node A; −1 for none. A search over the nodes (messages
  // only: no table of O(global DOFs) is kept for it on every rank).
  int node_of_global(PetscInt global) const;
  // Component of a global DOF in its block (the node's kind, or `multiplier`).
  int component_of_global(PetscInt global) const;

 private:
  const Partition* partition_;
  std::vector<model::UnknownKind> node_kinds_;  // n_nodes
  std::vector<int> node_offset_;                // n_nodes + 1
  std::vector<PetscInt> global_;                // per nodal DOF
  // The slots of slopes held in direction (few: clamped ends), ascending by slot; every
  // other slot has coefficient 1 and its own unknown.
  struct LinkedSlot {
    int slot;
    double coefficient;
    bool own;  // the shared unknown's own slot (the first of the three); the others share it
  };
  std::vector<LinkedSlot> linked_slots_;
  std::vector<PetscInt> ghosts_;  // ascending
  std::vector<int> owned_nodes_;
  std::vector<int> constraint_owner_;   // per constraint: owning rank
  std::vector<int> constraint_node_a_;  // per constraint: its node A
  std::vector<int> multiplier_offset_;  // n_constraints + 1: each one's first in multiplier_
  std::vector<PetscInt> multiplier_;    // per multiplier: global index
  int rank_ = 0;
  PetscInt n_global_ = 0, n_owned_ = 0, first_owned_ = 0;

  const LinkedSlot* linked_slot(int node, int k) const;
};

}  // namespace catena::assembly

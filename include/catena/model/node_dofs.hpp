#pragma once
// How many DOFs a node carries. Every node uses a prefix of the nodal layout
//   [r (3), r_x (3), r_y (3), r_z (3)]        (positions, then ANCF slope vectors)
// long enough for every element attached to it (each kind of element says how long:
// model.hpp, `node_dofs`): 12 where a beam attaches, else 6 where a cable attaches, else 3
// (only bars, springs, point masses or supports touch it).
// Shared by the scene reader (which support components exist), `catena check` and the
// assembly layer (DofMap).
#include <vector>

#include "catena/model/model.hpp"

namespace catena::model {

// Not collective. Nodal DOFs an element of these properties uses at each of its nodes.
int element_node_dofs(const ElementProps& props);

// Not collective. DOFs of node `node` (an index into model.nodes). O(n_elements): use
// all_node_dofs when asking for many nodes.
int node_dofs(const Model& model, int node);

// Not collective. DOFs of every node, indexed like model.nodes. O(n_nodes + n_elements).
std::vector<int> all_node_dofs(const Model& model);

}  // namespace catena::model

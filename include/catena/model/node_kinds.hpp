#pragma once
// The kind of each node's unknowns (model/unknown_kinds.hpp). Every node has a position,
// so its kind is at least `point`; each element attached to it asks for its own node kind
// (model.hpp, `node_kind`: cable → ancf_cable, beam → ancf_beam, bar and spring → point),
// and the node takes the kind that holds all of them. Point masses, springs to ground,
// nodal loads and supports need only the position.
// Shared by the scene reader (which support components exist), `catena check` and the
// assembly layer (DofMap).
#include <vector>

#include "catena/model/model.hpp"
#include "catena/model/unknown_kinds.hpp"

namespace catena::model {

// Not collective. The node kind an element of these properties asks for at its nodes.
UnknownKind element_node_kind(const ElementProps& props);
// Not collective. Unknowns per node of that kind.
int element_node_dofs(const ElementProps& props);

// Not collective. The kind of every node, indexed like model.nodes. O(n_nodes + n_elements).
// Throws catena::Error naming the node and two of its elements if no kind holds what
// they ask for.
std::vector<UnknownKind> node_kinds(const Model& model);

// Not collective. Unknowns of every node (the sizes of node_kinds).
std::vector<int> all_node_dofs(const Model& model);

}  // namespace catena::model

#pragma once
// The nodes a model holds: any fixed DOF (Model::supports), an elastic support or a
// surface it may touch (whose reaction is the contact force, zero out of contact), except
// the DOFs that only keep a 2D model in its plane (Support::plane_mask: in a 2D catenary
// every node's y, whose reaction is zero by symmetry and would cost a row per node). The
// reactions (assembly/state_view.hpp), their rows in the time series (io) and the couplings
// the system evaluates for them all index this one list.
#include <vector>

#include "catena/model/model.hpp"

namespace catena::model {

// Not collective. Model node indices, ascending, each once.
std::vector<int> supported_nodes(const Model& model);

}  // namespace catena::model

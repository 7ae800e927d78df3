#pragma once
// The free unknowns in node order: nodes ascending, each node's unknowns in its kind's
// layout, a slope held in direction (DofMap::linked) once. The global numbering follows
// the partition (each rank's nodes contiguously); this order is the same on any number of
// ranks, so a file that stores one value per unknown (a modal basis) can be read by a run
// on another number of ranks.
#include <cstdint>
#include <vector>

#include "catena/assembly/dof_map.hpp"

namespace catena::assembly {

struct NodeOrder {
  std::int64_t n_rows = 0;  // free nodal unknowns
  std::vector<int> owned;   // per owned DOF (global first_owned() + i): its row, ascending
};

// Not collective (the DofMap is the same on every rank). The map must have no multipliers.
NodeOrder node_order(const DofMap& dofs);

}  // namespace catena::assembly

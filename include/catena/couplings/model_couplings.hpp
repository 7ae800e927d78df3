#pragma once
// Where the model's description becomes couplings, and which rank evaluates each:
//   elements            the element's owner (the partition)
//   point masses, elastic supports, nodal loads   the owner of their node
//   moving loads        on each path element, that element's owner
//   constraints         the owner of node A (who also numbers its multipliers)
//   pantograph contacts the owner of the head node
// The order is the order of evaluation, so of summation: elements, node items, moving
// loads, constraints, contacts (results are bit-for-bit those of this order).
#include <vector>

#include "catena/couplings/coupling.hpp"
#include "catena/model/model.hpp"

namespace catena::couplings {

// Not collective. The couplings `rank` evaluates, given each element's and node's owner.
CouplingList make_couplings(const model::Model& model, const std::vector<int>& element_owner,
                            const std::vector<int>& node_owner, int rank);

}  // namespace catena::couplings

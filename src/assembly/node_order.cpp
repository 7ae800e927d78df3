#include "catena/assembly/node_order.hpp"

#include "catena/core/error.hpp"

namespace catena::assembly {

NodeOrder node_order(const DofMap& dofs) {
  CATENA_ASSERT(dofs.n_constraints() == 0, "node_order: a DOF map without multipliers");
  NodeOrder order;
  order.owned.assign(static_cast<std::size_t>(dofs.n_owned()), -1);
  std::vector<char> seen(static_cast<std::size_t>(dofs.n_global()), 0);
  const PetscInt first = dofs.first_owned(), end = first + dofs.n_owned();
  for (int node = 0; node < dofs.n_nodes(); ++node)
    for (int k = 0; k < dofs.node_dofs(node); ++k) {
      const PetscInt g = dofs.global_dof(node, k);
      if (g < 0 || seen[static_cast<std::size_t>(g)]) continue;  // fixed, or a linked slot
      seen[static_cast<std::size_t>(g)] = 1;
      if (g >= first && g < end)
        order.owned[static_cast<std::size_t>(g - first)] = static_cast<int>(order.n_rows);
      ++order.n_rows;
    }
  CATENA_ASSERT(order.n_rows == dofs.n_global(), "node_order: every free unknown once");
  return order;
}

}  // namespace catena::assembly

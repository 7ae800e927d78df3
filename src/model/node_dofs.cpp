#include "catena/model/node_dofs.hpp"

#include <algorithm>
#include <type_traits>

#include "catena/core/error.hpp"

namespace catena::model {

int element_node_dofs(const ElementProps& props) {
  return std::visit([](const auto& p) { return std::decay_t<decltype(p)>::node_dofs; }, props);
}

int node_dofs(const Model& model, int node) {
  CATENA_ASSERT(node >= 0 && node < static_cast<int>(model.nodes.size()), "node index");
  int dofs = 3;
  for (const ElementDesc& element : model.elements)
    if (std::find(element.nodes.begin(), element.nodes.end(), node) != element.nodes.end())
      dofs = std::max(dofs, element_node_dofs(element.props));
  return dofs;
}

std::vector<int> all_node_dofs(const Model& model) {
  std::vector<int> dofs(model.nodes.size(), 3);
  for (const ElementDesc& element : model.elements) {
    const int element_dofs = element_node_dofs(element.props);
    for (const int node : element.nodes) dofs[node] = std::max(dofs[node], element_dofs);
  }
  return dofs;
}

}  // namespace catena::model

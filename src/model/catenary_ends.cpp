#include "catena/model/catenary_ends.hpp"

#include <algorithm>

#include "catena/core/error.hpp"

namespace catena::model {
namespace {

// The one element that ends at `node`.
int element_ending_at(const Model& model, int node) {
  int found = -1, count = 0;
  for (std::size_t e = 0; e < model.elements.size(); ++e)
    for (const int n : model.elements[e].nodes)
      if (n == node) {
        found = static_cast<int>(e);
        ++count;
      }
  CATENA_ASSERT(count == 1, "a catenary wire's end node ends one element");
  return found;
}

}  // namespace

int absorb_catenary_ends(Model& model) {
  if (!model.catenary || !model.catenary->absorbing_ends) return 0;
  const CatenaryLayout& layout = *model.catenary;
  int added = 0;
  for (const std::vector<int>* supports :
       {&layout.contact_support_nodes, &layout.messenger_support_nodes}) {
    for (const int node : {supports->front(), supports->back()}) {
      // The anchor held x, y and z (and, in 2D, the plane): keep only the plane.
      const auto it = std::find_if(model.supports.begin(), model.supports.end(),
                                   [&](const Support& s) { return s.node == node; });
      CATENA_ASSERT(it != model.supports.end(), "a catenary wire's end is supported");
      it->fixed_mask = it->plane_mask;
      if (it->fixed_mask == 0u) model.supports.erase(it);
      model.absorbing_ends.push_back({node, element_ending_at(model, node)});
      ++added;
    }
  }
  return added;
}

}  // namespace catena::model

#include "catena/model/supported_nodes.hpp"

#include <algorithm>

namespace catena::model {

std::vector<int> supported_nodes(const Model& model) {
  std::vector<int> nodes;
  for (const Support& s : model.supports)
    if ((s.fixed_mask & ~s.plane_mask) != 0u || s.slope_direction) nodes.push_back(s.node);
  for (const ElasticSupport& s : model.elastic_supports) nodes.push_back(s.node);
  for (const AbsorbingEnd& a : model.absorbing_ends) nodes.push_back(a.node);
  for (const Surface& s : model.surfaces) nodes.insert(nodes.end(), s.nodes.begin(), s.nodes.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace catena::model

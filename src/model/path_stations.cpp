#include "catena/model/path_stations.hpp"

#include <algorithm>

namespace catena::model {

double element_chord(const Model& model, int element) {
  const std::vector<int>& nodes = model.elements[static_cast<std::size_t>(element)].nodes;
  return (model.nodes[static_cast<std::size_t>(nodes.back())].position -
          model.nodes[static_cast<std::size_t>(nodes.front())].position)
      .norm();
}

std::size_t PathStations::element_at(double s) const {
  const auto it = std::upper_bound(start.begin() + 1, start.end() - 1, s);
  return static_cast<std::size_t>(it - start.begin()) - 1;
}

PathStations path_stations(const Model& model, const std::vector<int>& elements) {
  PathStations p;
  p.start.reserve(elements.size() + 1);
  p.start.push_back(0.0);
  for (int e : elements) p.start.push_back(p.start.back() + element_chord(model, e));
  return p;
}

}  // namespace catena::model

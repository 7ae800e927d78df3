#include "pantograph_travel.hpp"

#include <unordered_map>

namespace catena::app {

PantographTravel::PantographTravel(const model::Model& model, const std::vector<int>& owned_nodes)
    : model_(model) {
  std::unordered_map<int, int> row_of;
  for (std::size_t r = 0; r < owned_nodes.size(); ++r) row_of[owned_nodes[r]] = static_cast<int>(r);
  for (const model::MovingContact& c : model.contacts) {
    Pantograph p;
    for (const int node : model::pantograph_nodes(c))
      if (const auto it = row_of.find(node); it != row_of.end()) p.rows.push_back(it->second);
    p.elements = &model.paths[static_cast<std::size_t>(c.path)].elements;
    p.stations = model::path_stations(model, *p.elements);
    p.start_point = model::path_point(model, *p.elements, p.stations, c.start);
    p.up = c.up;
    pantographs_.push_back(std::move(p));
  }
}

void PantographTravel::move(const std::vector<double>& contact_position,
                            std::vector<double>& positions) const {
  for (std::size_t j = 0; j < pantographs_.size() && j < contact_position.size(); ++j) {
    const Pantograph& p = pantographs_[j];
    if (p.rows.empty()) continue;
    Vec3 travel =
        model::path_point(model_, *p.elements, p.stations, contact_position[j]) - p.start_point;
    travel -= p.up * travel.dot(p.up);  // horizontal: the stages' own motion is along up
    for (const int row : p.rows)
      for (int d = 0; d < 3; ++d) positions[static_cast<std::size_t>(3 * row + d)] += travel[d];
  }
}

}  // namespace catena::app

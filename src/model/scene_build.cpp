#include "scene_build.hpp"

#include <algorithm>
#include <limits>
#include <string>

namespace catena::model::detail {

IntRange node_id_range() { return IntRange::any("a node id"); }

int SceneBuild::add_origin(const Field& entry) {
  origins_.push_back(entry);
  return static_cast<int>(origins_.size()) - 1;
}

void SceneBuild::add_node(const Node& node, int origin) {
  if (model.nodes.size() >= static_cast<std::size_t>(std::numeric_limits<int>::max()))
    origins_[origin].fail("too many nodes (more than " +
                          std::to_string(std::numeric_limits<int>::max()) + ")");
  const int index = static_cast<int>(model.nodes.size());
  const auto [existing, inserted] = node_index_.emplace(node.id, index);
  if (!inserted) {
    const Field& first = node_origin(existing->second);
    origins_[origin].child("id").fail(
        "duplicate node id " + std::to_string(node.id) + " (first defined at " + first.path() +
        ", line " + std::to_string(first.location().line) + "); node ids must be unique");
  }
  model.nodes.push_back(node);
  node_origin_.push_back(origin);
}

void SceneBuild::add_element(const ElementDesc& element, int origin) {
  if (model.elements.size() >= static_cast<std::size_t>(std::numeric_limits<int>::max()))
    origins_[origin].fail("too many elements (more than " +
                          std::to_string(std::numeric_limits<int>::max()) + ")");
  model.elements.push_back(element);
  element_origin_.push_back(origin);
}

void SceneBuild::prepend_elements(std::vector<ElementDesc> elements,
                                  const std::vector<int>& origins) {
  CATENA_ASSERT(elements.size() == origins.size(), "one origin per element");
  if (model.elements.size() + elements.size() >
      static_cast<std::size_t>(std::numeric_limits<int>::max()))
    origins_[origins.front()].fail("too many elements (more than " +
                                   std::to_string(std::numeric_limits<int>::max()) + ")");
  elements.insert(elements.end(), std::make_move_iterator(model.elements.begin()),
                  std::make_move_iterator(model.elements.end()));
  model.elements = std::move(elements);
  element_origin_.insert(element_origin_.begin(), origins.begin(), origins.end());
}

int SceneBuild::find_node(std::int64_t id) const {
  const auto it = node_index_.find(id);
  return it == node_index_.end() ? -1 : it->second;
}

int SceneBuild::resolve_node(const Field& reference) const {
  const std::int64_t id = reference.integer(node_id_range());
  const int index = find_node(id);
  if (index >= 0) return index;
  std::string known = "no nodes are defined";
  if (!model.nodes.empty()) {
    const auto [lowest, highest] =
        std::minmax_element(model.nodes.begin(), model.nodes.end(),
                            [](const Node& a, const Node& b) { return a.id < b.id; });
    known = "defined node ids range from " + std::to_string(lowest->id) + " to " +
            std::to_string(highest->id);
  }
  reference.fail("no node with id " + std::to_string(id) + " (" + known + ")");
}

void SceneBuild::mark_explicit_nodes_done() {
  n_explicit_nodes_ = static_cast<int>(model.nodes.size());
  if (n_explicit_nodes_ == 0) return;
  Vec3 lo = model.nodes.front().position, hi = lo;
  for (const Node& node : model.nodes) {
    lo = lo.cwiseMin(node.position);
    hi = hi.cwiseMax(node.position);
  }
  const double size = (hi - lo).norm();
  zero_length_tolerance_ = 1e-12 * (size > 0.0 ? size : 1.0);
}

}  // namespace catena::model::detail

#include "free_body_check.hpp"

#include <numeric>
#include <string>
#include <vector>

namespace catena::model::detail {
namespace {

constexpr std::size_t max_listed_nodes = 10;

// Disjoint sets over node indices (path halving, union by size).
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::size_t> parent_;
  std::vector<std::size_t> size_;
};

}  // namespace

void check_no_free_body(const SceneBuild& build) {
  const Model& model = build.model;
  const std::size_t n = model.nodes.size();
  DisjointSets parts(n);
  for (const ElementDesc& element : model.elements)
    for (std::size_t k = 1; k < element.nodes.size(); ++k)
      parts.unite(static_cast<std::size_t>(element.nodes[0]),
                  static_cast<std::size_t>(element.nodes[k]));
  for (const Constraint& c : model.constraints)
    if (c.node_b >= 0)
      parts.unite(static_cast<std::size_t>(c.node_a), static_cast<std::size_t>(c.node_b));
  // A slider is held by its path (as a node of it).
  for (const Slider& slider : model.sliders) {
    const int element = model.paths[static_cast<std::size_t>(slider.path)].elements.front();
    parts.unite(
        static_cast<std::size_t>(slider.node),
        static_cast<std::size_t>(model.elements[static_cast<std::size_t>(element)].nodes[0]));
  }

  std::vector<bool> held(n, false);  // per part representative
  for (const Support& s : model.supports) held[parts.find(static_cast<std::size_t>(s.node))] = true;
  for (const ElasticSupport& s : model.elastic_supports)
    held[parts.find(static_cast<std::size_t>(s.node))] = true;
  // Held in statics; in dynamics the line beyond holds it.
  for (const AbsorbingEnd& a : model.absorbing_ends)
    held[parts.find(static_cast<std::size_t>(a.node))] = true;
  // A rigid body's frame constraints hold its axes to each other, not the body to ground.
  for (const Constraint& c : model.constraints)
    if (c.node_b < 0 && c.type != ConstraintType::frame_lengths &&
        c.type != ConstraintType::frame_angles && c.type != ConstraintType::slider)
      held[parts.find(static_cast<std::size_t>(c.node_a))] = true;

  // Report the part of the first unsupported node, listing its nodes in scene order.
  std::size_t first_free = n;
  std::size_t n_free_parts = 0;
  std::vector<bool> counted(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t part = parts.find(i);
    if (held[part] || counted[part]) continue;
    counted[part] = true;
    ++n_free_parts;
    if (first_free == n) first_free = part;
  }
  if (n_free_parts == 0) return;

  std::string listed;
  std::size_t n_in_part = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (parts.find(i) != first_free) continue;
    if (n_in_part++ < max_listed_nodes)
      listed += (listed.empty() ? "" : ", ") + std::to_string(model.nodes[i].id);
  }
  if (n_in_part > max_listed_nodes)
    listed += " and " + std::to_string(n_in_part - max_listed_nodes) + " more";
  const std::string others =
      n_free_parts > 1 ? " (one of " + std::to_string(n_free_parts) + " unsupported parts)" : "";
  const std::string subject =
      n_in_part == 1 ? "node " + listed + " has" : "nodes " + listed + " have";
  throw InputError(InputLocation{build.source().file_label, 0, "supports"},
                   "structure is unsupported (a free body): " + subject + " no support" + others +
                       "; add supports or elastic_supports (every connected part of the "
                       "structure needs at least one)");
}

}  // namespace catena::model::detail

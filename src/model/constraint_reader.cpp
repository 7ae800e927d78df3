#include "constraint_reader.hpp"

#include <numeric>
#include <string>
#include <vector>

#include "did_you_mean.hpp"
#include "sine_motion.hpp"

namespace catena::model::detail {
namespace {

const std::vector<std::string>& type_names() {
  static const std::vector<std::string> names{"coincident", "pinned", "prescribed"};
  return names;
}

ConstraintType read_type(const Field& type) {
  if (!type.present())
    type.fail("missing required key; expected one of coincident, pinned, prescribed");
  const std::string name = type.text();
  if (name == "coincident") return ConstraintType::coincident;
  if (name == "pinned") return ConstraintType::pinned;
  if (name == "prescribed") return ConstraintType::prescribed;
  type.fail("unknown constraint type '" + name + "';" + did_you_mean(name, type_names()) +
            " expected coincident (two nodes share a position), pinned (a node held at its "
            "position, slopes free) or prescribed (a node moved along a given path)");
}

// Union–find over the nodes plus one extra element standing for the ground: a constraint
// joining two already connected elements repeats the others (singular multipliers).
class Connectivity {
 public:
  explicit Connectivity(size_t n_nodes) : parent_(n_nodes + 1) {
    std::iota(parent_.begin(), parent_.end(), size_t{0});
  }
  size_t ground() const { return parent_.size() - 1; }
  bool join(size_t a, size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[a] = b;
    return true;
  }

 private:
  size_t find(size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  std::vector<size_t> parent_;
};

// The position of `node` must be free: the support would repeat the constraint.
void require_free_position(const Field& where, const SceneBuild& build, int node) {
  for (const Support& s : build.model.supports)
    if (s.node == node && (s.fixed_mask & 7u))
      where.fail("node " + std::to_string(build.model.nodes[node].id) +
                 " has a support fixing its position, which the constraint would repeat "
                 "(singular); remove the support or the constraint");
}

}  // namespace

void read_constraints(const Field& constraints, SceneBuild& build) {
  if (!constraints.present()) return;
  Model& model = build.model;
  Connectivity connected(model.nodes.size());
  for (const Field& entry : constraints.items()) {
    entry.expect_map("a constraint {type, node | nodes, ...}");
    Constraint c;
    c.type = read_type(entry.child("type"));
    Field node_field = entry.child("node");
    if (c.type == ConstraintType::coincident) {
      entry.check_keys({"type", "nodes"});
      const Field nodes = entry.child("nodes");
      if (!nodes.present()) nodes.fail("missing required key; expected two node ids [A, B]");
      const std::vector<Field> ends = nodes.items();
      if (ends.size() != 2)
        nodes.fail("expected two node ids [A, B], got " + std::to_string(ends.size()));
      c.node_a = build.resolve_node(ends[0]);
      c.node_b = build.resolve_node(ends[1]);
      if (c.node_a == c.node_b)
        nodes.fail("a node cannot coincide with itself (node " +
                   std::to_string(model.nodes[c.node_a].id) + " twice)");
      require_free_position(ends[0], build, c.node_a);
      require_free_position(ends[1], build, c.node_b);
      if (!connected.join(c.node_a, c.node_b))
        nodes.fail("nodes " + std::to_string(model.nodes[c.node_a].id) + " and " +
                   std::to_string(model.nodes[c.node_b].id) +
                   " are already joined (directly, through other coincident nodes, or both "
                   "held to ground): this constraint is redundant and its multipliers "
                   "would be singular");
      node_field = ends[0];
    } else {
      if (c.type == ConstraintType::pinned)
        entry.check_keys({"type", "node"});
      else
        entry.check_keys({"type", "node", "velocity", "amplitude", "frequency"});
      if (!node_field.present()) node_field.fail("missing required key; expected a node id");
      c.node_a = build.resolve_node(node_field);
      require_free_position(node_field, build, c.node_a);
      if (!connected.join(c.node_a, connected.ground()))
        node_field.fail("node " + std::to_string(model.nodes[c.node_a].id) +
                        " is already held to ground (by another pinned or prescribed "
                        "constraint, possibly through coincident nodes): this constraint "
                        "is redundant and its multipliers would be singular");
      if (c.type == ConstraintType::prescribed) {
        c.velocity = entry.child("velocity").vec3_or(Vec3::Zero(), RealRange::any("m/s"));
        c.amplitude = entry.child("amplitude").vec3_or(Vec3::Zero(), RealRange::any("m"));
        c.frequency = read_sine_frequency(entry.child("frequency"), c.amplitude.isZero(), "m");
      }
    }
    model.constraints.push_back(c);
  }
}

}  // namespace catena::model::detail

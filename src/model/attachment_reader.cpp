#include "attachment_reader.hpp"

#include <algorithm>
#include <map>

#include "did_you_mean.hpp"
#include "section_reader.hpp"

namespace catena::model::detail {
namespace {

// Support components in the nodal layout order [r, r_x, r_y, r_z]: bit k of
// Support::fixed_mask fixes the k-th.
const std::vector<std::string>& component_names() {
  static const std::vector<std::string> names{"x",    "y",    "z",    "rx_x", "rx_y", "rx_z",
                                              "ry_x", "ry_y", "ry_z", "rz_x", "rz_y", "rz_z"};
  return names;
}

std::string node_kind_note(int dofs) {
  switch (dofs) {
    case 3:
      return "3 DOFs (x, y, z): only bars, springs or point masses attach there";
    case 6:
      return "6 DOFs (x, y, z, rx_*): a cable node";
    default:
      return "12 DOFs: a beam node";
  }
}

std::string accepted_fix() {
  std::string list;
  for (const std::string& c : component_names()) list += (list.empty() ? "" : ", ") + c;
  return "pinned (x, y, z), clamped (every DOF of the node) or a list of components from "
         "[" +
         list + "]";
}

unsigned low_bits(int n) { return (1u << static_cast<unsigned>(n)) - 1u; }

unsigned read_component_list(const Field& fix, int dofs, std::int64_t node_id) {
  const std::vector<Field> items = fix.items();
  if (items.empty()) fix.fail("empty component list; expected " + accepted_fix());
  const std::vector<std::string>& names = component_names();
  unsigned mask = 0;
  for (const Field& item : items) {
    const std::string name = item.text();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      item.fail("unknown component '" + name + "';" + did_you_mean(name, names) + " expected " +
                accepted_fix());
    const int bit = static_cast<int>(it - names.begin());
    if (bit >= dofs)
      item.fail("component '" + name + "' does not exist at node " + std::to_string(node_id) +
                ", which has " + node_kind_note(dofs));
    if (mask & (1u << static_cast<unsigned>(bit)))
      item.fail("component '" + name + "' is listed twice");
    mask |= 1u << static_cast<unsigned>(bit);
  }
  return mask;
}

unsigned read_fixed_mask(const Field& fix, int dofs, std::int64_t node_id) {
  if (!fix.present()) fix.fail("missing required key; expected " + accepted_fix());
  if (fix.is_list()) return read_component_list(fix, dofs, node_id);
  if (!fix.is_scalar()) fix.fail("expected " + accepted_fix() + ", got " + fix.value_text());
  static const std::vector<std::string> kinds{"pinned", "clamped"};
  const std::string kind = fix.text();
  if (kind == "pinned") return low_bits(3);
  if (kind == "clamped") return low_bits(dofs);
  fix.fail("unknown fix '" + kind + "';" + did_you_mean(kind, kinds) + " expected " +
           accepted_fix());
}

}  // namespace

void read_supports(const Field& supports, const std::vector<int>& node_dofs, SceneBuild& build) {
  static const std::vector<std::string> keys{"node", "fix"};
  std::map<int, Field> first_support_of_node;
  for (const Field& entry : supports.items()) {
    entry.expect_map("a support {node, fix}");
    entry.check_keys(keys);
    const Field node_field = entry.child("node");
    const int node = build.resolve_node(node_field);
    const std::int64_t id = build.model.nodes[node].id;
    const auto [first, inserted] = first_support_of_node.emplace(node, entry);
    if (!inserted)
      node_field.fail("node " + std::to_string(id) + " already has a support (" +
                      first->second.path() + ", line " +
                      std::to_string(first->second.location().line) +
                      "); list all its fixed components in one support");
    build.model.supports.push_back(
        Support{node, read_fixed_mask(entry.child("fix"), node_dofs[node], id)});
  }
}

void read_elastic_supports(const Field& elastic_supports, SceneBuild& build) {
  static const std::vector<std::string> keys{"node", "stiffness", "damping"};
  for (const Field& entry : elastic_supports.items()) {
    entry.expect_map("an elastic support {node, stiffness, damping}");
    entry.check_keys(keys);
    ElasticSupport support;
    support.node = build.resolve_node(entry.child("node"));
    support.stiffness = read_spring_stiffness(entry.child("stiffness"));
    support.damping = read_spring_damping(entry.child("damping"));
    build.model.elastic_supports.push_back(support);
  }
}

void read_loads(const Field& loads, SceneBuild& build) {
  static const std::vector<std::string> keys{"node", "force"};
  for (const Field& entry : loads.items()) {
    entry.expect_map("a load {node, force}");
    entry.check_keys(keys);
    NodalLoad load;
    load.node = build.resolve_node(entry.child("node"));
    load.force = entry.child("force").vec3(RealRange::any("N"));
    build.model.nodal_loads.push_back(load);
  }
}

void read_masses(const Field& masses, SceneBuild& build) {
  static const std::vector<std::string> keys{"node", "mass"};
  for (const Field& entry : masses.items()) {
    entry.expect_map("a point mass {node, mass}");
    entry.check_keys(keys);
    PointMass mass;
    mass.node = build.resolve_node(entry.child("node"));
    mass.mass = entry.child("mass").real(RealRange::positive("kg"));
    build.model.point_masses.push_back(mass);
  }
}

}  // namespace catena::model::detail

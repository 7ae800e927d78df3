#include "attachment_reader.hpp"

#include <algorithm>
#include <map>

#include "did_you_mean.hpp"
#include "section_reader.hpp"

namespace catena::model::detail {
namespace {

// Support components by name: bit k of Support::fixed_mask fixes component k of the node's
// kind (model/unknown_kinds.hpp). Accepted: the component names of every node kind.
const std::vector<std::string>& component_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const UnknownKind kind : all_unknown_kinds()) {
      const UnknownKindInfo& info = kind_info(kind);
      if (!info.nodal) continue;
      for (int k = 0; k < info.size; ++k)
        if (std::find(all.begin(), all.end(), info.components[k]) == all.end())
          all.emplace_back(info.components[k]);
    }
    return all;
  }();
  return names;
}

std::string node_kind_note(const UnknownKindInfo& info) {
  std::string list;
  for (int k = 0; k < info.size; ++k) list += (k ? ", " : "") + std::string(info.components[k]);
  return std::string(info.name) + " (" + list + "): " + std::string(info.used_by);
}

std::string accepted_fix() {
  std::string list;
  for (const std::string& c : component_names()) list += (list.empty() ? "" : ", ") + c;
  return "pinned (x, y, z), clamped (every DOF of the node but the slope's length) or a list "
         "of components from "
         "[" +
         list + "]";
}

unsigned bit(int k) { return 1u << static_cast<unsigned>(k); }

unsigned read_component_list(const Field& fix, const UnknownKindInfo& node, std::int64_t node_id) {
  const std::vector<Field> items = fix.items();
  if (items.empty()) fix.fail("empty component list; expected " + accepted_fix());
  const std::vector<std::string>& names = component_names();
  unsigned mask = 0;
  for (const Field& item : items) {
    const std::string name = item.text();
    if (std::find(names.begin(), names.end(), name) == names.end())
      item.fail("unknown component '" + name + "';" + did_you_mean(name, names) + " expected " +
                accepted_fix());
    const auto it = std::find(node.components.begin(), node.components.begin() + node.size, name);
    if (it == node.components.begin() + node.size)
      item.fail("component '" + name + "' does not exist at node " + std::to_string(node_id) +
                ", which is " + node_kind_note(node));
    const int k = static_cast<int>(it - node.components.begin());
    if (mask & bit(k)) item.fail("component '" + name + "' is listed twice");
    mask |= bit(k);
  }
  return mask;
}

// The support `fix` gives the node (without its node index).
Support read_fix(const Field& fix, UnknownKind kind, std::int64_t node_id) {
  const UnknownKindInfo& node = kind_info(kind);
  if (!fix.present()) fix.fail("missing required key; expected " + accepted_fix());
  if (fix.is_list()) return {0, read_component_list(fix, node, node_id), false};
  if (!fix.is_scalar()) fix.fail("expected " + accepted_fix() + ", got " + fix.value_text());
  static const std::vector<std::string> fixes{"pinned", "clamped"};
  const std::string text = fix.text();
  if (text == "pinned") return {0, (bit(3) - 1u) << static_cast<unsigned>(node.position), false};
  if (text == "clamped") {
    const unsigned all = bit(node.size) - 1u;
    if (node.gradients < 0) return {0, all, false};
    // Every DOF but the slope r_x, whose direction alone is held (model.hpp, Support).
    return {0, all & ~((bit(3) - 1u) << static_cast<unsigned>(node.gradients)), true};
  }
  fix.fail("unknown fix '" + text + "';" + did_you_mean(text, fixes) + " expected " +
           accepted_fix());
}

}  // namespace

void read_supports(const Field& supports, const std::vector<UnknownKind>& node_kinds,
                   SceneBuild& build) {
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
    Support support = read_fix(entry.child("fix"), node_kinds[node], id);
    support.node = node;
    build.model.supports.push_back(support);
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

void read_absorbing_ends(const Field& absorbing_ends, SceneBuild& build) {
  static const std::vector<std::string> keys{"node"};
  Model& model = build.model;
  for (const Field& entry : absorbing_ends.items()) {
    entry.expect_map("an absorbing end {node}");
    entry.check_keys(keys);
    const Field node_field = entry.child("node");
    AbsorbingEnd end;
    end.node = build.resolve_node(node_field);
    const std::string id = std::to_string(model.nodes[static_cast<std::size_t>(end.node)].id);
    std::vector<int> attached;
    for (std::size_t e = 0; e < model.elements.size(); ++e)
      for (const int n : model.elements[e].nodes)
        if (n == end.node) attached.push_back(static_cast<int>(e));
    const auto* cable = attached.size() == 1
                            ? std::get_if<CableProps>(&*model.elements[attached[0]].props)
                            : nullptr;
    if (!cable || cable->tension_only)
      node_field.fail("node " + id + " is the end of " + std::to_string(attached.size()) +
                      " elements" +
                      (attached.size() == 1 ? " (not a cable line, or a tension-only one)" : "") +
                      "; an absorbing end is the cut end of one cable line (a wire), "
                      "where the line would go on");
    end.element = attached[0];
    for (const Support& s : model.supports)
      if (s.node == end.node)
        node_field.fail("node " + id +
                        " has a support; an absorbing end replaces the support at a cut line "
                        "end (held in statics, free in the run): remove one of them");
    for (const Constraint& c : model.constraints)
      if (c.node_a == end.node || c.node_b == end.node)
        node_field.fail("node " + id +
                        " has a constraint or joint; an absorbing end takes a line's free cut "
                        "end only");
    for (const AbsorbingEnd& other : model.absorbing_ends)
      if (other.node == end.node) node_field.fail("node " + id + " is listed twice");
    model.absorbing_ends.push_back(end);
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

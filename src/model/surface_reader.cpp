#include "surface_reader.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "number_format.hpp"
#include "output_name.hpp"

namespace catena::model::detail {

void read_surfaces(const Field& surfaces, SceneBuild& build) {
  static const std::vector<std::string> keys{"name",        "point",   "normal",
                                             "stiffness",   "damping", "friction",
                                             "stick_speed", "nodes",   "line"};
  Model& model = build.model;
  for (const Field& entry : surfaces.items()) {
    entry.expect_map("a surface {point, normal, stiffness, nodes or line}");
    entry.check_keys(keys);
    Surface surface;
    const Field name = entry.child("name");
    surface.name =
        read_output_name(name, "surface " + std::to_string(model.surfaces.size() + 1), "a surface");
    for (const Surface& other : model.surfaces)
      if (other.name == surface.name)
        name.fail("two surfaces are named '" + surface.name + "'; expected distinct names");
    const Field point = entry.child("point");
    if (!point.present())
      point.fail("missing required key; expected a point of the plane [x, y, z] in m");
    surface.point = point.vec3(RealRange::any("m"));
    const Field normal = entry.child("normal");
    if (!normal.present())
      normal.fail(
          "missing required key; expected the plane's normal [x, y, z], towards the side the "
          "nodes are on");
    surface.normal = normal.vec3(RealRange::any(""));
    if (!(surface.normal.norm() > 0.0))
      normal.fail("the normal is zero; expected a nonzero vector");
    surface.normal.normalize();
    const Field stiffness = entry.child("stiffness");
    if (!stiffness.present())
      stiffness.fail("missing required key; expected the contact stiffness in N/m (> 0)");
    surface.stiffness = stiffness.real(RealRange::positive("N/m"));
    surface.damping = entry.child("damping").real_or(0.0, RealRange::non_negative("N*s/m"));
    surface.friction = entry.child("friction").real_or(0.0, RealRange::non_negative(""));
    const Field stick = entry.child("stick_speed");
    if (stick.present() && !(surface.friction > 0.0))
      stick.fail(
          "stick_speed regularises Coulomb friction, and this surface has none; give friction "
          "(a coefficient > 0) or leave stick_speed out");
    surface.stick_speed = stick.real_or(surface.stick_speed, RealRange::positive("m/s"));

    // Its nodes: listed ids, and every node of a line's elements.
    std::vector<int> nodes;
    const Field listed = entry.child("nodes");
    if (listed.present())
      for (const Field& id : listed.items()) nodes.push_back(build.resolve_node(id));
    const std::size_t n_listed = nodes.size();  // then the line's
    const Field line = entry.child("line");
    if (line.present()) {
      const std::string set = line.text();
      bool found = false;
      for (const ElementDesc& e : model.elements)
        if (e.set == set) {
          found = true;
          nodes.insert(nodes.end(), e.nodes.begin(), e.nodes.end());
        }
      if (!found)
        line.fail("no line is named '" + set + "'; expected the name of a line in `lines`");
    }
    if (!listed.present() && !line.present())
      entry.fail(
          "a surface needs the nodes that touch it: 'nodes' (a list of node ids) and/or "
          "'line' (a line's name: all its nodes)");
    if (nodes.empty()) listed.fail("the list is empty; expected at least one node id");
    // Each node on the free side, a fault named where the node came from.
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const Node& node = model.nodes[static_cast<size_t>(nodes[k])];
      const double gap = (node.position - surface.point).dot(surface.normal);
      if (gap < 0.0)
        (k < n_listed ? listed : line)
            .fail("node " + std::to_string(node.id) + " at " + format_vector(node.position) +
                  " m is " + format_number(-gap) + " m behind the plane (through " +
                  format_vector(surface.point) + " m, normal " + format_vector(surface.normal) +
                  "); a node starts on the free side, the normal pointing to it");
      for (const RigidBody& body : model.rigid_bodies)
        if (body.node == nodes[k])
          (k < n_listed ? listed : line)
              .fail("node " + std::to_string(node.id) + " is rigid body '" + body.name +
                    "''s point: a surface acts on a node alone, not on a body's shape; give "
                    "the body a node of its own that touches (a spherical joint to it)");
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    surface.nodes = std::move(nodes);
    model.surfaces.push_back(std::move(surface));
  }
}

}  // namespace catena::model::detail

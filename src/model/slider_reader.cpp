#include "slider_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "catena/model/path_stations.hpp"
#include "line_path_reader.hpp"
#include "number_format.hpp"
#include "output_name.hpp"

namespace catena::model::detail {
namespace {

// m: how far a slider's node may lie from its path (the constraint holds it there from the
// first step: a gap would be a jump).
constexpr double kOnPathTolerance = 1e-6;

// The arc length of the path point nearest to x. A path is straight in the reference
// configuration (cables and beams meeting at a node are collinear, model/nodal_frames), so
// its ANCF curve there is its chords.
double nearest_arc_length(const Model& model, const std::vector<int>& elements,
                          const PathStations& stations, const Vec3& x) {
  double best = 0.0, best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const double a = stations.start[i], b = stations.start[i + 1];
    const Vec3 pa = path_point(model, elements, stations, a);
    const Vec3 chord = path_point(model, elements, stations, b) - pa;
    const double u = chord.squaredNorm() > 0.0
                         ? std::clamp((x - pa).dot(chord) / chord.squaredNorm(), 0.0, 1.0)
                         : 0.0;
    const double distance = (pa + u * chord - x).norm();
    if (distance < best_distance) {
      best_distance = distance;
      best = a + u * (b - a);
    }
  }
  return best;
}

}  // namespace

void read_sliders(const Field& sliders, SceneBuild& build) {
  static const std::vector<std::string> keys{"name",    "node",     "path",       "line",
                                             "damping", "friction", "stick_speed"};
  Model& model = build.model;
  for (const Field& entry : sliders.items()) {
    entry.expect_map("a slider {node, path or line, damping, friction, stick_speed}");
    entry.check_keys(keys);
    Slider slider;
    const Field name = entry.child("name");
    slider.name =
        read_output_name(name, "slider " + std::to_string(model.sliders.size() + 1), "a slider");
    for (const Slider& other : model.sliders)
      if (other.name == slider.name)
        name.fail("two sliders are named '" + slider.name + "'; expected distinct names");
    const Field node_field = entry.child("node");
    if (!node_field.present())
      node_field.fail("missing required key; expected the id of the node that slides");
    slider.node = build.resolve_node(node_field);
    const Node& node = model.nodes[static_cast<size_t>(slider.node)];
    const std::string id = std::to_string(node.id);
    for (const Slider& other : model.sliders)
      if (other.node == slider.node)
        node_field.fail("node " + id + " already carries slider '" + other.name +
                        "'; a node carries one slider");
    for (const RigidBody& body : model.rigid_bodies)
      if (body.node == slider.node)
        node_field.fail("node " + id + " is rigid body '" + body.name +
                        "''s point; give the slider a node of its own and join the body to it "
                        "with a spherical joint");
    if (node.tangent != Vec3::Zero())
      node_field.fail("node " + id +
                      " is a node of a cable or beam; a slider needs a node of its own (bars, "
                      "springs, masses and spherical joints may attach to it)");
    // Its own path (from `line`) is named after the line, as in `catena check`.
    const Field line = entry.child("line");
    slider.path = read_path_or_line(
        entry, build, line.present() && line.is_scalar() ? line.text() : "slider " + slider.name,
        "sliders");
    const std::vector<int>& path = model.paths[static_cast<size_t>(slider.path)].elements;
    for (int e : path)
      for (int n : model.elements[static_cast<size_t>(e)].nodes)
        if (n == slider.node)
          node_field.fail("node " + id +
                          " is a node of the slider's own path; a slider needs "
                          "a node of its own, placed on the path");
    const PathStations stations = path_stations(model, path);
    slider.start = nearest_arc_length(model, path, stations, node.position);
    const Vec3 nearest = path_point(model, path, stations, slider.start);
    const double gap = (nearest - node.position).norm();
    if (!(gap <= kOnPathTolerance))
      node_field.fail("node " + id + " at " + format_vector(node.position) + " m is " +
                      format_number(gap) + " m from its path (nearest point " +
                      format_vector(nearest) + " m, " + format_number(slider.start) +
                      " m along it); a slider's node must lie on the path within " +
                      format_number(kOnPathTolerance) + " m: move it there");
    // At an end any outward motion leaves the path (solvers/time/state_guard.hpp).
    if (!(slider.start > kOnPathTolerance && slider.start < stations.length() - kOnPathTolerance))
      node_field.fail("node " + id + " is at the end of its path (" + format_number(slider.start) +
                      " m along it, of " + format_number(stations.length()) +
                      " m); a slider starts inside its path");
    slider.damping = entry.child("damping").real_or(0.0, RealRange::non_negative("N*s/m"));
    slider.friction = entry.child("friction").real_or(0.0, RealRange::non_negative(""));
    const Field stick = entry.child("stick_speed");
    if (stick.present() && !(slider.friction > 0.0))
      stick.fail(
          "stick_speed regularises Coulomb friction, and this slider has none; give "
          "friction (a coefficient > 0) or leave stick_speed out");
    slider.stick_speed = stick.real_or(slider.stick_speed, RealRange::positive("m/s"));
    model.sliders.push_back(slider);
  }
}

void check_sliders_carried(const Field& sliders, const SceneBuild& build) {
  const Model& model = build.model;
  const std::vector<Field> entries = sliders.items();
  for (size_t k = 0; k < model.sliders.size(); ++k) {
    const int node = model.sliders[k].node;
    bool carried = false;
    for (const PointMass& m : model.point_masses) carried = carried || m.node == node;
    for (const ElementDesc& e : model.elements)
      for (int n : e.nodes) carried = carried || n == node;
    for (const ElasticSupport& s : model.elastic_supports) carried = carried || s.node == node;
    for (const Joint& j : model.joints) carried = carried || j.node_b == node;
    if (!carried)
      entries[k].child("node").fail(
          "slider '" + model.sliders[k].name + "''s node " +
          std::to_string(model.nodes[static_cast<size_t>(node)].id) +
          " carries nothing: a slider has no mass of its own; put a mass on it (masses), "
          "join a body to it (a spherical joint) or attach a spring or bar");
  }
}

void add_slider_constraints(SceneBuild& build) {
  Model& model = build.model;
  for (size_t k = 0; k < model.sliders.size(); ++k) {
    Slider& slider = model.sliders[k];
    Constraint c;
    c.type = ConstraintType::slider;
    c.node_a = slider.node;
    c.slider = static_cast<int>(k);
    c.equations = 3;
    slider.constraint = static_cast<int>(model.constraints.size());
    model.constraints.push_back(c);
  }
}

}  // namespace catena::model::detail

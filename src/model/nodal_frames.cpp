#include "nodal_frames.hpp"

#include <cmath>
#include <string>

#include "number_format.hpp"

namespace catena::model::detail {
namespace {

constexpr double direction_tolerance = 1e-9;  // |t_1 - t_2| of unit directions
constexpr double parallel_sine = 1e-6;        // y_axis vs beam axis

std::string element_label(const SceneBuild& build, int element) {
  return "element " + std::to_string(build.model.elements[element].id) + " (" +
         build.element_origin(element).path() + ")";
}

[[noreturn]] void fail_kinked_slope(const SceneBuild& build, int node, int first, int second,
                                    const Vec3& first_direction, const Vec3& second_direction) {
  const bool reversed = (first_direction + second_direction).norm() <= direction_tolerance;
  const std::string how = reversed ? "run in opposite directions" : "meet at an angle";
  build.element_origin(second).fail(
      "at node " + std::to_string(build.model.nodes[node].id) + ", " + element_label(build, first) +
      " and " + element_label(build, second) + " " + how + " (directions " +
      format_vector(first_direction) + " and " + format_vector(second_direction) +
      "). ANCF slopes are continuous at a node, so the cables and beams meeting there "
      "must be collinear and run the same way (first node to second node). " +
      (reversed ? "Reverse one element's nodes (or a line's from/to)."
                : "Use separate nodes joined by a short stiff element (spring or bar)."));
}

}  // namespace

void check_element_lengths(const SceneBuild& build) {
  const double tolerance = build.zero_length_tolerance();
  const auto& nodes = build.model.nodes;
  for (std::size_t e = 0; e < build.model.elements.size(); ++e) {
    const ElementDesc& element = build.model.elements[e];
    if (std::holds_alternative<SpringProps>(*element.props)) continue;
    const Node& a = nodes[element.nodes[0]];
    const Node& b = nodes[element.nodes[1]];
    const double length = (b.position - a.position).norm();
    if (length > tolerance) continue;
    build.element_origin(static_cast<int>(e))
        .fail("element " + std::to_string(element.id) + " has zero length: nodes " +
              std::to_string(a.id) + " and " + std::to_string(b.id) + " coincide at " +
              format_vector(a.position) + " (tolerance " + format_number(tolerance) +
              " m); only springs may join coincident nodes");
  }
}

void assign_nodal_frames(SceneBuild& build) {
  std::vector<Node>& nodes = build.model.nodes;
  std::vector<int> tangent_source(nodes.size(), -1);  // element that set the tangent
  std::vector<int> section_source(nodes.size(), -1);  // beam element that set section_y
  for (std::size_t e = 0; e < build.model.elements.size(); ++e) {
    const ElementDesc& element = build.model.elements[e];
    const auto* beam = std::get_if<BeamProps>(&*element.props);
    if (!beam && !std::holds_alternative<CableProps>(*element.props)) continue;
    const int self = static_cast<int>(e);
    const Vec3 axis =
        (nodes[element.nodes[1]].position - nodes[element.nodes[0]].position).normalized();
    for (const int node : element.nodes) {
      if (tangent_source[node] < 0) {
        nodes[node].tangent = axis;
        tangent_source[node] = self;
      } else if ((axis - nodes[node].tangent).norm() > direction_tolerance) {
        fail_kinked_slope(build, node, tangent_source[node], self, nodes[node].tangent, axis);
      }
    }
    if (!beam) continue;

    const double sine = beam->y_axis.cross(axis).norm();
    if (sine < parallel_sine)
      build.element_origin(self).fail(
          "section '" + build.element_origin(self).child("section").text() + "' has y_axis " +
          format_vector(beam->y_axis) + ", parallel to the axis " + format_vector(axis) +
          " of beam element " + std::to_string(element.id) + " (|sin| = " + format_number(sine) +
          " < 1e-6); choose a y_axis across the beam");
    const Vec3 section_y = (beam->y_axis - beam->y_axis.dot(axis) * axis).normalized();
    for (const int node : element.nodes) {
      if (section_source[node] < 0) {
        nodes[node].section_y = section_y;
        nodes[node].section_z = nodes[node].tangent.cross(section_y);
        section_source[node] = self;
      } else if ((section_y - nodes[node].section_y).norm() > direction_tolerance) {
        build.element_origin(self).fail(
            "at node " + std::to_string(nodes[node].id) + ", " +
            element_label(build, section_source[node]) + " and " + element_label(build, self) +
            " give different section y axes " + format_vector(nodes[node].section_y) + " and " +
            format_vector(section_y) + "; beams sharing a node need sections with the same y_axis");
      }
    }
  }
}

}  // namespace catena::model::detail

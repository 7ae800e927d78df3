#include "catena/model/explicit_step_limit.hpp"

#include <cmath>
#include <variant>

#include "number_format.hpp"

namespace catena::model {
namespace {

double mesh_length(const Model& m, const ElementDesc& e) {
  return (m.nodes[static_cast<std::size_t>(e.nodes.back())].position -
          m.nodes[static_cast<std::size_t>(e.nodes.front())].position)
      .norm();
}

std::string element_text(const ElementDesc& e, const char* kind, double length) {
  std::string text = kind;
  text += " element ";
  text += std::to_string(e.id);
  if (!e.set.empty()) {
    text += " of set '";
    text += e.set;
    text += '\'';
  }
  text += " (";
  text += detail::format_number(length);
  text += " m)";
  return text;
}

}  // namespace

ExplicitStepLimit explicit_step_limit(const Model& m) {
  ExplicitStepLimit limit;
  const auto consider = [&](double omega, const std::string& source) {
    if (omega > limit.omega) {
      limit.omega = omega;
      limit.source = source;
    }
  };
  for (const ElementDesc& e : m.elements) {
    if (std::holds_alternative<BeamProps>(e.props)) limit.has_beams = true;
    const double length = mesh_length(m, e);
    if (!(length > 0.0)) continue;
    if (const auto* cable = std::get_if<CableProps>(&e.props)) {
      // μ per mesh length μ/(1 + ε_p); the axial stiffness per mesh length EA (1 + ε_p)².
      const double stretch = 1.0 + cable->prestrain;
      if (cable->mass_per_length > 0.0)
        consider(
            std::sqrt(105.0 * cable->EA * stretch * stretch * stretch / cable->mass_per_length) /
                length,
            element_text(e, "cable", length));
    } else if (const auto* bar = std::get_if<BarProps>(&e.props)) {
      if (bar->mass_per_length > 0.0)
        consider(2.0 * std::sqrt(bar->EA / bar->mass_per_length) / length,
                 element_text(e, "bar", length));
    }
  }
  for (const MovingContact& c : m.contacts) {
    const ElementPath& path = m.paths[static_cast<std::size_t>(c.path)];
    if (path.elements.empty()) continue;
    const ElementDesc& wire = m.elements[static_cast<std::size_t>(path.elements.front())];
    const auto* cable = std::get_if<CableProps>(&wire.props);
    if (!cable || !(cable->mass_per_length > 0.0)) continue;
    const double wire_mass = cable->mass_per_length * mesh_length(m, wire);
    const double head = c.stages.empty() ? 0.0 : c.stages.front().mass;
    consider(std::sqrt(c.stiffness * (1.0 / wire_mass + (head > 0.0 ? 1.0 / head : 0.0))),
             "the contact spring of pantograph '" + c.name + "'");
  }
  if (limit.omega > 0.0) limit.step = 2.0 / limit.omega;
  return limit;
}

}  // namespace catena::model

#pragma once
// The contact spring's own mode: a pantograph's head on its penalty spring against the
// wire's mass over one element, the highest frequency a penalty contact adds to a scene,
//   ω = √(k_c (1/m_head + 1/(μ L_e))),
// with k_c the contact stiffness, m_head the head's (first stage's) mass and μ L_e the
// mass of the path's lightest element (its ends' distance as L_e). `catena check` compares dt·ω
// with what resolves it (model/structure_advice.cpp), and both check and run warn where a multistep
// method's numerical damping hides an unresolved one (model/moving_summary.cpp).
//
// Not collective: plain numbers.
#include <cmath>
#include <limits>
#include <variant>

#include "catena/model/integrator_catalogue.hpp"
#include "catena/model/model.hpp"
#include "catena/model/path_stations.hpp"

namespace catena::model {

struct ContactMode {
  double omega = 0.0;           // rad/s; 0: no spring (bilateral) or no wire mass to say it
  double element_length = 0.0;  // m, of the path element it was taken on
};

// The mode on the path's lightest element (the smallest μ L_e), where it is highest.
inline ContactMode contact_mode(const Model& m, const MovingContact& c) {
  if (c.bilateral) return {};
  double wire_mass = 0.0, element_length = 0.0;
  for (const int index : m.paths[static_cast<std::size_t>(c.path)].elements) {
    const ElementDesc& e = m.elements[static_cast<std::size_t>(index)];
    double mass_per_length = 0.0;
    if (const auto* cable = std::get_if<CableProps>(&*e.props))
      mass_per_length = cable->mass_per_length;
    if (const auto* beam = std::get_if<BeamProps>(&*e.props))
      mass_per_length = beam->mass_per_length;
    const double length = element_chord(m, index);  // as the path's stations measure it
    const double mass = mass_per_length * length;
    if (mass > 0.0 && (wire_mass == 0.0 || mass < wire_mass)) {
      wire_mass = mass;
      element_length = length;
    }
  }
  if (wire_mass <= 0.0) return {};
  const double m_head = c.stages.empty() ? 0.0 : c.stages.front().mass;
  const double inverse_mass = 1.0 / wire_mass + (m_head > 0.0 ? 1.0 / m_head : 0.0);
  return {std::sqrt(c.stiffness * inverse_mass), element_length};
}

// The largest dt·ω of the contact mode at which a multistep method (Park, BDF-2) keeps the
// contact force's σ within 0.22 % where it was measured, at least 25 steps a period
// (docs/accuracy.md, "The multistep methods' gap"). Beyond it their numerical damping
// smooths the mode into a force that is wrong but smooth, which the run's roughness check
// (post/contact_resolution.hpp) cannot see: measured σ errors at dt·ω 0.20 (EN 50318 at
// 300 km/h, dt 0.5 ms) −0.1 % (Park) and −0.2 % (BDF-2); at 0.39 (dt 1 ms) −1.0 % and
// −1.6 %; a wire at 0.28 (dt 1 ms) +1.3 % and −2.0 %; with 100 times the contact stiffness
// at 0.28 (dt 0.1 ms) −18 % and −39 %, and still −4.5 % and −29 % at 0.14 (dt 0.05 ms):
// a contact that stiff loses contact and strikes again, and the strikes' content lies far
// above its own mode, so no limit on dt·ω covers it. At 0.25 BDF-2 takes 2.1 % off the
// mode's amplitude a period (the larger root of (3/2 − i dt·ω) ζ² − 2ζ + 1/2 = 0).
inline constexpr double kMultistepContactLimit = 0.25;
// BDF of order 1 (backward Euler, |ζ| = 1/√(1 + (dt·ω)²)) takes the same 2.1 % a period
// off already at dt·ω = 0.0068.
inline constexpr double kBackwardEulerContactLimit = 0.0068;

// The limit above for the scene's integrator, or +∞ where it does not apply: one-step
// methods (their unresolved contact force is rough, and the run's check says so), adaptive
// steps, and the modal model (its modal coordinates take no integrator.type).
inline double multistep_contact_limit(const Model& m) {
  const IntegratorOptions& o = m.dynamic_options.integrator;
  const IntegratorType* type = find_integrator_type(o.type);
  if (!type || !type->multistep || o.adaptive ||
      m.dynamic_options.structure == StructureModel::modal)
    return std::numeric_limits<double>::infinity();
  return o.type == "bdf" && o.order == 1 ? kBackwardEulerContactLimit : kMultistepContactLimit;
}

}  // namespace catena::model

#pragma once
// The contact spring's own mode: a pantograph's head on its penalty spring against the
// wire's mass over one element, the highest frequency a penalty contact adds to a scene,
//   ω = √(k_c (1/m_head + 1/(μ L_e))),
// with k_c the contact stiffness, m_head the head's (first stage's) mass, μ the path's
// mass per length and L_e its first element's length. `catena check` compares dt·ω with
// what resolves it (model/structure_advice.cpp), and both check and run warn where a
// multistep method's numerical damping hides an unresolved one (model/moving_summary.cpp).
//
// Not collective: plain numbers.
#include <cmath>
#include <variant>

#include "catena/model/model.hpp"

namespace catena::model {

// rad/s; 0 for a bilateral contact (no spring) or a path whose first element carries no
// mass per length (then there is nothing to say).
inline double contact_mode_omega(const Model& m, const MovingContact& c) {
  if (c.bilateral) return 0.0;
  const std::vector<int>& elements = m.paths[static_cast<std::size_t>(c.path)].elements;
  if (elements.empty()) return 0.0;
  const ElementDesc& e = m.elements[static_cast<std::size_t>(elements.front())];
  double mass_per_length = 0.0;
  if (const auto* cable = std::get_if<CableProps>(&e.props))
    mass_per_length = cable->mass_per_length;
  if (const auto* beam = std::get_if<BeamProps>(&e.props)) mass_per_length = beam->mass_per_length;
  const double length = (m.nodes[static_cast<std::size_t>(e.nodes.back())].position -
                         m.nodes[static_cast<std::size_t>(e.nodes.front())].position)
                            .norm();
  if (mass_per_length <= 0.0 || length <= 0.0) return 0.0;
  const double m_head = c.stages.empty() ? 0.0 : c.stages.front().mass;
  const double inverse_mass =
      1.0 / (mass_per_length * length) + (m_head > 0.0 ? 1.0 / m_head : 0.0);
  return std::sqrt(c.stiffness * inverse_mass);
}

// The largest dt·ω of the contact mode at which the multistep methods (Park, BDF, ABM)
// were measured to keep the contact force's σ within about 2 %, at least 25 steps a period
// (docs/accuracy.md, "The multistep methods' gap"). Their numerical damping smooths the
// mode beyond it into a force that is wrong but smooth, which the run's roughness check
// (post/contact_resolution.hpp) cannot see: measured σ errors at dt·ω 0.39 (EN 50318 at
// 300 km/h, dt 1 ms) −1.0 % (Park) and −1.6 % (BDF-2), at 0.20 (dt 0.5 ms) −0.1 % and
// −0.2 %; a wire at 0.28 (dt 1 ms) +1.3 % and −2.0 %; with 100 times the contact stiffness
// at 0.28 (dt 0.1 ms) −18 % and −39 %.
inline constexpr double kMultistepContactLimit = 0.25;

}  // namespace catena::model

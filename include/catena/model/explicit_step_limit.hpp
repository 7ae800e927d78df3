#pragma once
// The largest step central differences (integrator.type central_difference: Newmark β = 0,
// γ = ½) take stably on a model: h ≤ 2/ω_max, ω_max the highest undamped frequency
// (Hughes, The Finite Element Method, 2000, §9.1), bounded before the run from closed
// forms of the parts that carry it:
// - an ANCF cable element's highest mode is axial: with its axial strain sampled at the
//   Lobatto points (Simpson's weights, elements/ancf_cable.hpp) and its consistent mass,
//   the cubic Hermite element's free–free spectrum ends at ω = √105 · c / L, c = √(EA/μ)
//   the bar wave speed (μ per mesh length, EA with the prestrain's stretch);
// - a bar with mass lumped half to each end: ω = 2 c / L;
// - a pantograph's contact spring: the head against one wire element's mass,
//   ω = √(k (1/m_head + 1/(μ L))).
// Measured on the taut string (1 m cables: 2/ω = 5.35e-5 s; stable at 5e-5, unstable at
// 6e-5) and on EN 50318's line (0.25 m: 1.34e-5 s; stable at 1.3e-5, garbage at 1.4e-5
// that the state guard does not catch: the nonlinear droppers and contact bound it),
// docs/integrators.md. Not bounded here: beams, springs and massless bars (stiff ones
// between light masses would lower the limit), which the result names.
//
// Not collective: no MPI, no PETSc.
#include <limits>
#include <string>

#include "catena/model/model.hpp"

namespace catena::model {

struct ExplicitStepLimit {
  double omega = 0.0;                                     // rad/s, the highest bound found
  double step = std::numeric_limits<double>::infinity();  // s, 2/omega
  std::string source;      // what carries it: "cable element 12 of set 'contact_wire' (0.25 m)"
  bool has_beams = false;  // beams are not bounded (their own modes are not in omega)
};

ExplicitStepLimit explicit_step_limit(const Model& model);

}  // namespace catena::model

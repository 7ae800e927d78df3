#pragma once
// The continuum truth of a straight cantilever under a dead tip load ⊥ its axis: the
// extensible, shear-rigid elastica, for either bending law (core/curvature_measure.hpp),
// solved by shooting. Tests only.
//
// Along the reference arc length s ∈ [0, L], θ the tangent angle, m the bending moment
// (conjugate of θ' = dθ/ds), λ the stretch: the section force is P·n̂ throughout, so
//   N = P sin θ (tangential),  m' = −λ P cos θ,  x' = λ cos θ,  y' = λ sin θ,
// with θ(0) = 0, x(0) = y(0) = 0, m(L) = 0, and the law per unit reference length
//   reference length:  W = ½EA (λ−1)² + ½EI θ'²      ⇒ θ' = m/EI,  λ = 1 + N/EA
//   deformed length:   W = ½EA (λ−1)² + ½EI θ'²/λ²   ⇒ θ' = m λ²/EI, and ∂W/∂λ = N gives
//                      λ = (EA + N)/(EA − m²/EI).
// Classical RK4 in s (4000 steps: truncation far below 1e-10 m for the Gerstmayr–Irschik
// cantilever), bisection on m(0) between 0.5 and 1.5 P L.
#include "catena/core/curvature_measure.hpp"

namespace catena::test {

struct Cantilever {
  double length, EA, EI, load;  // m, N, N·m², N
};

struct CantileverTip {
  double ux, uy;  // shortening along the axis L − x_tip, deflection along the load y_tip
};

CantileverTip elastica_tip(const Cantilever& c, CurvatureMeasure law);

// Gerstmayr & Irschik's large-deflection cantilever (J. Sound Vib. 318 (2008) 461–487):
// L = 2 m, square steel section b = h = 0.1 m, E = 2.07e11 Pa (EA = 2.07e9 N, EI =
// 1.725e6 N·m²), dead tip load P = 3 EI/L².
inline constexpr double kGerstmayrIrschikEI = 2.07e11 * 1e-4 / 12.0;
inline constexpr Cantilever kGerstmayrIrschik{2.0, 2.07e9, kGerstmayrIrschikEI,
                                              3.0 * kGerstmayrIrschikEI / 4.0};

}  // namespace catena::test

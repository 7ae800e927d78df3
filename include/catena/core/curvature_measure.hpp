#pragma once
// Which curvature the bending energy of a cable or beam squares (docs/formulation.md,
// "Bending law"). Shared by the scene model (a section key) and the elements, which are
// sibling layers, hence here.
//
//   reference_length  κ₀ = dθ/ds₀ = |r'×r''|/|r'|² (per unit reference length): the
//                     bending strain of the geometrically exact (Reissner) rod, M = EI κ₀.
//                     Bending and stretching are uncoupled: EA ε is the tangential
//                     section force.
//   deformed_length   κ = |r'×r''|/|r'|³ (the curve's curvature, per deformed length),
//                     M = EI κ. The bending energy then falls as the line stretches, so
//                     bending drives stretching: EA ε = N + EI κ²/(1 + ε).
#include <array>
#include <string_view>

namespace catena {

enum class CurvatureMeasure { reference_length, deformed_length };

// Scene names, indexed by the enum's value.
inline constexpr std::array<std::string_view, 2> kCurvatureMeasureNames{"reference_length",
                                                                        "deformed_length"};

}  // namespace catena

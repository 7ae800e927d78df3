#pragma once
// The frequency key of a prescribed motion velocity·t + amplitude·sin(2π·frequency·t)
// (a node's `prescribed` constraint, a joint's `motion`).
#include <string>

#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. The frequency in Hz: required (> 0) when the amplitude is nonzero, refused
// when it is zero (0 returned); `amplitude_unit` names the amplitude's unit in messages.
double read_sine_frequency(const Field& frequency, bool amplitude_is_zero,
                           const std::string& amplitude_unit);

}  // namespace catena::model::detail

#pragma once
// The `rayleigh` key of cable and beam sections and of the catenary's wires: proportional
// damping D = α M + β K_ref (elements/rayleigh_damped.hpp), given either by its
// coefficients or by a damping ratio at two frequencies. docs/scene.md "Rayleigh damping".
#include "catena/model/model.hpp"
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. Absent: no Rayleigh damping. Accepted forms:
//   {mass: α (1/s, >= 0), stiffness: β (s, >= 0)}          at least one of them > 0
//   {ratio: ζ (in (0, 1)), frequencies: [f1, f2] (Hz, 0 < f1 < f2)}
Rayleigh read_rayleigh(const Field& rayleigh);

}  // namespace catena::model::detail

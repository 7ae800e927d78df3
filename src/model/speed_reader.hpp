#pragma once
// The speed of something that moves along a path (moving loads, pantographs): exactly one
// of `speed` (m/s) and `speed_kmh` (km/h) in its scene entry.
#include "yaml_fields.hpp"

namespace catena::model::detail {

// Not collective. m/s, ≥ 0; fails at the entry (neither given) or at `speed_kmh` (both).
double read_speed(const Field& entry);

// Not collective. A pantograph's velocity along its path, m/s: read_speed, negative with
// `direction: backward` (toward decreasing arc length; default forward). Fails at
// `direction` for any other value.
double read_path_velocity(const Field& entry);

}  // namespace catena::model::detail

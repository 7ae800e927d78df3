#pragma once
// How numbers appear in messages and in the `catena check` summary: 6 significant digits,
// so that values the user wrote (1.8e7, 0.5) come back as written.
#include <string>

#include "catena/core/vec3.hpp"

namespace catena::model::detail {

// Not collective. "%.6g": 20000, 0.00111111, 1.8e+07.
std::string format_number(double x);

// Not collective. "(x, y, z)" with format_number components.
std::string format_vector(const Vec3& v);

}  // namespace catena::model::detail

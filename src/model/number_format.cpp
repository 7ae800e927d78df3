#include "number_format.hpp"

#include <array>
#include <cstdio>

namespace catena::model::detail {

std::string format_number(double x) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.6g", x);
  return buffer.data();
}

std::string format_vector(const Vec3& v) {
  // Appended piece by piece: GCC 12's -Wrestrict misfires on "(" + std::string&& at -O2.
  std::string text = "(";
  text += format_number(v.x());
  text += ", ";
  text += format_number(v.y());
  text += ", ";
  text += format_number(v.z());
  text += ")";
  return text;
}

}  // namespace catena::model::detail

#pragma once
// The vocabulary in which an element's properties struct (element_props.hpp) declares its
// scene keys, once, in `template <class Keys> void read_keys(Keys& k)`. The same
// declaration is run by the scene reader, which reads and validates each key into the
// member it names (src/model/section_reader.cpp), and by KeyNames below, which only lists
// the keys: the accepted keys in messages and the typo suggestions come from it, so a key
// cannot be read without being accepted, or accepted without being read. No yaml-cpp here.
//
// The operations, each naming its key; declare them in the order docs/scene.md lists the
// keys (messages list accepted keys in that order, after `type`):
//   k.real(key, double& value, Range, unit)               required
//   k.real_or(key, double& value, fallback, Range, unit)  absent: fallback
//   k.boolean_or(key, bool& value, fallback)              true | false; absent: fallback
//   k.rayleigh(key, Rayleigh& value)                      docs/scene.md "Rayleigh damping";
//                                                         absent: none
//   k.direction_or(key, Vec3& value, fallback)            [x, y, z], not zero; stored as a
//                                                         unit vector; absent: fallback
//   k.spring_stiffness(key, Vec3& value)                  a scalar or [kx, ky, kz] in N/m,
//                                                         each >= 0, not all zero; required
//   k.spring_damping(key, Vec3& value)                    a scalar or [cx, cy, cz] in N·s/m,
//                                                         each >= 0; absent: zero
//   k.choice_or(key, Enum& value, fallback, names)        one of names (names[i] is the
//                                                         enum value i); absent: fallback
// Units are written as in messages ("N*m^2", "kg/m"); "" is dimensionless.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "catena/core/vec3.hpp"

namespace catena::model {

struct Rayleigh;

// The accepted values of a real-valued key (all finite, and within the unit's physical
// bound: docs/scene.md "Physical bounds").
enum class Range {
  positive,      // > 0
  non_negative,  // >= 0
};

// A `Keys` for read_keys that records the key names in declaration order and reads
// nothing. Not collective.
class KeyNames {
 public:
  const std::vector<std::string>& names() const { return names_; }

  void real(std::string_view key, double&, Range, std::string_view) { add(key); }
  void real_or(std::string_view key, double&, double, Range, std::string_view) { add(key); }
  void boolean_or(std::string_view key, bool&, bool) { add(key); }
  void rayleigh(std::string_view key, Rayleigh&) { add(key); }
  void direction_or(std::string_view key, Vec3&, const Vec3&) { add(key); }
  void spring_stiffness(std::string_view key, Vec3&) { add(key); }
  void spring_damping(std::string_view key, Vec3&) { add(key); }
  template <class Enum>
  void choice_or(std::string_view key, Enum&, Enum, std::span<const std::string_view>) {
    add(key);
  }

 private:
  void add(std::string_view key) { names_.emplace_back(key); }
  std::vector<std::string> names_;
};

// Not collective. The keys a properties struct declares, in declaration order (without
// the `type` every section has).
template <class Props>
std::vector<std::string> declared_keys() {
  Props props;
  KeyNames keys;
  props.read_keys(keys);
  return keys.names();
}

}  // namespace catena::model

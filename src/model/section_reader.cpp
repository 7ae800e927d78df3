#include "section_reader.hpp"

#include <algorithm>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "did_you_mean.hpp"
#include "rayleigh_reader.hpp"

namespace catena::model::detail {
namespace {

// Reads each key a properties struct declares (catena/model/scene_keys.hpp) from its
// section, validated, into the member the declaration names.
class SectionKeys {
 public:
  explicit SectionKeys(const Field& section) : section_(section) {}

  void real(std::string_view key, double& value, Range range, std::string_view unit) const {
    value = section_.child(key).real(real_range(range, unit));
  }
  void real_or(std::string_view key, double& value, double fallback, Range range,
               std::string_view unit) const {
    value = section_.child(key).real_or(fallback, real_range(range, unit));
  }
  void boolean_or(std::string_view key, bool& value, bool fallback) const {
    value = section_.child(key).boolean_or(fallback);
  }
  void rayleigh(std::string_view key, Rayleigh& value) const {
    value = read_rayleigh(section_.child(key));
  }
  void direction_or(std::string_view key, Vec3& value, const Vec3& fallback) const {
    const Field field = section_.child(key);
    const Vec3 direction = field.vec3_or(fallback, RealRange::any(""));
    if (!(direction.norm() > 0.0))
      field.fail(std::string(key) + " is the zero vector; expected a direction");
    value = direction.normalized();
  }
  void spring_stiffness(std::string_view key, Vec3& value) const {
    value = read_spring_stiffness(section_.child(key));
  }
  void spring_damping(std::string_view key, Vec3& value) const {
    value = read_spring_damping(section_.child(key));
  }
  template <class Enum>
  void choice_or(std::string_view key, Enum& value, Enum fallback,
                 std::span<const std::string_view> names) const {
    value = static_cast<Enum>(read_choice(section_.child(key), static_cast<int>(fallback), names));
  }

 private:
  static RealRange real_range(Range range, std::string_view unit) {
    switch (range) {
      case Range::positive:
        return RealRange::positive(std::string(unit));
      case Range::non_negative:
        return RealRange::non_negative(std::string(unit));
    }
    return RealRange::positive(std::string(unit));  // not reached: every Range is above
  }

  // Index of the field's text in names (fallback when absent); anything else is refused
  // with the accepted names.
  static int read_choice(const Field& field, int fallback,
                         std::span<const std::string_view> names) {
    if (!field.present()) return fallback;
    const std::string text = field.text();
    std::vector<std::string> accepted;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == text) return static_cast<int>(i);
      accepted.emplace_back(names[i]);
    }
    std::string list;
    for (const std::string& a : accepted) list += (list.empty() ? "" : ", ") + a;
    field.fail("unknown value '" + text + "';" + did_you_mean(text, accepted) +
               " accepted: " + list);
  }

  const Field& section_;
};

template <class Props>
ElementProps read_props(const Field& section) {
  Props props;
  SectionKeys keys(section);
  props.read_keys(keys);
  return props;
}

// A section `type`: the kind of element it makes, everything from its properties struct.
struct SectionType {
  std::string_view name;          // Props::kind
  std::vector<std::string> keys;  // "type", then Props::read_keys's keys in order
  ElementProps (*read)(const Field& section);
};

template <class Props>
SectionType section_type() {
  std::vector<std::string> keys{"type"};
  for (std::string& key : declared_keys<Props>()) keys.push_back(std::move(key));
  return {Props::kind, std::move(keys), &read_props<Props>};
}

// Every section type, in ElementProps order (also docs/scene.md's).
const std::vector<SectionType>& section_types() {
  static const std::vector<SectionType> types = []<class... Props>(std::variant<Props...>*) {
    return std::vector<SectionType>{section_type<Props>()...};
  }(static_cast<ElementProps*>(nullptr));
  return types;
}

const SectionType& read_type(const Field& type) {
  const std::string name = type.text();
  std::vector<std::string> names;
  std::string accepted;
  for (const SectionType& t : section_types()) {
    if (t.name == name) return t;
    names.emplace_back(t.name);
    accepted += (accepted.empty() ? "" : ", ") + std::string(t.name);
  }
  type.fail("unknown section type '" + name + "';" + did_you_mean(name, names) +
            " accepted: " + accepted);
}

// A key of another section type gets a clearer message than "unknown key".
void reject_keys_of_other_types(const Field& section, const SectionType& type) {
  const std::vector<std::string>& own = type.keys;
  for (const auto& [key, value] : section.entries()) {
    if (std::find(own.begin(), own.end(), key) != own.end()) continue;
    for (const SectionType& other : section_types()) {
      if (std::find(other.keys.begin(), other.keys.end(), key) == other.keys.end()) continue;
      std::string accepted;
      for (const std::string& k : own) accepted += (accepted.empty() ? "" : ", ") + k;
      value.fail("key '" + key + "' belongs to " + std::string(other.name) + " sections, not to " +
                 std::string(type.name) + " sections; accepted keys: " + accepted);
    }
  }
  section.check_keys(own);  // anything else is a typo: suggest the closest key
}

}  // namespace

Vec3 read_spring_stiffness(const Field& stiffness) {
  const Vec3 k = stiffness.scalar_or_vec3(RealRange::non_negative("N/m"));
  if (k.maxCoeff() <= 0.0)
    stiffness.fail("stiffness is zero in every direction; at least one component must be > 0");
  return k;
}

Vec3 read_spring_damping(const Field& damping) {
  return damping.present() ? damping.scalar_or_vec3(RealRange::non_negative("N*s/m"))
                           : Vec3::Zero();
}

SectionTable read_sections(const Field& sections) {
  SectionTable table;
  for (const auto& [name, s] : sections.entries()) {
    s.expect_map("a section");
    const SectionType& type = read_type(s.child("type"));
    reject_keys_of_other_types(s, type);
    table.emplace(name, Section{name, type.read(s)});
  }
  return table;
}

const Section& find_section(const SectionTable& sections, const Field& reference) {
  const std::string name = reference.text();
  if (const auto it = sections.find(name); it != sections.end()) return it->second;
  if (sections.empty())
    reference.fail("no section named '" + name +
                   "': the scene defines no sections; add a "
                   "'sections' map (see docs/scene.md)");
  std::vector<std::string> names;
  std::string list;
  for (const auto& [defined, section] : sections) {
    names.push_back(defined);
    list += (list.empty() ? "" : ", ") + defined;
  }
  reference.fail("no section named '" + name + "';" + did_you_mean(name, names) +
                 " defined sections: " + list);
}

}  // namespace catena::model::detail

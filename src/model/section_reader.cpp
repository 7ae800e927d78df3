#include "section_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "did_you_mean.hpp"
#include "rayleigh_reader.hpp"

namespace catena::model::detail {
namespace {

struct KindKeys {
  SectionKind kind;
  std::vector<std::string> keys;
};

// The accepted keys of each section type, in the order docs/scene.md lists them.
const std::array<KindKeys, 4>& keys_by_kind() {
  static const std::array<KindKeys, 4> table{{
      {SectionKind::cable, {"type", "EA", "EI", "mass_per_length", "damping_time", "rayleigh"}},
      {SectionKind::beam,
       {"type", "EA", "GA_y", "GA_z", "GJ", "EI_y", "EI_z", "mass_per_length", "rho_Iy", "rho_Iz",
        "damping_time", "rayleigh", "y_axis"}},
      {SectionKind::bar,
       {"type", "EA", "mass_per_length", "damping", "tension_only", "unstretched_length"}},
      {SectionKind::spring, {"type", "stiffness", "damping"}},
  }};
  return table;
}

const std::vector<std::string>& keys_of(SectionKind kind) {
  return keys_by_kind()[static_cast<std::size_t>(kind)].keys;
}

SectionKind read_kind(const Field& type) {
  static const std::vector<std::string> names{"cable", "beam", "bar", "spring"};
  const std::string name = type.text();
  for (const KindKeys& k : keys_by_kind())
    if (section_kind_name(k.kind) == name) return k.kind;
  type.fail("unknown section type '" + name + "';" + did_you_mean(name, names) +
            " accepted: cable, beam, bar, spring");
}

// A key of another section type gets a clearer message than "unknown key".
void reject_keys_of_other_kinds(const Field& section, SectionKind kind) {
  const std::vector<std::string>& own = keys_of(kind);
  for (const auto& [key, value] : section.entries()) {
    if (std::find(own.begin(), own.end(), key) != own.end()) continue;
    for (const KindKeys& other : keys_by_kind()) {
      if (std::find(other.keys.begin(), other.keys.end(), key) == other.keys.end()) continue;
      std::string accepted;
      for (const std::string& k : own) accepted += (accepted.empty() ? "" : ", ") + k;
      value.fail("key '" + key + "' belongs to " + std::string(section_kind_name(other.kind)) +
                 " sections, not to " + std::string(section_kind_name(kind)) +
                 " sections; accepted keys: " + accepted);
    }
  }
  section.check_keys(own);  // anything else is a typo: suggest the closest key
}

CableProps read_cable(const Field& s) {
  CableProps p;
  p.EA = s.child("EA").real(RealRange::positive("N"));
  p.EI = s.child("EI").real(RealRange::positive("N*m^2"));
  p.mass_per_length = s.child("mass_per_length").real(RealRange::positive("kg/m"));
  p.damping_time = s.child("damping_time").real_or(0.0, RealRange::non_negative("s"));
  p.rayleigh = read_rayleigh(s.child("rayleigh"));
  return p;
}

BeamProps read_beam(const Field& s) {
  BeamProps p;
  p.EA = s.child("EA").real(RealRange::positive("N"));
  p.GA_y = s.child("GA_y").real(RealRange::positive("N"));
  p.GA_z = s.child("GA_z").real(RealRange::positive("N"));
  p.GJ = s.child("GJ").real(RealRange::positive("N*m^2"));
  p.EI_y = s.child("EI_y").real(RealRange::positive("N*m^2"));
  p.EI_z = s.child("EI_z").real(RealRange::positive("N*m^2"));
  p.mass_per_length = s.child("mass_per_length").real(RealRange::positive("kg/m"));
  p.rho_Iy = s.child("rho_Iy").real_or(0.0, RealRange::non_negative("kg*m"));
  p.rho_Iz = s.child("rho_Iz").real_or(0.0, RealRange::non_negative("kg*m"));
  p.damping_time = s.child("damping_time").real_or(0.0, RealRange::non_negative("s"));
  p.rayleigh = read_rayleigh(s.child("rayleigh"));
  const Field y_axis = s.child("y_axis");
  const Vec3 y = y_axis.vec3_or(Vec3::UnitZ(), RealRange::any(""));
  // Only the direction matters; it is checked against each element's axis later.
  if (!(y.norm() > 0.0)) y_axis.fail("y_axis is the zero vector; expected a direction");
  p.y_axis = y.normalized();
  return p;
}

BarProps read_bar(const Field& s) {
  BarProps p;
  p.EA = s.child("EA").real(RealRange::positive("N"));
  p.mass_per_length = s.child("mass_per_length").real_or(0.0, RealRange::non_negative("kg/m"));
  p.damping = s.child("damping").real_or(0.0, RealRange::non_negative("N*s/m"));
  p.unstretched_length = s.child("unstretched_length").real_or(0.0, RealRange::non_negative("m"));
  p.tension_only = s.child("tension_only").boolean_or(false);
  return p;
}

SpringProps read_spring(const Field& s) {
  SpringProps p;
  p.stiffness = read_spring_stiffness(s.child("stiffness"));
  p.damping = read_spring_damping(s.child("damping"));
  return p;
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

std::string_view section_kind_name(SectionKind kind) {
  switch (kind) {
    case SectionKind::cable:
      return "cable";
    case SectionKind::beam:
      return "beam";
    case SectionKind::bar:
      return "bar";
    case SectionKind::spring:
      return "spring";
  }
  return "?";
}

SectionTable read_sections(const Field& sections) {
  SectionTable table;
  for (const auto& [name, s] : sections.entries()) {
    s.expect_map("a section");
    const SectionKind kind = read_kind(s.child("type"));
    reject_keys_of_other_kinds(s, kind);
    Section section{name, kind, CableProps{}};
    switch (kind) {
      case SectionKind::cable:
        section.props = read_cable(s);
        break;
      case SectionKind::beam:
        section.props = read_beam(s);
        break;
      case SectionKind::bar:
        section.props = read_bar(s);
        break;
      case SectionKind::spring:
        section.props = read_spring(s);
        break;
    }
    table.emplace(name, std::move(section));
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

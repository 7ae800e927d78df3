// Sections are read from each properties struct's key declaration (read_keys,
// catena/model/element_props.hpp): every declared key is read into its member, optional
// keys take their documented defaults, and the accepted-key lists in messages (an unknown
// key, a key of another section type) are the documented ones, in docs/scene.md's order.
// Other malformed sections: tests/data/bad_scenes/ (test_model_scene_errors).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/model/element_props.hpp"
#include "catena/model/scene_reader.hpp"

namespace {

using namespace catena;
using namespace catena::model;

// A struct missing any of kind, node_kind and read_keys is not an ElementProps alternative
// (element_props.hpp static_asserts this for every alternative).
struct WithoutKeys {
  static constexpr const char* kind = "x";
  static constexpr UnknownKind node_kind = UnknownKind::point;
};
struct WithoutKind {
  static constexpr UnknownKind node_kind = UnknownKind::point;
  template <class Keys>
  void read_keys(Keys&) {}
};
struct WithoutNodeKind {
  static constexpr const char* kind = "x";
  template <class Keys>
  void read_keys(Keys&) {}
};
static_assert(!DescribedElementProps<WithoutKeys>);
static_assert(!DescribedElementProps<WithoutKind>);
static_assert(!DescribedElementProps<WithoutNodeKind>);
static_assert(DescribedElementProps<CableProps> && DescribedElementProps<BeamProps> &&
              DescribedElementProps<BarProps> && DescribedElementProps<SpringProps>);

// The message parse_scene gives for a scene with only the section `s`.
std::string section_error(const std::string& section) {
  try {
    parse_scene("sections:\n  s: " + section + "\n", "s.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << section;
  return "";
}

struct TypeKeys {
  std::string type;
  std::string accepted;  // as docs/scene.md lists them
};

const std::vector<TypeKeys> documented_keys{
    {"cable", "type, EA, EI, mass_per_length, damping_time, rayleigh, curvature"},
    {"beam",
     "type, EA, GA_y, GA_z, GJ, EI_y, EI_z, mass_per_length, rho_Iy, rho_Iz, damping_time, "
     "rayleigh, y_axis, curvature"},
    {"bar", "type, EA, mass_per_length, damping, tension_only, unstretched_length"},
    {"spring", "type, stiffness, damping"},
};

TEST(SectionKeys, UnknownKeyListsTheTypesKeysInDocumentedOrder) {
  for (const TypeKeys& t : documented_keys) {
    const std::string message = section_error("{type: " + t.type + ", zzz: 1}");
    // The whole list: it ends the message.
    EXPECT_TRUE(
        message.ends_with("'sections.s.zzz': unknown key 'zzz'; accepted keys: " + t.accepted))
        << message;
    EXPECT_EQ(message.find("did you mean"), std::string::npos) << message;
  }
}

TEST(SectionKeys, DeclaredKeysAreTheDocumentedOnes) {
  const auto listed = [](const std::vector<std::string>& keys) {
    std::string list = "type";
    for (const std::string& key : keys) list += ", " + key;
    return list;
  };
  EXPECT_EQ(listed(declared_keys<CableProps>()), documented_keys[0].accepted);
  EXPECT_EQ(listed(declared_keys<BeamProps>()), documented_keys[1].accepted);
  EXPECT_EQ(listed(declared_keys<BarProps>()), documented_keys[2].accepted);
  EXPECT_EQ(listed(declared_keys<SpringProps>()), documented_keys[3].accepted);
}

TEST(SectionKeys, KeyOfAnotherTypeNamesTheFirstTypeItBelongsTo) {
  struct Case {
    std::string section, message;
  };
  const std::vector<Case> cases{
      {"{type: cable, y_axis: [0, 1, 0]}",
       "key 'y_axis' belongs to beam sections, not to cable sections; accepted keys: " +
           documented_keys[0].accepted},
      {"{type: cable, stiffness: 1}",
       "key 'stiffness' belongs to spring sections, not to cable sections"},
      {"{type: beam, EI: 1}", "key 'EI' belongs to cable sections, not to beam sections"},
      // `damping` is a bar's and a spring's key: the first type in documented order.
      {"{type: beam, damping: 1}", "key 'damping' belongs to bar sections, not to beam sections"},
      {"{type: bar, EA: 1, unstretched_length: 1, rayleigh: {mass: 1}}",
       "key 'rayleigh' belongs to cable sections, not to bar sections; accepted keys: " +
           documented_keys[2].accepted},
      {"{type: spring, stiffness: 1, tension_only: true}",
       "key 'tension_only' belongs to bar sections, not to spring sections; accepted keys: " +
           documented_keys[3].accepted},
      {"{type: spring, GJ: 1}", "key 'GJ' belongs to beam sections, not to spring sections"},
  };
  for (const Case& c : cases) {
    const std::string message = section_error(c.section);
    EXPECT_NE(message.find(c.message), std::string::npos) << c.section << "\n" << message;
  }
}

TEST(SectionKeys, TypoSuggestsTheClosestKeyOfTheSameType) {
  EXPECT_NE(section_error("{type: beam, rho_Iyy: 1}").find("did you mean 'rho_Iy'?"),
            std::string::npos);
  EXPECT_NE(section_error("{type: spring, stifness: 1}").find("did you mean 'stiffness'?"),
            std::string::npos);
  EXPECT_NE(section_error("{type: bar, tension_onl: true}").find("did you mean 'tension_only'?"),
            std::string::npos);
  EXPECT_NE(section_error("{type: cabel}")
                .find("unknown section type 'cabel'; did you mean 'cable'? accepted: cable, beam, "
                      "bar, spring"),
            std::string::npos);
}

TEST(SectionKeys, ChecksOfDirectionAndSpringStiffness) {
  EXPECT_NE(section_error("{type: beam, EA: 1, GA_y: 1, GA_z: 1, GJ: 1, EI_y: 1, EI_z: 1, "
                          "mass_per_length: 1, y_axis: [0, 0, 0]}")
                .find("'sections.s.y_axis': y_axis is the zero vector; expected a direction"),
            std::string::npos);
  EXPECT_NE(section_error("{type: spring, stiffness: [0, 0, 0]}")
                .find("'sections.s.stiffness': stiffness is zero in every direction"),
            std::string::npos);
  EXPECT_NE(section_error("{type: spring, damping: 1}")
                .find("'sections.s.stiffness': missing required key; expected a number or a list"),
            std::string::npos);
  EXPECT_NE(section_error("{type: bar, EA: 1, mass_per_length: -1}")
                .find("'sections.s.mass_per_length': value -1 is out of range; expected a "
                      "finite number >= 0 [kg/m]"),
            std::string::npos);
  EXPECT_NE(section_error("{type: cable, EA: 1, EI: 1, mass_per_length: 1, curvature: deformed}")
                .find("'sections.s.curvature': unknown value 'deformed'; did you mean "
                      "'deformed_length'? accepted: reference_length, deformed_length"),
            std::string::npos);
  EXPECT_NE(section_error("{type: cable, EA: 1, EI: 0, mass_per_length: 1}")
                .find("'sections.s.EI': value 0 is out of range; expected a finite number > 0 "
                      "[N*m^2]"),
            std::string::npos);
}

// One element of each type, each type's section given by `sections`.
Model four_elements(const std::string& sections) {
  return parse_scene("sections:\n" + sections + R"(nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [10, 0, 0]}
  - {id: 3, position: [0, 1, 0]}
  - {id: 4, position: [10, 1, 0]}
  - {id: 5, position: [0, 2, 0]}
  - {id: 6, position: [0, 2, -1]}
  - {id: 7, position: [0, 3, 0]}
  - {id: 8, position: [0, 3, -1]}
elements:
  - {id: 1, section: c, nodes: [1, 2], tension: 1000}
  - {id: 2, section: b, nodes: [3, 4]}
  - {id: 3, section: r, nodes: [5, 6]}
  - {id: 4, section: s, nodes: [7, 8]}
supports:
  - {node: 1, fix: pinned}
  - {node: 2, fix: pinned}
  - {node: 3, fix: clamped}
  - {node: 5, fix: pinned}
  - {node: 6, fix: pinned}
  - {node: 7, fix: pinned}
  - {node: 8, fix: pinned}
)",
                     "four.yaml");
}

TEST(SectionKeys, OptionalKeysTakeTheirDocumentedDefaults) {
  const Model m = four_elements(
      "  c: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}\n"
      "  b: {type: beam, EA: 1e9, GA_y: 1e8, GA_z: 1e8, GJ: 1e5, EI_y: 1e6, EI_z: 1e6, "
      "mass_per_length: 10}\n"
      "  r: {type: bar, EA: 2e5}\n"
      "  s: {type: spring, stiffness: 1e5}\n");
  const auto& cable = std::get<CableProps>(*m.elements[0].props);
  EXPECT_EQ(cable.damping_time, 0.0);
  EXPECT_FALSE(cable.rayleigh.active());
  EXPECT_EQ(cable.curvature, catena::CurvatureMeasure::reference_length);
  const auto& beam = std::get<BeamProps>(*m.elements[1].props);
  EXPECT_EQ(beam.rho_Iy, 0.0);
  EXPECT_EQ(beam.rho_Iz, 0.0);
  EXPECT_EQ(beam.damping_time, 0.0);
  EXPECT_FALSE(beam.rayleigh.active());
  EXPECT_EQ(beam.y_axis, Vec3::UnitZ());
  EXPECT_EQ(beam.curvature, catena::CurvatureMeasure::reference_length);
  const auto& bar = std::get<BarProps>(*m.elements[2].props);
  EXPECT_EQ(bar.mass_per_length, 0.0);
  EXPECT_EQ(bar.damping, 0.0);
  EXPECT_FALSE(bar.tension_only);
  EXPECT_EQ(bar.unstretched_length, 0.0);
  const auto& spring = std::get<SpringProps>(*m.elements[3].props);
  EXPECT_EQ(spring.stiffness, Vec3::Constant(1e5));
  EXPECT_EQ(spring.damping, Vec3::Zero());
}

TEST(SectionKeys, EveryKeyIsReadIntoItsMember) {
  const Model m = four_elements(
      "  c: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35, damping_time: 0.02, "
      "rayleigh: {mass: 0.06, stiffness: 7.6e-5}, curvature: deformed_length}\n"
      "  b: {type: beam, EA: 1e9, GA_y: 2e8, GA_z: 3e8, GJ: 4e5, EI_y: 5e6, EI_z: 6e6, "
      "mass_per_length: 10, rho_Iy: 0.01, rho_Iz: 0.02, damping_time: 0.003, "
      "rayleigh: {mass: 0.5}, y_axis: [0, 3, 4], curvature: deformed_length}\n"
      "  r: {type: bar, EA: 2e5, mass_per_length: 0.1, damping: 5, tension_only: true, "
      "unstretched_length: 0.99}\n"
      "  s: {type: spring, stiffness: [1, 2, 3], damping: 4}\n");
  const auto& cable = std::get<CableProps>(*m.elements[0].props);
  EXPECT_EQ(cable.EA, 1.8e7);
  EXPECT_EQ(cable.EI, 195.0);
  EXPECT_EQ(cable.mass_per_length, 1.35);
  EXPECT_EQ(cable.damping_time, 0.02);
  EXPECT_EQ(cable.rayleigh.mass, 0.06);
  EXPECT_EQ(cable.rayleigh.stiffness, 7.6e-5);
  EXPECT_EQ(cable.curvature, catena::CurvatureMeasure::deformed_length);
  const auto& beam = std::get<BeamProps>(*m.elements[1].props);
  EXPECT_EQ(beam.EA, 1e9);
  EXPECT_EQ(beam.GA_y, 2e8);
  EXPECT_EQ(beam.GA_z, 3e8);
  EXPECT_EQ(beam.GJ, 4e5);
  EXPECT_EQ(beam.EI_y, 5e6);
  EXPECT_EQ(beam.EI_z, 6e6);
  EXPECT_EQ(beam.mass_per_length, 10.0);
  EXPECT_EQ(beam.rho_Iy, 0.01);
  EXPECT_EQ(beam.rho_Iz, 0.02);
  EXPECT_EQ(beam.damping_time, 0.003);
  EXPECT_EQ(beam.rayleigh.mass, 0.5);
  EXPECT_NEAR((beam.y_axis - Vec3(0, 0.6, 0.8)).norm(), 0.0, 1e-15);  // normalised
  EXPECT_EQ(beam.curvature, catena::CurvatureMeasure::deformed_length);
  const auto& bar = std::get<BarProps>(*m.elements[2].props);
  EXPECT_EQ(bar.EA, 2e5);
  EXPECT_EQ(bar.mass_per_length, 0.1);
  EXPECT_EQ(bar.damping, 5.0);
  EXPECT_TRUE(bar.tension_only);
  EXPECT_EQ(bar.unstretched_length, 0.99);
  const auto& spring = std::get<SpringProps>(*m.elements[3].props);
  EXPECT_EQ(spring.stiffness, Vec3(1, 2, 3));
  EXPECT_EQ(spring.damping, Vec3::Constant(4.0));
}

}  // namespace

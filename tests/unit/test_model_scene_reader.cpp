// The scene reader builds the Model a scene describes: shipped meshes parse, lines
// generate the documented ids and positions, prestrain follows from tension or
// unstretched length, --set overrides apply, and nodal frames are set.
// Malformed scenes: test_model_scene_errors.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/model/scene_reader.hpp"

namespace {

namespace fs = std::filesystem;
using namespace catena;
using namespace catena::model;

const fs::path meshes_dir = fs::path(CATENA_SOURCE_DIR) / "meshes";
const std::string mini_catenary =
    (fs::path(CATENA_TEST_DATA) / "good_scenes" / "mini_catenary.yaml").string();

const Node& node_with_id(const Model& m, std::int64_t id) {
  const auto it =
      std::find_if(m.nodes.begin(), m.nodes.end(), [&](const Node& n) { return n.id == id; });
  EXPECT_NE(it, m.nodes.end()) << "no node " << id;
  return *it;
}

int index_of_node(const Model& m, std::int64_t id) {
  return static_cast<int>(&node_with_id(m, id) - m.nodes.data());
}

const ElementDesc& element_with_id(const Model& m, std::int64_t id) {
  const auto it = std::find_if(m.elements.begin(), m.elements.end(),
                               [&](const ElementDesc& e) { return e.id == id; });
  EXPECT_NE(it, m.elements.end()) << "no element " << id;
  return *it;
}

std::vector<std::int64_t> element_node_ids(const Model& m, const ElementDesc& e) {
  std::vector<std::int64_t> ids;
  for (const int n : e.nodes) ids.push_back(m.nodes[n].id);
  return ids;
}

// A one-line cable scene for the override and prestrain tests.
const std::string wire_scene = R"(sections:
  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}
nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [10, 0, 0]}
lines:
  - {name: wire, from: 1, to: 2, elements: 10, section: cw, tension: 18000}
supports:
  - {node: 1, fix: pinned}
  - {node: 2, fix: pinned}
)";

double prestrain_of(const ElementDesc& e) { return std::get<CableProps>(*e.props).prestrain; }

// --- shipped meshes ---------------------------------------------------------------------

TEST(ShippedMeshes, AllParse) {
  int n_meshes = 0;
  for (const auto& entry : fs::directory_iterator(meshes_dir)) {
    if (entry.path().extension() != ".yaml") continue;
    ++n_meshes;
    EXPECT_NO_THROW(read_scene(entry.path().string())) << entry.path();
  }
  EXPECT_GE(n_meshes, 3);
}

TEST(ShippedMeshes, DefaultIsThreeSpanPretensionedWire) {
  const Model m = read_scene((meshes_dir / "default.yaml").string());
  ASSERT_EQ(m.nodes.size(), 301u);  // 5 explicit + 99 + 49 + 49 + 99 interior
  ASSERT_EQ(m.elements.size(), 300u);
  for (const ElementDesc& e : m.elements) {
    const auto& cable = std::get<CableProps>(*e.props);
    EXPECT_DOUBLE_EQ(cable.EA, 1.8e7);
    EXPECT_DOUBLE_EQ(cable.EI, 195.0);
    EXPECT_DOUBLE_EQ(cable.mass_per_length, 1.35);
    EXPECT_DOUBLE_EQ(cable.prestrain, 20000.0 / 1.8e7);
    const double length = (m.nodes[e.nodes[1]].position - m.nodes[e.nodes[0]].position).norm();
    EXPECT_NEAR(length, 0.5, 1e-12);
  }
  ASSERT_EQ(m.supports.size(), 2u);
  EXPECT_EQ(m.nodes[m.supports[0].node].id, 1);
  EXPECT_EQ(m.supports[0].fixed_mask, 0b111u);
  ASSERT_EQ(m.elastic_supports.size(), 2u);
  EXPECT_DOUBLE_EQ(m.nodes[m.elastic_supports[0].node].position.x(), 50.0);
  EXPECT_DOUBLE_EQ(m.elastic_supports[1].stiffness.z(), 5.0e4);
  ASSERT_EQ(m.nodal_loads.size(), 1u);
  EXPECT_DOUBLE_EQ(m.nodes[m.nodal_loads[0].node].position.x(), 75.0);
  EXPECT_EQ(m.nodal_loads[0].force, Vec3(0, 0, 100));
  EXPECT_EQ(m.gravity, Vec3(0, 0, -9.81));
  EXPECT_EQ(m.name, "three-span contact wire");
}

TEST(ShippedMeshes, CantileverIsClampedBeamWithTipLoad) {
  const Model m = read_scene((meshes_dir / "cantilever_beam.yaml").string());
  EXPECT_EQ(m.elements.size(), 20u);
  EXPECT_TRUE(std::holds_alternative<BeamProps>(*m.elements[0].props));
  ASSERT_EQ(m.supports.size(), 1u);
  // Position and section frame; the slope's direction (not its length) is held.
  EXPECT_EQ(m.supports[0].fixed_mask, 0xFC7u);
  EXPECT_TRUE(m.supports[0].slope_direction);
  ASSERT_EQ(m.nodal_loads.size(), 1u);
  EXPECT_DOUBLE_EQ(m.nodes[m.nodal_loads[0].node].position.x(), 2.0);
}

TEST(ShippedMeshes, HangingCableIsSlack) {
  const Model m = read_scene((meshes_dir / "hanging_cable.yaml").string());
  for (const ElementDesc& e : m.elements) EXPECT_DOUBLE_EQ(prestrain_of(e), 100.0 / 102.0 - 1.0);
  EXPECT_EQ(m.supports.size(), 2u);
}

// --- line generation, ids, explicit elements --------------------------------------------

TEST(LineGeneration, IdsPositionsAndOrderFollowTheDocumentedNumbering) {
  const Model m = read_scene(mini_catenary);
  ASSERT_EQ(m.nodes.size(), 13u);     // 6 explicit + 3 + 3 + 1 generated
  ASSERT_EQ(m.elements.size(), 13u);  // 3 explicit + 4 + 4 + 2 from lines

  // Explicit nodes first, in file order; then generated ones in line order.
  const std::vector<std::int64_t> expected_ids{10, 11, 20, 21, 30, 31, 32, 33, 34, 35, 36, 37, 38};
  for (std::size_t i = 0; i < expected_ids.size(); ++i) EXPECT_EQ(m.nodes[i].id, expected_ids[i]);
  EXPECT_EQ(node_with_id(m, 33).position, Vec3(10, 0, 1.2));
  EXPECT_EQ(node_with_id(m, 37).position, Vec3(15, 0, 0));
  EXPECT_EQ(node_with_id(m, 38).position, Vec3(0, -1.25, 0));

  // Explicit elements first; line elements numbered after the largest explicit id (110)
  // and ordered from `from` to `to`.
  const std::vector<std::int64_t> element_ids{100, 101, 110, 111, 112, 113, 114,
                                              115, 116, 117, 118, 119, 120};
  for (std::size_t i = 0; i < element_ids.size(); ++i) EXPECT_EQ(m.elements[i].id, element_ids[i]);
  EXPECT_EQ(element_node_ids(m, element_with_id(m, 111)), (std::vector<std::int64_t>{10, 32}));
  EXPECT_EQ(element_node_ids(m, element_with_id(m, 114)), (std::vector<std::int64_t>{34, 11}));
  EXPECT_EQ(element_node_ids(m, element_with_id(m, 120)), (std::vector<std::int64_t>{38, 31}));

  // Explicit elements may hang from generated nodes.
  EXPECT_EQ(element_node_ids(m, element_with_id(m, 100)), (std::vector<std::int64_t>{32, 35}));
  EXPECT_EQ(element_with_id(m, 100).set, "droppers");
  EXPECT_EQ(element_with_id(m, 110).set, "");
  EXPECT_EQ(element_with_id(m, 116).set, "contact_wire");
  EXPECT_EQ(element_with_id(m, 116).distributed_load, Vec3(0, 0.5, 0));
}

TEST(LineGeneration, SectionPropertiesReachEveryElement) {
  const Model m = read_scene(mini_catenary);
  const auto& bar = std::get<BarProps>(*element_with_id(m, 101).props);
  EXPECT_DOUBLE_EQ(bar.EA, 2.0e5);
  EXPECT_DOUBLE_EQ(bar.damping, 5.0);
  EXPECT_TRUE(bar.tension_only);
  EXPECT_DOUBLE_EQ(bar.unstretched_length, 0.0);
  const auto& spring = std::get<SpringProps>(*element_with_id(m, 110).props);
  EXPECT_EQ(spring.stiffness, Vec3::Constant(1.0e7));  // a scalar means all three axes
  EXPECT_EQ(spring.damping, Vec3(1, 2, 3));
  const auto& beam = std::get<BeamProps>(*element_with_id(m, 119).props);
  EXPECT_DOUBLE_EQ(beam.GA_z, 2.0e8);
  EXPECT_DOUBLE_EQ(beam.rho_Iy, 0.01);
  EXPECT_DOUBLE_EQ(beam.rho_Iz, 0.0);  // default
  EXPECT_EQ(beam.y_axis, Vec3(0, 0, 1));
  EXPECT_DOUBLE_EQ(std::get<CableProps>(*element_with_id(m, 115).props).damping_time, 0.01);
}

TEST(LineGeneration, ZeroLengthSpringBetweenCoincidentNodesIsAccepted) {
  // A spring joining the wire end to a coincident anchor node.
  const std::string text = R"(sections:
  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}
  joint: {type: spring, stiffness: [1e9, 1e9, 1e9]}
nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [10, 0, 0]}
  - {id: 3, position: [10, 0, 0]}
lines:
  - {from: 1, to: 2, elements: 2, section: cw}
elements:
  - {id: 1, section: joint, nodes: [2, 3]}
supports:
  - {node: 1, fix: pinned}
  - {node: 3, fix: pinned}
)";
  const Model m = parse_scene(text, "joint.yaml");
  EXPECT_EQ(m.elements.size(), 3u);
}

// --- prestrain ----------------------------------------------------------------------------

TEST(Prestrain, FromTensionIsTensionOverEA) {
  const Model m = parse_scene(wire_scene, "wire.yaml");
  for (const ElementDesc& e : m.elements) EXPECT_DOUBLE_EQ(prestrain_of(e), 18000.0 / 1.8e7);
}

TEST(Prestrain, FromUnstretchedLengthOrPrestrainOnLinesAndElements) {
  const std::string text = R"(sections:
  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}
nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [3, 4, 0]}
  - {id: 3, position: [6, 8, 0]}
lines:
  - {from: 1, to: 2, elements: 5, section: cw, unstretched_length: 4.9}
elements:
  - {id: 1, section: cw, nodes: [2, 3], unstretched_length: 5.2}
  - {id: 2, section: cw, nodes: [1, 3], prestrain: 0.25}
supports:
  - {node: 1, fix: pinned}
  - {node: 3, fix: pinned}
)";
  // Element 2 runs 1 -> 3 along the same direction: collinear slopes are fine.
  const Model m = parse_scene(text, "prestrain.yaml");
  EXPECT_DOUBLE_EQ(prestrain_of(element_with_id(m, 1)), 5.0 / 5.2 - 1.0);
  EXPECT_DOUBLE_EQ(prestrain_of(element_with_id(m, 2)), 0.25);
  EXPECT_DOUBLE_EQ(prestrain_of(element_with_id(m, 3)), 5.0 / 4.9 - 1.0);  // line: chord 5
  EXPECT_DOUBLE_EQ(prestrain_of(element_with_id(m, 7)), 5.0 / 4.9 - 1.0);
}

TEST(Prestrain, FromTensionAndUnstretchedLengthInTheMiniCatenary) {
  const Model m = read_scene(mini_catenary);
  EXPECT_DOUBLE_EQ(prestrain_of(element_with_id(m, 111)), 10000.0 / 7.0e6);
  EXPECT_DOUBLE_EQ(prestrain_of(element_with_id(m, 115)), 20.0 / 19.99 - 1.0);
}

// --- overrides ----------------------------------------------------------------------------

TEST(Overrides, OutputFile) {
  const Model m = parse_scene(wire_scene, "wire.yaml", {"output.file=x.h5"});
  EXPECT_EQ(m.output.file, "x.h5");
}

TEST(Overrides, LineElementCount) {
  const Model m = parse_scene(wire_scene, "wire.yaml", {"lines[0].elements=7"});
  EXPECT_EQ(m.elements.size(), 7u);
  EXPECT_EQ(m.nodes.size(), 8u);
  EXPECT_NEAR(node_with_id(m, 3).position.x(), 10.0 / 7.0, 1e-15);
}

TEST(Overrides, SectionStiffnessChangesPrestrainFromTension) {
  const Model m = parse_scene(wire_scene, "wire.yaml", {"sections.cw.EA=2e7"});
  EXPECT_DOUBLE_EQ(std::get<CableProps>(*m.elements[0].props).EA, 2e7);
  EXPECT_DOUBLE_EQ(prestrain_of(m.elements[0]), 18000.0 / 2e7);
}

TEST(Overrides, CreateMissingMapsAndTakeYamlValues) {
  const Model m = parse_scene(
      wire_scene, "wire.yaml",
      {"analysis.newton.rtol=1e-6", "lines[0].distributed_load=[0, 0, -5]", "gravity=[0, 0, -10]"});
  EXPECT_DOUBLE_EQ(m.static_options.rtol, 1e-6);
  EXPECT_EQ(m.elements[3].distributed_load, Vec3(0, 0, -5));
  EXPECT_EQ(m.gravity, Vec3(0, 0, -10));
}

TEST(Overrides, LaterOverrideWins) {
  const Model m = parse_scene(wire_scene, "wire.yaml", {"output.file=a.h5", "output.file=b.h5"});
  EXPECT_EQ(m.output.file, "b.h5");
}

TEST(Overrides, SourceTextReproducesTheRun) {
  const Model m = parse_scene(wire_scene, "wire.yaml", {"lines[0].elements=7", "output.file=x.h5"});
  EXPECT_NE(m.source_text.find("# Scene wire.yaml with command-line overrides:"), std::string::npos)
      << m.source_text;
  EXPECT_NE(m.source_text.find("--set lines[0].elements=7"), std::string::npos);
  const Model again = parse_scene(m.source_text, "stored.yaml");
  EXPECT_EQ(again.elements.size(), 7u);
  EXPECT_EQ(again.output.file, "x.h5");
}

TEST(Overrides, WithoutOverridesSourceTextIsTheFile) {
  const Model m = parse_scene(wire_scene, "wire.yaml");
  EXPECT_EQ(m.source_text, wire_scene);
  EXPECT_EQ(m.source_file, "wire.yaml");
  const Model from_file = read_scene(mini_catenary);
  EXPECT_EQ(from_file.source_file, mini_catenary);
  EXPECT_NE(from_file.source_text.find("# A small but complete catenary bay"), std::string::npos);
}

TEST(Overrides, ValueFailingValidationNamesTheOverrideAndHasNoFileLine) {
  try {
    parse_scene(wire_scene, "wire.yaml", {"sections.cw.EA=-1"});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 0);
    EXPECT_EQ(e.where().key, "sections.cw.EA");
    EXPECT_NE(std::string(e.what()).find("--set 'sections.cw.EA=-1'"), std::string::npos)
        << e.what();
  }
}

TEST(Overrides, TildeRemovesAKeySoThatItsDefaultApplies) {
  const std::string dynamic = wire_scene + R"(analysis: {type: dynamic, duration: 1}
integrator: {type: hht, alpha: -0.2, dt: 0.01}
)";
  EXPECT_DOUBLE_EQ(parse_scene(dynamic, "wire.yaml").dynamic_options.integrator.alpha, -0.2);
  EXPECT_DOUBLE_EQ(
      parse_scene(dynamic, "wire.yaml", {"integrator.alpha=~"}).dynamic_options.integrator.alpha,
      IntegratorOptions{}.alpha);
  // Without the removal a Runge-Kutta type refuses HHT's alpha; with it the scene serves both.
  EXPECT_THROW(parse_scene(dynamic, "wire.yaml", {"integrator.type=radau"}), InputError);
  const Model radau =
      parse_scene(dynamic, "wire.yaml", {"integrator.type=radau", "integrator.alpha=~"});
  EXPECT_EQ(radau.dynamic_options.integrator.type, "radau_iia");
  // A key that is not there (or whose map is not) is nothing to remove.
  EXPECT_NO_THROW(parse_scene(dynamic, "wire.yaml", {"integrator.stages=~", "no.such.key=~"}));
}

TEST(Overrides, TildeDoesNotRemoveAListItem) {
  EXPECT_THROW(parse_scene(wire_scene, "wire.yaml", {"lines[0]=~"}), InputError);
}

// --- reference frames, supports, options ---------------------------------------------------

TEST(NodalFrames, CableTangentsBeamSectionAxesAndPlainNodes) {
  const Model m = read_scene(mini_catenary);
  EXPECT_EQ(node_with_id(m, 33).tangent, Vec3(1, 0, 0));   // messenger
  EXPECT_EQ(node_with_id(m, 20).tangent, Vec3(1, 0, 0));   // wire end
  EXPECT_EQ(node_with_id(m, 20).section_y, Vec3::Zero());  // no beam there
  const Node& arm_tip = node_with_id(m, 31);
  EXPECT_EQ(arm_tip.tangent, Vec3(0, 1, 0));
  EXPECT_EQ(arm_tip.section_y, Vec3(0, 0, 1));
  EXPECT_EQ(arm_tip.section_z, Vec3(1, 0, 0));  // tangent x section_y
}

TEST(NodalFrames, YAxisIsOrthogonalisedAgainstTheTangent) {
  const std::string text = R"(sections:
  b: {type: beam, EA: 1e9, GA_y: 1e8, GA_z: 1e8, GJ: 1e5, EI_y: 1e6, EI_z: 1e6,
      mass_per_length: 10, y_axis: [1, 1, 0]}
nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [4, 0, 0]}
lines:
  - {from: 1, to: 2, elements: 2, section: b}
supports:
  - {node: 1, fix: clamped}
)";
  const Model m = parse_scene(text, "beam.yaml");
  for (const Node& n : m.nodes) {
    EXPECT_NEAR((n.section_y - Vec3(0, 1, 0)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((n.section_z - Vec3(0, 0, 1)).norm(), 0.0, 1e-15);
  }
}

TEST(Supports, MasksFollowTheNodalLayout) {
  const Model m = read_scene(mini_catenary);
  ASSERT_EQ(m.supports.size(), 4u);
  EXPECT_EQ(m.supports[0].fixed_mask, 0b111u);    // pinned
  EXPECT_EQ(m.supports[2].fixed_mask, 0b10111u);  // [x, y, z, rx_y]
  EXPECT_FALSE(m.supports[2].slope_direction);    // a list fixes exactly its components
  EXPECT_EQ(m.supports[3].fixed_mask, 0xFC7u);    // clamped beam node: r, r_y, r_z ...
  EXPECT_TRUE(m.supports[3].slope_direction);     // ... and r_x's direction
  EXPECT_EQ(m.supports[3].node, index_of_node(m, 30));
  const Model wire = parse_scene(wire_scene, "wire.yaml", {"supports[0].fix=clamped"});
  EXPECT_EQ(wire.supports[0].fixed_mask, 0b111u);  // clamped cable node: r ...
  EXPECT_TRUE(wire.supports[0].slope_direction);   // ... and r_x's direction
  const Model whole =
      parse_scene(wire_scene, "wire.yaml", {"supports[0].fix=[x, y, z, rx_x, rx_y, rx_z]"});
  EXPECT_EQ(whole.supports[0].fixed_mask, 0b111111u);  // the whole slope, by listing it
  EXPECT_FALSE(whole.supports[0].slope_direction);
}

TEST(Options, ReadFromTheScene) {
  const Model m = read_scene(mini_catenary);
  EXPECT_DOUBLE_EQ(m.static_options.initial_load_step, 0.5);
  EXPECT_DOUBLE_EQ(m.static_options.min_load_step, 0.001);
  EXPECT_EQ(m.static_options.max_load_steps, 80);
  EXPECT_DOUBLE_EQ(m.static_options.rtol, 1e-9);
  EXPECT_DOUBLE_EQ(m.static_options.atol, 1e-7);
  EXPECT_EQ(m.static_options.max_newton_iterations, 25);
  EXPECT_EQ(m.output.file, "mini.h5");
  ASSERT_EQ(m.point_masses.size(), 1u);
  EXPECT_DOUBLE_EQ(m.point_masses[0].mass, 2.5);
  EXPECT_EQ(m.elastic_supports[0].stiffness, Vec3(1e5, 0, 0));
  EXPECT_EQ(m.elastic_supports[0].damping, Vec3::Zero());
}

TEST(Options, DefaultsWhenAbsent) {
  const Model m = parse_scene(wire_scene, "wire.yaml");
  const StaticOptions defaults;
  EXPECT_EQ(m.static_options.initial_load_step, defaults.initial_load_step);
  EXPECT_EQ(m.static_options.max_newton_iterations, defaults.max_newton_iterations);
  EXPECT_EQ(m.output.file, OutputOptions{}.file);
  EXPECT_EQ(m.gravity, Vec3(0, 0, -9.81));
  EXPECT_EQ(m.name, "");
}

}  // namespace

// --- Rayleigh damping ---------------------------------------------------------------------

TEST(Rayleigh, RatioAtTwoFrequenciesGivesThatRatioAtBoth) {
  std::string text = wire_scene;
  text.replace(text.find("mass_per_length: 1.35}"), 22,
               "mass_per_length: 1.35, rayleigh: {ratio: 0.005, frequencies: [1, 20]}}");
  const Model m = parse_scene(text, "rayleigh.yaml");
  const catena::model::Rayleigh r = std::get<CableProps>(*m.elements.front().props).rayleigh;
  for (double f : {1.0, 20.0}) {
    const double w = 2.0 * std::numbers::pi * f;
    EXPECT_NEAR(r.mass / (2.0 * w) + r.stiffness * w / 2.0, 0.005, 1e-15);
  }
  EXPECT_TRUE(r.active());
}

TEST(Rayleigh, CoefficientsAsGivenAndAbsentMeansNone) {
  std::string text = wire_scene;
  text.replace(text.find("mass_per_length: 1.35}"), 22,
               "mass_per_length: 1.35, rayleigh: {stiffness: 2.0e-4}}");
  const catena::model::Rayleigh r =
      std::get<CableProps>(*parse_scene(text, "r.yaml").elements.front().props).rayleigh;
  EXPECT_EQ(r.mass, 0.0);
  EXPECT_EQ(r.stiffness, 2.0e-4);
  EXPECT_FALSE(std::get<CableProps>(*parse_scene(wire_scene, "w.yaml").elements.front().props)
                   .rayleigh.active());
}

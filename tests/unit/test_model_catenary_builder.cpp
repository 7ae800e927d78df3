// The scene's `catenary` becomes nodes, cables, dropper bars, masses, supports, the
// contact-wire path and Model::catenary: counts, dropper positions, element sizes, path
// continuity, the 2D and 3D support schemes, the stagger joints, ids, the evaluation
// range and the stitch wires (nodes, which droppers they carry, clamps, hinges). The base scene is
// tests/data/good_scenes/catenary_3span.yaml, varied by --set; malformed files are
// tests/data/bad_scenes/catenary_*.yaml (test_model_scene_errors).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "catena/model/scene_reader.hpp"
#include "input_errors.hpp"

namespace {

namespace fs = std::filesystem;
using namespace catena;
using namespace catena::model;

const std::string scene_file =
    (fs::path(CATENA_TEST_DATA) / "good_scenes" / "catenary_3span.yaml").string();

// The base scene's numbers: 3 spans of 60 m, 9 droppers per span, 1 m elements.
constexpr int n_spans = 3;
constexpr int droppers_per_span = 9;
const std::vector<double> offsets{5.0, 10.5, 17.0, 23.5, 30.0, 36.5, 43.0, 49.5, 55.0};
// Elements per span: each gap between stations cut into the fewest elements of <= 1 m.
constexpr int elements_per_span = 5 + 6 + 7 * 6 + 6 + 5;

constexpr unsigned fix_y = 1u << 1, fix_slope_y = 1u << 4, fix_xyz = 0b111u;

long long count_kind(const Model& m, std::size_t kind) {
  return std::count_if(m.elements.begin(), m.elements.end(),
                       [&](const ElementDesc& e) { return e.props->index() == kind; });
}

unsigned mask_of(const Model& m, int node) {
  unsigned mask = 0;
  for (const Support& s : m.supports)
    if (s.node == node) mask |= s.fixed_mask;
  return mask;
}

// The base scene without its `presag` line (design sags and a pre-sag exclude each other).
std::string scene_without_presag() {
  std::ifstream in(scene_file);
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  const std::string line = "  presag: 0.055\n";
  const std::size_t at = scene.find(line);
  EXPECT_NE(at, std::string::npos);
  return scene.erase(at, line.size());
}

double element_length(const Model& m, int e) {
  const ElementDesc& element = m.elements[e];
  return (m.nodes[element.nodes[1]].position - m.nodes[element.nodes[0]].position).norm();
}

TEST(CatenaryBuilder, CountsOfThePlanarCatenary) {
  const Model m = read_scene(scene_file);
  ASSERT_TRUE(m.catenary.has_value());
  const CatenaryLayout& c = *m.catenary;
  const int wire_elements = n_spans * elements_per_span;
  EXPECT_EQ(m.nodes.size(), 2u * (wire_elements + 1));
  EXPECT_EQ(count_kind(m, 0), 2 * wire_elements);            // cables
  EXPECT_EQ(count_kind(m, 2), n_spans * droppers_per_span);  // dropper bars
  EXPECT_EQ(count_kind(m, 3), 0);                            // no joints in 2D
  EXPECT_EQ(c.contact_wire.elements.size(), static_cast<std::size_t>(wire_elements));
  EXPECT_EQ(c.messenger.elements.size(), static_cast<std::size_t>(wire_elements));
  EXPECT_EQ(c.droppers.size(), static_cast<std::size_t>(n_spans * droppers_per_span));
  EXPECT_EQ(c.registrations.size(), static_cast<std::size_t>(n_spans - 1));
  // Elastic supports: a steady arm and a messenger support at each intermediate support.
  EXPECT_EQ(m.elastic_supports.size(), 2u * (n_spans - 1));
  // Point masses: a clamp at both ends of every dropper, a steady arm per registration.
  EXPECT_EQ(m.point_masses.size(), 2u * c.droppers.size() + c.registrations.size());
  // The steady arms' preloads, sized later by shape finding.
  ASSERT_EQ(m.nodal_loads.size(), c.registrations.size());
  for (const CatenaryRegistration& r : c.registrations) {
    ASSERT_GE(r.load, 0);
    EXPECT_EQ(m.nodal_loads[r.load].node, r.node);
    EXPECT_EQ(m.nodal_loads[r.load].force, Vec3::Zero());
  }
  EXPECT_EQ(c.dimension, 2);
  EXPECT_EQ(c.support_x, (std::vector<double>{0.0, 60.0, 120.0, 180.0}));
  EXPECT_EQ(c.dropper_offsets, offsets);
}

TEST(CatenaryBuilder, IdsFollowContactWireThenMessengerInXOrder) {
  const Model m = read_scene(scene_file);
  const std::size_t per_wire = m.nodes.size() / 2;
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    EXPECT_EQ(m.nodes[i].id, static_cast<std::int64_t>(i + 1));
  for (std::size_t i = 1; i < per_wire; ++i) {
    EXPECT_GT(m.nodes[i].position.x(), m.nodes[i - 1].position.x());
    EXPECT_EQ(m.nodes[i].position.z(), 0.0);
    EXPECT_EQ(m.nodes[per_wire + i].position.z(), 1.2);
  }
  for (std::size_t e = 0; e < m.elements.size(); ++e)
    EXPECT_EQ(m.elements[e].id, static_cast<std::int64_t>(e + 1));
}

TEST(CatenaryBuilder, DroppersHangFromTheMessengerAtTheirPositions) {
  const Model m = read_scene(scene_file);
  const CatenaryLayout& c = *m.catenary;
  for (std::size_t i = 0; i < c.droppers.size(); ++i) {
    const CatenaryDropper& d = c.droppers[i];
    const int span = static_cast<int>(i) / droppers_per_span;
    const double s = offsets[i % droppers_per_span];
    EXPECT_EQ(d.span, span);
    const Vec3 bottom = m.nodes[d.contact_node].position;
    const Vec3 top = m.nodes[d.upper_node].position;
    EXPECT_NEAR(bottom.x(), 60.0 * span + s, 1e-12);
    EXPECT_NEAR(top.x(), bottom.x(), 1e-12);
    EXPECT_EQ(bottom.z(), 0.0);
    EXPECT_EQ(top.z(), 1.2);
    // The design height on the pre-sag parabola through 0 at the supports.
    EXPECT_NEAR(d.design_z, -4.0 * 0.055 * (s / 60.0) * (1.0 - s / 60.0), 1e-15);
    EXPECT_EQ(d.stiffness, 1.0e5);
    const ElementDesc& bar = m.elements[d.element];
    ASSERT_TRUE(std::holds_alternative<BarProps>(*bar.props));
    const BarProps& props = std::get<BarProps>(*bar.props);
    EXPECT_TRUE(props.tension_only);
    EXPECT_EQ(props.unstretched_length, 0.0);  // the mesh length until shape finding
    EXPECT_DOUBLE_EQ(props.EA, 1.0e5 * 1.2);   // stiffness × that length
    EXPECT_EQ(bar.set, "droppers");
    EXPECT_EQ(bar.nodes, (std::array<int, 2>{d.upper_node, d.contact_node}));
    EXPECT_EQ(d.stitch, -1);  // no stitch wires in the base scene
  }
  EXPECT_TRUE(c.stitch_wires.empty());
}

TEST(CatenaryBuilder, WiresAreSplitIntoElementsOfAtMostTheElementLength) {
  const Model m = read_scene(scene_file);
  const CatenaryLayout& c = *m.catenary;
  for (const CatenaryWire* wire : {&c.contact_wire, &c.messenger}) {
    double total = 0.0;
    for (const int e : wire->elements) {
      EXPECT_LE(element_length(m, e), 1.0 + 1e-12);
      total += element_length(m, e);
      const CableProps& cable = std::get<CableProps>(*m.elements[e].props);
      EXPECT_DOUBLE_EQ(cable.prestrain, wire->tension / cable.EA);
      EXPECT_EQ(m.elements[e].set, wire->name);
    }
    EXPECT_NEAR(total, 180.0, 1e-9);
  }
  EXPECT_EQ(c.contact_wire.tension, 20000.0);
  EXPECT_EQ(c.messenger.tension, 16000.0);
}

TEST(CatenaryBuilder, ContactWirePathIsContinuousInXOrder) {
  const Model m = read_scene(scene_file);
  ASSERT_EQ(m.paths.size(), 1u);
  const ElementPath& path = m.paths[0];
  EXPECT_EQ(path.name, "contact_wire");
  EXPECT_EQ(path.elements, m.catenary->contact_wire.elements);
  EXPECT_EQ(m.nodes[m.elements[path.elements.front()].nodes[0]].position, Vec3(0, 0, 0));
  EXPECT_EQ(m.nodes[m.elements[path.elements.back()].nodes[1]].position, Vec3(180, 0, 0));
  for (std::size_t k = 1; k < path.elements.size(); ++k)
    EXPECT_EQ(m.elements[path.elements[k]].nodes[0], m.elements[path.elements[k - 1]].nodes[1]);
  // Registration nodes: the contact wire at every support; evaluation: span 2.
  ASSERT_EQ(m.registration_nodes.size(), static_cast<std::size_t>(n_spans + 1));
  for (int j = 0; j <= n_spans; ++j)
    EXPECT_EQ(m.nodes[m.registration_nodes[j]].position, Vec3(60.0 * j, 0, 0));
  EXPECT_DOUBLE_EQ(m.evaluation_start, 60.0);
  EXPECT_DOUBLE_EQ(m.evaluation_end, 120.0);
}

TEST(CatenaryBuilder, PlanarCatenaryHoldsEveryOutOfPlaneDof) {
  const Model m = read_scene(scene_file);
  const CatenaryLayout& c = *m.catenary;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    const unsigned mask = mask_of(m, static_cast<int>(n));
    EXPECT_EQ(mask & (fix_y | fix_slope_y), fix_y | fix_slope_y) << "node " << m.nodes[n].id;
  }
  // Anchored ends; free x and z at the intermediate supports (elastic in z).
  const int first = m.registration_nodes.front(), last = m.registration_nodes.back();
  EXPECT_EQ(mask_of(m, first) & fix_xyz, fix_xyz);
  EXPECT_EQ(mask_of(m, last) & fix_xyz, fix_xyz);
  for (const CatenaryRegistration& r : c.registrations)
    EXPECT_EQ(mask_of(m, r.node) & fix_xyz, fix_y);
  for (const ElasticSupport& s : m.elastic_supports) {
    EXPECT_EQ(s.stiffness.x(), 0.0);
    EXPECT_EQ(s.stiffness.y(), 0.0);
    EXPECT_TRUE(s.stiffness.z() == 300.0 || s.stiffness.z() == 50000.0);
  }
}

TEST(CatenaryBuilder, SpatialCatenaryWithStaggerJoinsTheSpansAtTheSupports) {
  const Model m = read_scene(scene_file, {"catenary.dimension=3", "catenary.stagger=0.3"});
  const CatenaryLayout& c = *m.catenary;
  const int wire_elements = n_spans * elements_per_span;
  // Each wire gets a second node at each intermediate support, joined by a spring.
  EXPECT_EQ(m.nodes.size(), 2u * (wire_elements + 1 + (n_spans - 1)));
  EXPECT_EQ(count_kind(m, 3), 2 * (n_spans - 1));
  // Only the anchors, the steady arms (lateral) and the messenger supports (lateral) are
  // held: no out-of-plane restraint elsewhere.
  EXPECT_EQ(m.supports.size(), 4u + 2u * (n_spans - 1));
  for (const CatenaryRegistration& r : c.registrations) EXPECT_EQ(mask_of(m, r.node), fix_y);
  // The wire zig-zags ±0.3 m, starting at +0.3 m.
  for (int j = 0; j <= n_spans; ++j)
    EXPECT_EQ(m.nodes[m.registration_nodes[j]].position,
              Vec3(60.0 * j, j % 2 == 0 ? 0.3 : -0.3, 0));
  // The path: consecutive elements share a node, or meet at coincident joint nodes.
  const ElementPath& path = m.paths[0];
  int n_joints = 0;
  for (std::size_t k = 1; k < path.elements.size(); ++k) {
    const int end = m.elements[path.elements[k - 1]].nodes[1];
    const int start = m.elements[path.elements[k]].nodes[0];
    if (end == start) continue;
    ++n_joints;
    EXPECT_EQ(m.nodes[end].position, m.nodes[start].position);
  }
  EXPECT_EQ(n_joints, n_spans - 1);
  // Droppers stay vertical: both wires are staggered alike.
  for (const CatenaryDropper& d : c.droppers) {
    const Vec3 gap = m.nodes[d.upper_node].position - m.nodes[d.contact_node].position;
    EXPECT_NEAR((gap - Vec3(0, 0, 1.2)).norm(), 0.0, 1e-12);
  }
  EXPECT_EQ(m.catenary->dimension, 3);
}

TEST(CatenaryBuilder, AcceptanceRangesAreTheScenesDeclaration) {
  EXPECT_EQ(read_scene(scene_file, {}).acceptance, "");
  const Model m = read_scene(scene_file, {"catenary.acceptance=en50318"});
  EXPECT_EQ(m.acceptance, "en50318");
}

TEST(CatenaryBuilder, SpatialCatenaryWithoutStaggerSharesTheSupportNodes) {
  const Model m = read_scene(scene_file, {"catenary.dimension=3"});
  EXPECT_EQ(m.nodes.size(), 2u * (n_spans * elements_per_span + 1));
  EXPECT_EQ(count_kind(m, 3), 0);
  for (const Support& s : m.supports) EXPECT_EQ(s.fixed_mask & fix_slope_y, 0u);
}

TEST(CatenaryBuilder, PerSpanPositionsSpanLengthsAndFixedMessengerSupports) {
  const Model m = parse_scene(R"(
catenary:
  span_lengths: [40, 50]
  system_height: 1.0
  element_length: 2.0
  evaluation_spans: [1, 2]
  contact_wire: {EA: 1.8e7, EI: 195, mass_per_length: 1.35, tension: 20000}
  messenger: {EA: 1.2e7, EI: 131.7, mass_per_length: 1.07, tension: 16000}
  droppers: {positions: [[10, 30], [5, 25, 45]], EA: 2.0e5, tension_only: false}
  steady_arms: {stiffness: 300, hold_design_height: false}
  messenger_supports: {fixed: true}
)",
                              "per_span.yaml");
  const CatenaryLayout& c = *m.catenary;
  EXPECT_EQ(c.dimension, 3);  // the default
  EXPECT_EQ(c.support_x, (std::vector<double>{0.0, 40.0, 90.0}));
  EXPECT_TRUE(c.dropper_offsets.empty());  // they differ per span
  std::vector<double> x;
  for (const CatenaryDropper& d : c.droppers) {
    x.push_back(m.nodes[d.contact_node].position.x());
    const BarProps& bar = std::get<BarProps>(*m.elements[d.element].props);
    EXPECT_EQ(bar.EA, 2.0e5);
    EXPECT_FALSE(bar.tension_only);
    EXPECT_EQ(d.stiffness, 0.0);
  }
  EXPECT_EQ(x, (std::vector<double>{10, 30, 45, 65, 85}));
  // A fixed messenger support holds y and z; only the steady arm is elastic, and its
  // height is not held: no preload.
  EXPECT_EQ(m.elastic_supports.size(), 1u);
  EXPECT_TRUE(m.nodal_loads.empty());
  ASSERT_EQ(c.registrations.size(), 1u);
  EXPECT_EQ(c.registrations[0].load, -1);
  EXPECT_DOUBLE_EQ(m.evaluation_start, 0.0);
  EXPECT_DOUBLE_EQ(m.evaluation_end, 90.0);
}

TEST(CatenaryBuilder, NodesAndElementsNumberAfterTheScenesOwn) {
  const Model m = read_scene(
      scene_file, {"sections={s: {type: spring, stiffness: 1}}",
                   "nodes=[{id: 100, position: [0, 5, 0]}, {id: 7, position: [1, 5, 0]}]",
                   "elements=[{id: 40, section: s, nodes: [100, 7]}]",
                   "supports=[{node: 100, fix: pinned}, {node: 7, fix: pinned}]"});
  EXPECT_EQ(m.nodes[2].id, 101);
  EXPECT_EQ(m.elements[0].id, 40);
  EXPECT_EQ(m.elements[1].id, 41);
  EXPECT_EQ(m.catenary->contact_wire.elements.front(), 1);
}

// Stitch wires of 18 m at the two intermediate supports (x = 60, 120 m) of the base scene:
// clamps at 51, 69, 111 and 129 m; the droppers at 55 m of spans 1 and 2 and at 5 m of
// spans 2 and 3 lie between clamps.
const std::string stitch =
    "catenary.stitch={length: 18, tension: 2800, EA: 3.5e6, EI: 10, mass_per_length: 0.31}";
const std::vector<double> clamp_x{51.0, 69.0, 111.0, 129.0};

// The elements of a wire between stations, each gap cut into the fewest of <= 1 m.
int elements_between(const std::vector<double>& stations) {
  int n = 0;
  for (std::size_t k = 1; k < stations.size(); ++k)
    n += static_cast<int>(std::ceil(stations[k] - stations[k - 1] - 1e-12));
  return n;
}

TEST(CatenaryBuilder, StitchWiresCarryTheDroppersBetweenTheirClamps) {
  const Model m = read_scene(scene_file, {stitch});
  const CatenaryLayout& c = *m.catenary;
  ASSERT_EQ(c.stitch_wires.size(), 2u);
  const int wire_elements = n_spans * elements_per_span;
  // The messenger gets a station at each clamp: 1.5 + 4 m instead of 5.5 m around 51 m
  // (and alike at the others); here that keeps its element count.
  const int messenger_elements =
      elements_between({0, 5, 10.5, 17, 23.5, 30, 36.5, 43, 49.5, 51, 55, 60}) +
      elements_between({0, 5, 9, 10.5, 17, 23.5, 30, 36.5, 43, 49.5, 51, 55, 60}) +
      elements_between({0, 5, 9, 10.5, 17, 23.5, 30, 36.5, 43, 49.5, 55, 60});
  const int stitch_elements = elements_between({51, 55, 65, 69});  // clamps and droppers
  EXPECT_EQ(c.messenger.elements.size(), static_cast<std::size_t>(messenger_elements));
  EXPECT_EQ(m.nodes.size(), static_cast<std::size_t>(wire_elements + 1 + messenger_elements + 1 +
                                                     2 * (stitch_elements + 1)));
  EXPECT_EQ(count_kind(m, 0), wire_elements + messenger_elements + 2 * stitch_elements);
  EXPECT_EQ(count_kind(m, 2), n_spans * droppers_per_span);  // the same droppers
  EXPECT_EQ(count_kind(m, 3), 4);                            // a hinge at each stitch end

  // Droppers strictly between the clamps hang from the stitch wire, the others from the
  // messenger; every dropper stays vertical (2D: the stitch wire lies on the messenger).
  std::vector<double> on_stitch;
  for (const CatenaryDropper& d : c.droppers) {
    const Vec3 bottom = m.nodes[d.contact_node].position;
    const Vec3 top = m.nodes[d.upper_node].position;
    EXPECT_NEAR((top - bottom - Vec3(0, 0, 1.2)).norm(), 0.0, 1e-12);
    if (d.stitch < 0) continue;
    on_stitch.push_back(bottom.x());
    const CatenaryStitch& s = c.stitch_wires[d.stitch];
    const double support = c.support_x[s.support];
    EXPECT_LT(std::abs(bottom.x() - support), 9.0);
    // The upper node is a node of that stitch wire's cables.
    bool found = false;
    for (const int e : s.wire.elements)
      for (const int n : m.elements[e].nodes) found = found || n == d.upper_node;
    EXPECT_TRUE(found) << "dropper at x = " << bottom.x();
  }
  EXPECT_EQ(on_stitch, (std::vector<double>{55, 65, 115, 125}));
  EXPECT_EQ(c.droppers[8].stitch, 0);
  EXPECT_EQ(c.droppers[9].stitch, 0);
  EXPECT_EQ(c.droppers[17].stitch, 1);
  EXPECT_EQ(c.droppers[18].stitch, 1);

  for (std::size_t k = 0; k < c.stitch_wires.size(); ++k) {
    const CatenaryStitch& s = c.stitch_wires[k];
    EXPECT_EQ(s.support, static_cast<int>(k) + 1);
    EXPECT_EQ(s.wire.tension, 2800.0);
    EXPECT_EQ(s.wire.elements.size(), static_cast<std::size_t>(stitch_elements));
    for (const int e : s.wire.elements) {
      EXPECT_EQ(m.elements[e].set, "stitch_wires");
      const CableProps& cable = std::get<CableProps>(*m.elements[e].props);
      EXPECT_DOUBLE_EQ(cable.prestrain, 2800.0 / 3.5e6);
      EXPECT_EQ(cable.mass_per_length, 0.31);
      EXPECT_LE(element_length(m, e), 1.0 + 1e-12);
    }
    // The clamps are messenger nodes at x_support -/+ 9 m; the stitch wire's end nodes
    // coincide with them and are joined to them by springs.
    const int first = m.elements[s.wire.elements.front()].nodes[0];
    const int last = m.elements[s.wire.elements.back()].nodes[1];
    EXPECT_EQ(m.nodes[s.clamp_nodes[0]].position, Vec3(clamp_x[2 * k], 0, 1.2));
    EXPECT_EQ(m.nodes[s.clamp_nodes[1]].position, Vec3(clamp_x[2 * k + 1], 0, 1.2));
    EXPECT_EQ(m.nodes[first].position, m.nodes[s.clamp_nodes[0]].position);
    EXPECT_EQ(m.nodes[last].position, m.nodes[s.clamp_nodes[1]].position);
    bool on_messenger = false;
    for (const int e : c.messenger.elements)
      on_messenger = on_messenger || m.elements[e].nodes[0] == s.clamp_nodes[0];
    EXPECT_TRUE(on_messenger);
    std::vector<std::array<int, 2>> joints;
    for (const ElementDesc& e : m.elements)
      if (e.set == "stitch_joints") joints.push_back(e.nodes);
    EXPECT_NE(std::find(joints.begin(), joints.end(), std::array<int, 2>{s.clamp_nodes[0], first}),
              joints.end());
    EXPECT_NE(std::find(joints.begin(), joints.end(), std::array<int, 2>{last, s.clamp_nodes[1]}),
              joints.end());
    // 2D: every stitch node held out of plane, none held otherwise (not at the support).
    for (const int e : s.wire.elements)
      for (const int n : m.elements[e].nodes)
        EXPECT_EQ(mask_of(m, n), fix_y | fix_slope_y) << "node " << m.nodes[n].id;
  }
  // Node ids: contact wire, messenger, then the stitch wires, each in x order.
  const int first_stitch_node = m.elements[c.stitch_wires[0].wire.elements.front()].nodes[0];
  EXPECT_EQ(first_stitch_node, wire_elements + 1 + messenger_elements + 1);
  EXPECT_EQ(m.nodes[first_stitch_node].id, first_stitch_node + 1);
}

// 3D with stagger: the messenger kinks at the support, the stitch wire runs straight
// between its clamps, which lie on the messenger's segments on either side; its droppers
// are then slightly inclined (the contact wire follows the messenger's zig-zag).
TEST(CatenaryBuilder, StaggeredStitchWireIsStraightBetweenClampsOnTheMessenger) {
  const Model m = read_scene(scene_file, {stitch, "catenary.dimension=3", "catenary.stagger=0.3"});
  const CatenaryLayout& c = *m.catenary;
  ASSERT_EQ(c.stitch_wires.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const CatenaryStitch& s = c.stitch_wires[k];
    // Messenger at the supports: +0.3 (x = 0), -0.3 (60), +0.3 (120), -0.3 (180), linear
    // in between: 9 m from a support y is 0.3 - 0.6 * 9/60 = 0.21 from the centre line.
    const double y = k == 0 ? -0.21 : 0.21;
    for (const int clamp : s.clamp_nodes)
      EXPECT_NEAR((m.nodes[clamp].position - Vec3(m.nodes[clamp].position.x(), y, 1.2)).norm(), 0.0,
                  1e-12);
    for (const int e : s.wire.elements)
      for (const int n : m.elements[e].nodes) {
        EXPECT_NEAR(m.nodes[n].position.y(), y, 1e-12);
        EXPECT_EQ(mask_of(m, n), 0u);  // held by its hinges and its tension only
      }
  }
  // The messenger supports still hold the messenger: its node at each intermediate
  // support is held in y.
  for (const double x : {60.0, 120.0}) {
    bool held = false;
    for (const int e : c.messenger.elements)
      for (const int n : m.elements[e].nodes)
        if (std::abs(m.nodes[n].position.x() - x) < 1e-9)
          held = held || (mask_of(m, n) & fix_y) != 0u;
    EXPECT_TRUE(held) << "support at x = " << x;
  }
  for (const CatenaryDropper& d : c.droppers) {
    if (d.stitch < 0) continue;
    EXPECT_NEAR(m.nodes[d.upper_node].position.x(), m.nodes[d.contact_node].position.x(), 1e-12);
  }
}

// A dropper exactly on a clamp point hangs from the messenger (only droppers strictly
// between the clamps hang from the stitch wire), and the messenger's station there is one.
TEST(CatenaryBuilder, DropperOnAClampPointHangsFromTheMessenger) {
  const Model m = read_scene(
      scene_file,
      {"catenary.stitch={length: 10, tension: 2800, EA: 3.5e6, EI: 10, mass_per_length: 0.31}"});
  const CatenaryLayout& c = *m.catenary;
  for (const CatenaryDropper& d : c.droppers) {
    const double x = m.nodes[d.contact_node].position.x();
    const bool on_clamp = std::abs(std::remainder(x, 60.0)) == 5.0;
    if (on_clamp) {
      EXPECT_EQ(d.stitch, -1) << "x = " << x;
      EXPECT_EQ(m.nodes[d.upper_node].position, Vec3(x, 0, 1.2));
    }
  }
  // No dropper strictly inside a 10 m stitch: the stitch wires carry none.
  EXPECT_TRUE(std::all_of(c.droppers.begin(), c.droppers.end(),
                          [](const CatenaryDropper& d) { return d.stitch < 0; }));
  EXPECT_EQ(c.stitch_wires[0].clamp_nodes[0], c.droppers[8].upper_node);
}

// In the first and last span only one stitch wire reaches in, so there a clamp may be up
// to the span length from its support: [20, 60] m accepts stitch wires shorter than 40 m.
TEST(CatenaryBuilder, StitchLengthIsLimitedByTheSpansAround) {
  const std::string scene = R"(
catenary:
  span_lengths: [20, 60]
  system_height: 1.2
  element_length: 1.0
  contact_wire: {EA: 1.8e7, EI: 195, mass_per_length: 1.35, tension: 20000}
  messenger: {EA: 1.2e7, EI: 131.7, mass_per_length: 1.07, tension: 16000}
  droppers: {positions: [[0.25, 10], [5, 30]], stiffness: 1.0e5}
  steady_arms: {stiffness: 300}
  messenger_supports: {stiffness: 50000}
  stitch: {length: 39, tension: 2800, EA: 3.5e6, EI: 10, mass_per_length: 0.31}
)";
  const Model m = parse_scene(scene, "short_first_span.yaml");
  const CatenaryStitch& s = m.catenary->stitch_wires.at(0);
  EXPECT_DOUBLE_EQ(m.nodes[s.clamp_nodes[0]].position.x(), 0.5);
  EXPECT_DOUBLE_EQ(m.nodes[s.clamp_nodes[1]].position.x(), 39.5);
  // The dropper at 0.25 m is outside the stitch, the ones at 10 m and 25 m inside it.
  std::vector<int> stitch_of;
  for (const CatenaryDropper& d : m.catenary->droppers) stitch_of.push_back(d.stitch);
  EXPECT_EQ(stitch_of, (std::vector<int>{-1, 0, 0, -1}));
  const std::string message = test::input_error_message(
      [&] { parse_scene(scene, "short_first_span.yaml", {"catenary.stitch.length=40"}); });
  EXPECT_NE(message.find("catenary.stitch.length"), std::string::npos) << message;
  EXPECT_NE(message.find("40 m does not fit: expected < 40 m"), std::string::npos) << message;
}

TEST(CatenaryBuilder, BadInputNamesTheKeyAndTheAcceptedRange) {
  const std::vector<test::InputErrorCase> cases{
      {{"catenary.droppers.EA=1e5"}, {"catenary.droppers", "both 'EA' and 'stiffness'"}},
      {{"catenary.droppers.positions=[5, 3]"},
       {"catenary.droppers.positions[1]", "must increase along the span"}},
      {{"catenary.droppers.positions=[[5], [5]]"},
       {"catenary.droppers.positions", "needs 3 lists (one per span), got 2"}},
      {{"catenary.span_lengths=[60]"}, {"catenary.span_lengths", "not both"}},
      {{"catenary.spans=0"}, {"catenary.spans", "expected an integer in [1, 10000]"}},
      {{"catenary.presag=1.2"}, {"catenary.presag", "in [0, 1.2) [m]"}},
      {{"catenary.presag_between=masts"},
       {"catenary.presag_between", "unknown value 'masts'", "accepted: supports"}},
      {{"catenary.droppers.positions=[[30], [5, 55], [5, 55]]",
        "catenary.presag_between=end_droppers"},
       {"catenary.presag_between", "span 1 has one dropper", "needs two"}},
      {{"catenary.droppers.design_sags=[0, 0.01]"},
       {"catenary.presag", "remove this key (the pre-sag parabola) or the design sags"}},
      {{"catenary.droppers.clamp_mass={contact_wire: 0.1}"},
       {"catenary.droppers.clamp_mass.messenger", "missing required key"}},
      {{"catenary.droppers.clamp_mass={contact: 0.1, messenger: 0.2}"},
       {"catenary.droppers.clamp_mass.contact", "unknown key"}},
      {{"catenary.element_length=0"}, {"catenary.element_length", "> 0 [m]"}},
      {{"catenary.dimension=4"}, {"catenary.dimension", "in [2, 3]"}},
      {{"catenary.contact_wire.tension=-1"}, {"catenary.contact_wire.tension", "> 0 [N]"}},
      {{"catenary.messenger.EI="}, {"catenary.messenger.EI", "no value given"}},
      {{"catenary.steady_arms="}, {"catenary.steady_arms", "no value given"}},
      {{"catenary.messenger_supports={fixed: true, stiffness: 5}"},
       {"catenary.messenger_supports.stiffness", "a fixed messenger support has no stiffness"}},
      {{"catenary.evaluation_spans=[3, 2]"}, {"catenary.evaluation_spans[1]", "comes before"}},
      {{"catenary.acceptance=en50367"},
       {"catenary.acceptance", "unknown acceptance ranges 'en50367'", "accepted: en50318"}},
      {{"catenary.evaluation_spans=~", "catenary.acceptance=en50318"},
       {"catenary.acceptance", "give evaluation_spans", "[5, 6]"}},
      {{"catenary.droppers.spacing=5"}, {"catenary.droppers.spacing", "unknown key"}},
      {{"catenary.droppers.model=rope"}, {"catenary.droppers.model", "accepted: bar"}},
      {{"catenary.droppers.EI=0.02"}, {"catenary.droppers.EI", "cable droppers only"}},
      {{"catenary.droppers.elements=2"}, {"catenary.droppers.elements", "cable droppers only"}},
      {{"catenary.droppers.model=cable", "catenary.droppers.mass_per_length=0.1"},
       {"catenary.droppers.EI", "missing required key"}},
      {{"catenary.droppers.model=cable", "catenary.droppers.EI=0.02"},
       {"catenary.droppers.mass_per_length", "need a mass per length > 0"}},
      {{"catenary.droppers.model=cable", "catenary.droppers.EI=0.02",
        "catenary.droppers.mass_per_length=0.1", "catenary.droppers.elements=0"},
       {"catenary.droppers.elements", "in [1, 100]"}},
      {{"gravity=[0, -9.81, 0]"}, {"catenary", "gravity must point along -z"}},
      // Stitch wires: every key, with the stitch of the tests above as the base.
      {{"catenary.stitch=true"}, {"catenary.stitch", "expected the stitch wires {length"}},
      {{stitch, "catenary.stitch.length=0"}, {"catenary.stitch.length", "> 0 [m]"}},
      {{stitch, "catenary.stitch.length=60"},
       {"catenary.stitch.length", "60 m does not fit: expected < 60 m", "adjacent span"}},
      {{stitch, "catenary.spans=1"}, {"catenary.stitch", "a single span has none"}},
      {{stitch, "catenary.stitch.length="}, {"catenary.stitch.length", "no value given"}},
      {{stitch, "catenary.stitch.tension=0"}, {"catenary.stitch.tension", "> 0 [N]"}},
      {{stitch, "catenary.stitch.EA=-3"}, {"catenary.stitch.EA", "> 0 [N]"}},
      {{stitch, "catenary.stitch.EI=0"}, {"catenary.stitch.EI", "> 0 [N*m^2]"}},
      {{stitch, "catenary.stitch.mass_per_length=0"},
       {"catenary.stitch.mass_per_length", "> 0 [kg/m]"}},
      {{stitch, "catenary.stitch.damping_time=-1"}, {"catenary.stitch.damping_time", ">= 0 [s]"}},
      {{stitch, "catenary.stitch.rayleigh={alpha: 1}"}, {"catenary.stitch.rayleigh"}},
      {{stitch, "catenary.stitch.lenght=18"}, {"catenary.stitch.lenght", "unknown key"}},
  };
  test::expect_input_errors([](const auto& o) { read_scene(scene_file, o); }, "catenary_3span.yaml",
                            cases);
  const std::vector<test::InputErrorCase> sag_cases{
      {{"catenary.droppers.design_sags=[0, 0.01]"},
       {"catenary.droppers.design_sags", "span 1 has 9 droppers but 2 design sags"}},
      {{"catenary.droppers.design_sags=[0, 0, 0, 0, 1.2, 0, 0, 0, 0]"},
       {"catenary.droppers.design_sags[4]", "in (-1.2, 1.2) [m]"}},
      {{"catenary.droppers.design_sags=[[0], [0]]"},
       {"catenary.droppers.design_sags", "needs 3 lists (one per span), got 2"}},
  };
  test::expect_input_errors(
      [](const auto& o) { parse_scene(scene_without_presag(), "no_presag.yaml", o); },
      "no_presag.yaml", sag_cases);
}

// The design heights at the droppers: the pre-sag parabola through the supports (the
// default), through each span's first and last droppers (`presag_between: end_droppers`,
// zero there and −presag midway), or the scene's own sags dropper by dropper.
TEST(CatenaryBuilder, DesignHeightsFromTheParabolaOrDropperByDropper) {
  const auto heights = [](const Model& m) {
    std::vector<double> z;
    for (const CatenaryDropper& d : m.catenary->droppers) z.push_back(d.design_z);
    return z;
  };
  const Model through_supports = read_scene(scene_file, {"catenary.presag=0.06"});
  const Model through_droppers =
      read_scene(scene_file, {"catenary.presag=0.06", "catenary.presag_between=end_droppers"});
  for (int span = 0; span < n_spans; ++span)
    for (int k = 0; k < droppers_per_span; ++k) {
      const double s = offsets[k];
      const std::size_t i = span * droppers_per_span + k;
      EXPECT_NEAR(heights(through_supports)[i], -0.24 * (s / 60.0) * (1.0 - s / 60.0), 1e-15);
      EXPECT_NEAR(heights(through_droppers)[i], -0.24 * (s - 5.0) * (55.0 - s) / (50.0 * 50.0),
                  1e-15);
    }
  EXPECT_EQ(heights(through_droppers)[0], 0.0);
  EXPECT_EQ(heights(through_droppers)[8], 0.0);
  EXPECT_NEAR(heights(through_droppers)[4], -0.06, 1e-15);
  // One list per span, sags down positive; the clamp masses end by end.
  const Model own =
      parse_scene(scene_without_presag(), "no_presag.yaml",
                  {"catenary.droppers.design_sags=[[0, 0.01, 0.02, 0.03, 0.04, 0.03, 0.02, 0.01, "
                   "0], [0, 0, 0, 0, 0, 0, 0, 0, 0], [-0.01, 0, 0, 0, 0.05, 0, 0, 0, 0]]",
                   "catenary.droppers.clamp_mass={contact_wire: 0.165, messenger: 0.195}"});
  const std::vector<double> z = heights(own);
  EXPECT_DOUBLE_EQ(z[3], -0.03);
  EXPECT_DOUBLE_EQ(z[13], 0.0);
  EXPECT_DOUBLE_EQ(z[18], 0.01);
  EXPECT_DOUBLE_EQ(z[22], -0.05);
  for (const CatenaryDropper& d : own.catenary->droppers) {
    double lower = 0.0, upper = 0.0;
    for (const PointMass& p : own.point_masses) {
      if (p.node == d.contact_node) lower += p.mass;
      if (p.node == d.upper_node) upper += p.mass;
    }
    EXPECT_DOUBLE_EQ(lower, 0.165);
    EXPECT_DOUBLE_EQ(upper, 0.195);
    EXPECT_DOUBLE_EQ(d.unstretched_length, d.mesh_length);  // until shape finding
  }
}

// droppers.model: cable. Each dropper is a vertical chain of `elements` cable elements
// with its own nodes (ends coinciding with the wire nodes, held in the plane in 2D),
// hinged to the wires by two springs; EA from the stiffness at mesh length, tension-only,
// prestrain put on with the loads, damping as a Kelvin–Voigt time c·L/EA.
TEST(CatenaryBuilder, CableDroppersAreHingedChains) {
  const int per = 3;
  const Model m = read_scene(
      scene_file, {"catenary.droppers.model=cable", "catenary.droppers.EI=0.02",
                   "catenary.droppers.mass_per_length=0.089", "catenary.droppers.damping=50",
                   "catenary.droppers.elements=" + std::to_string(per)});
  const CatenaryLayout& c = *m.catenary;
  const int wire_elements = n_spans * elements_per_span;
  const int n_droppers = n_spans * droppers_per_span;
  EXPECT_EQ(m.nodes.size(), 2u * (wire_elements + 1) + n_droppers * (per + 1));
  EXPECT_EQ(count_kind(m, 0), 2 * wire_elements + n_droppers * per);  // cables
  EXPECT_EQ(count_kind(m, 2), 0);                                     // no bars
  EXPECT_EQ(count_kind(m, 3), 2 * n_droppers);                        // hinges
  ASSERT_EQ(c.droppers.size(), static_cast<std::size_t>(n_droppers));
  for (const CatenaryDropper& d : c.droppers) {
    ASSERT_EQ(d.elements.size(), static_cast<std::size_t>(per));
    EXPECT_EQ(d.element, d.elements.back());
    EXPECT_NEAR(d.mesh_length, 1.2, 1e-12);
    const Vec3 top = m.nodes[d.upper_node].position;
    const Vec3 bottom = m.nodes[d.contact_node].position;
    for (std::size_t j = 0; j < d.elements.size(); ++j) {
      const ElementDesc& e = m.elements[d.elements[j]];
      EXPECT_EQ(e.set, "droppers");
      const auto& cable = std::get<CableProps>(*e.props);
      EXPECT_TRUE(cable.tension_only);
      EXPECT_TRUE(cable.prestrain_with_loads);
      EXPECT_DOUBLE_EQ(cable.EA, 1e5 * 1.2);
      EXPECT_DOUBLE_EQ(cable.EI, 0.02);
      EXPECT_NEAR(cable.damping_time, 50.0 * 1.2 / (1e5 * 1.2), 1e-15);
      EXPECT_NEAR(element_length(m, d.elements[j]), 1.2 / per, 1e-12);
      // A chain from the messenger node down to the contact-wire node.
      const Vec3 expected = top + (bottom - top) * (static_cast<double>(j) / per);
      EXPECT_LT((m.nodes[e.nodes[0]].position - expected).norm(), 1e-12);
      if (j > 0) {
        EXPECT_EQ(e.nodes[0], m.elements[d.elements[j - 1]].nodes[1]);
      }
      EXPECT_EQ(mask_of(m, e.nodes[0]), fix_y | fix_slope_y) << "2D: in the plane";
    }
    // The hinges: springs from each wire node to the coincident chain end.
    int hinges = 0;
    for (const ElementDesc& e : m.elements) {
      if (e.set != "dropper_hinges") continue;
      const int top_end = m.elements[d.elements.front()].nodes[0];
      const int bottom_end = m.elements[d.elements.back()].nodes[1];
      if ((e.nodes[0] == d.upper_node && e.nodes[1] == top_end) ||
          (e.nodes[0] == bottom_end && e.nodes[1] == d.contact_node)) {
        ++hinges;
        // Far stiffer than the dropper's elements (the hinge is in series with them).
        EXPECT_GE(std::get<SpringProps>(*e.props).stiffness.z(), 1e3 * 1e5 * 1.2 / (1.2 / per));
      }
    }
    EXPECT_EQ(hinges, 2);
  }
}

}  // namespace

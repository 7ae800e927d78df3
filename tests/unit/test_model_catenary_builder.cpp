// The scene's `catenary` becomes nodes, cables, dropper bars, masses, supports, the
// contact-wire path and Model::catenary: counts, dropper positions, element sizes, path
// continuity, the 2D and 3D support schemes, the stagger joints, ids and the evaluation
// range. The base scene is tests/data/good_scenes/catenary_3span.yaml, varied by --set;
// malformed files are tests/data/bad_scenes/catenary_*.yaml (test_model_scene_errors).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
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
                       [&](const ElementDesc& e) { return e.props.index() == kind; });
}

unsigned mask_of(const Model& m, int node) {
  unsigned mask = 0;
  for (const Support& s : m.supports)
    if (s.node == node) mask |= s.fixed_mask;
  return mask;
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
    const Vec3 top = m.nodes[d.messenger_node].position;
    EXPECT_NEAR(bottom.x(), 60.0 * span + s, 1e-12);
    EXPECT_NEAR(top.x(), bottom.x(), 1e-12);
    EXPECT_EQ(bottom.z(), 0.0);
    EXPECT_EQ(top.z(), 1.2);
    // The design height on the pre-sag parabola through 0 at the supports.
    EXPECT_NEAR(d.design_z, -4.0 * 0.055 * (s / 60.0) * (1.0 - s / 60.0), 1e-15);
    EXPECT_EQ(d.stiffness, 1.0e5);
    const ElementDesc& bar = m.elements[d.element];
    ASSERT_TRUE(std::holds_alternative<BarProps>(bar.props));
    const BarProps& props = std::get<BarProps>(bar.props);
    EXPECT_TRUE(props.tension_only);
    EXPECT_EQ(props.unstretched_length, 0.0);  // the mesh length until shape finding
    EXPECT_DOUBLE_EQ(props.EA, 1.0e5 * 1.2);   // stiffness × that length
    EXPECT_EQ(bar.set, "droppers");
    EXPECT_EQ(bar.nodes, (std::vector<int>{d.messenger_node, d.contact_node}));
  }
}

TEST(CatenaryBuilder, WiresAreSplitIntoElementsOfAtMostTheElementLength) {
  const Model m = read_scene(scene_file);
  const CatenaryLayout& c = *m.catenary;
  for (const CatenaryWire* wire : {&c.contact_wire, &c.messenger}) {
    double total = 0.0;
    for (const int e : wire->elements) {
      EXPECT_LE(element_length(m, e), 1.0 + 1e-12);
      total += element_length(m, e);
      const CableProps& cable = std::get<CableProps>(m.elements[e].props);
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
    const Vec3 gap = m.nodes[d.messenger_node].position - m.nodes[d.contact_node].position;
    EXPECT_NEAR((gap - Vec3(0, 0, 1.2)).norm(), 0.0, 1e-12);
  }
  EXPECT_EQ(m.catenary->dimension, 3);
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
    const BarProps& bar = std::get<BarProps>(m.elements[d.element].props);
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
      {{"catenary.element_length=0"}, {"catenary.element_length", "> 0 [m]"}},
      {{"catenary.dimension=4"}, {"catenary.dimension", "in [2, 3]"}},
      {{"catenary.contact_wire.tension=-1"}, {"catenary.contact_wire.tension", "> 0 [N]"}},
      {{"catenary.messenger.EI="}, {"catenary.messenger.EI", "no value given"}},
      {{"catenary.steady_arms="}, {"catenary.steady_arms", "no value given"}},
      {{"catenary.messenger_supports={fixed: true, stiffness: 5}"},
       {"catenary.messenger_supports.stiffness", "a fixed messenger support has no stiffness"}},
      {{"catenary.evaluation_spans=[3, 2]"}, {"catenary.evaluation_spans[1]", "comes before"}},
      {{"catenary.stitch=true"}, {"catenary.stitch", "stitch wires are not modelled"}},
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
  };
  test::expect_input_errors([](const auto& o) { read_scene(scene_file, o); },
                            "catenary_3span.yaml", cases);
}

// droppers.model: cable. Each dropper is a vertical chain of `elements` cable elements
// with its own nodes (ends coinciding with the wire nodes, held in the plane in 2D),
// hinged to the wires by two springs; EA from the stiffness at mesh length, tension-only,
// prestrain put on with the loads, damping as a Kelvin–Voigt time c·L/EA.
TEST(CatenaryBuilder, CableDroppersAreHingedChains) {
  const int per = 3;
  const Model m = read_scene(scene_file, {"catenary.droppers.model=cable",
                                          "catenary.droppers.EI=0.02",
                                          "catenary.droppers.mass_per_length=0.089",
                                          "catenary.droppers.damping=50",
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
    const Vec3 top = m.nodes[d.messenger_node].position;
    const Vec3 bottom = m.nodes[d.contact_node].position;
    for (std::size_t j = 0; j < d.elements.size(); ++j) {
      const ElementDesc& e = m.elements[d.elements[j]];
      EXPECT_EQ(e.set, "droppers");
      const auto& cable = std::get<CableProps>(e.props);
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
      if ((e.nodes[0] == d.messenger_node && e.nodes[1] == top_end) ||
          (e.nodes[0] == bottom_end && e.nodes[1] == d.contact_node)) {
        ++hinges;
        // Far stiffer than the dropper's elements (the hinge is in series with them).
        EXPECT_GE(std::get<SpringProps>(e.props).stiffness.z(), 1e3 * 1e5 * 1.2 / (1.2 / per));
      }
    }
    EXPECT_EQ(hinges, 2);
  }
}

}  // namespace

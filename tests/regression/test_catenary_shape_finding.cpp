// Shape finding of a three-span EN 50318 catenary (tests/data/good_scenes/
// catenary_3span.yaml): the found dropper lengths put the contact wire on its pre-sag
// parabola within 1 mm in an independent static solve of the shaped model, the lengths are
// positive and shorter than the system height, the wires carry their design tensions, and
// the middle span's lengths agree with a hand computation (taut strings, below). With
// stitch wires (18 m, 2800 N) likewise, their tension included, and the stitch droppers'
// lengths against a taut-string hand computation of the stitch wire.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "catena/catenary/shape_finding.hpp"
#include "catena/model/scene_reader.hpp"
#include "petsc_test_session.hpp"
#include "static_solution.hpp"

namespace {

namespace fs = std::filesystem;
using namespace catena;
using namespace catena::model;

const std::string scene_file =
    (fs::path(CATENA_TEST_DATA) / "good_scenes" / "catenary_3span.yaml").string();

struct Shaped {
  Model model;
  catenary::ShapeFindingReport report;
  test::GatheredStatic statics;  // of the shaped model, solved independently
};

Shaped shape_scene(const std::string& file, const std::vector<std::string>& overrides) {
  test::ensure_petsc();
  Shaped s{read_scene(file, overrides), {}, {}};
  s.report = catenary::find_catenary_shape(MPI_COMM_WORLD, s.model);
  s.statics = test::solve_static(MPI_COMM_WORLD, s.model);
  std::printf(
      "  shape finding: %d whole-structure solves (%d in all), max error %.4f mm;"
      " history (mm):",
      s.report.n_iterations, s.report.n_static_solves, 1e3 * s.report.max_height_error);
  for (const double e : s.report.error_history) std::printf(" %.3g", 1e3 * e);
  std::printf("\n");
  return s;
}

Shaped shape(const std::vector<std::string>& overrides = {}) {
  return shape_scene(scene_file, overrides);
}

double z_of(const test::GatheredStatic& g, int node) { return g.positions[3 * node + 2]; }

// The model index of the node at reference position x (within 1e-9 m).
int node_at(const Model& m, const Vec3& x) {
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if ((m.nodes[i].position - x).norm() < 1e-9) return static_cast<int>(i);
  ADD_FAILURE() << "no node at " << x.transpose();
  return 0;
}

void expect_design_heights(const Shaped& s, double tolerance) {
  const CatenaryLayout& c = *s.model.catenary;
  double worst = 0.0;
  for (const CatenaryDropper& d : c.droppers) {
    const double error = z_of(s.statics, d.contact_node) - d.design_z;
    worst = std::max(worst, std::abs(error));
    EXPECT_LT(std::abs(error), tolerance)
        << "dropper at x = " << s.model.nodes[d.contact_node].position.x();
  }
  for (const CatenaryRegistration& r : c.registrations)
    EXPECT_LT(std::abs(z_of(s.statics, r.node) - r.design_z), tolerance);
  std::printf("  independent static solve: max dropper-point height error %.4f mm\n", 1e3 * worst);
}

TEST(ShapeFinding, ContactWireOnThePresagParabolaWithin1mm) {
  const Shaped s = shape();
  const CatenaryLayout& c = *s.model.catenary;
  EXPECT_LT(s.report.max_height_error, 1e-4);  // the iteration's own tolerance, 0.1 mm
  EXPECT_LE(s.report.n_iterations, 10);
  expect_design_heights(s, 1e-3);

  // The lengths are set in the model, positive and shorter than the system height; the
  // droppers all carry tension (none slack).
  ASSERT_EQ(s.report.dropper_lengths.size(), c.droppers.size());
  for (std::size_t i = 0; i < c.droppers.size(); ++i) {
    const double l0 = s.report.dropper_lengths[i];
    const BarProps& bar = std::get<BarProps>(*s.model.elements[c.droppers[i].element].props);
    EXPECT_EQ(bar.unstretched_length, l0);
    EXPECT_DOUBLE_EQ(bar.EA, 1.0e5 * l0);  // the design fixes the stiffness EA/l0
    EXPECT_GT(l0, 0.0);
    EXPECT_LT(l0, c.system_height);
    EXPECT_GT(s.statics.axial_force[c.droppers[i].element], 0.0);
  }
  // Design tensions as mean axial forces, in the report and in the independent solve.
  EXPECT_NEAR(s.report.contact_wire_tension, 20000.0, 2.0);
  EXPECT_NEAR(s.report.messenger_tension, 16000.0, 1.6);

  // The pre-sag shape: mid-span droppers are the shortest, and the spans are alike.
  for (std::size_t k = 0; k < 9; ++k)
    EXPECT_NEAR(s.report.dropper_lengths[k], s.report.dropper_lengths[18 + 8 - k], 2e-3);
}

// Hand computation of the middle span. The contact wire, held at its design heights z_i
// at the dropper points s_i (and at 0 at the registrations), is a taut string of
// tension T_c carrying w_c = 1.35 g N/m: dropper i carries
//   F_i = w_c (s_{i+1} − s_{i−1})/2 + m_clamp g + T_c [(z_i − z_{i−1})/(s_i − s_{i−1})
//         − (z_{i+1} − z_i)/(s_{i+1} − s_i)].
// The messenger, a taut string of horizontal tension H_m ≈ T_m between its two support
// points (whose heights come from the solve), sags below their chord by M(s)/H_m, M the
// bending moment of a simply supported beam under w_m = 1.07 g N/m and the point loads
// F_i + m_clamp g. Then l0_i = (z_m(s_i) − z_i) − F_i/k. Bending enters only through
// the boundary layers at the kinks over the supports (below); the rest of it (the
// droppers' small kinks in the messenger, ≈ 0.2 mm each), H versus the mean axial force
// and the droppers' inclination are left out, which the 1.5 mm tolerance covers.
// The design data the hand computation needs: the span checked (its length and start x,
// and its first dropper's index), the wires, the droppers and the clamps.
struct HandDesign {
  double L = 60.0, x0 = 60.0;  // m: the span and its start (a 2D line, messenger at 1.2 m)
  std::size_t first_dropper = 9, n_droppers = 9;
  double T_c = 20000.0, T_m = 16000.0;          // N
  double mass_c = 1.35, mass_m = 1.07;          // kg/m
  double EI_c = 195.0, EI_m = 131.7;            // N·m²
  double dropper_stiffness = 1.0e5;             // N/m (EA/l0), or 0 with dropper_EA
  double dropper_EA = 0.0;                      // N
  double dropper_mass = 0.0;                    // kg/m, lumped half at each end
  double lower_clamp = 0.2, upper_clamp = 0.2;  // kg
  double force_rtol = 0.02;  // the droppers' forces against the string's, relative
};

// The span of `s` against the hand computation above, a bar dropper's weight lumped half
// on each wire, its stretch N/k (or N·l0/EA). Returns the largest |l0 − hand computation|.
double compare_span_with_hand_computation(const Shaped& s, const HandDesign& h, double tolerance) {
  const CatenaryLayout& c = *s.model.catenary;
  const double g = 9.81, w_c = h.mass_c * g, w_m = h.mass_m * g, L = h.L, x0 = h.x0;
  std::vector<double> st{0.0}, z{0.0};
  for (std::size_t i = 0; i < h.n_droppers; ++i) {
    const CatenaryDropper& d = c.droppers[h.first_dropper + i];
    st.push_back(s.model.nodes[d.contact_node].position.x() - x0);
    z.push_back(d.design_z);
  }
  st.push_back(L);
  z.push_back(0.0);
  // Bending boundary layers: at a kink of slope θ per side a tensioned wire of bending
  // length λ = √(EI/T) is rounded, which shifts the string beyond it by θ λ (up at a
  // support). Applied at the registrations and at the messenger supports.
  const double lambda_c = std::sqrt(h.EI_c / h.T_c), lambda_m = std::sqrt(h.EI_m / h.T_m);
  const double theta_c = -z[1] / st[1] + w_c * st[1] / (2.0 * h.T_c);
  z.front() = z.back() = theta_c * lambda_c;
  const double z_left = z_of(s.statics, node_at(s.model, Vec3(x0, 0, 1.2)));
  const double z_right = z_of(s.statics, node_at(s.model, Vec3(x0 + L, 0, 1.2)));
  // The droppers' weight depends on their lengths: two passes, from the mesh length.
  std::vector<double> l0(st.size(), 1.2), F(st.size(), 0.0);
  double worst = 0.0;
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t i = 1; i + 1 < st.size(); ++i)
      F[i] =
          w_c * (st[i + 1] - st[i - 1]) / 2.0 + (h.lower_clamp + h.dropper_mass * l0[i] / 2) * g +
          h.T_c *
              ((z[i] - z[i - 1]) / (st[i] - st[i - 1]) - (z[i + 1] - z[i]) / (st[i + 1] - st[i]));
    // The messenger carries w_m and, at each dropper, F_i, the upper clamp and the
    // dropper's upper half-weight: a simply supported span's moment over H ≈ T_m.
    std::vector<double> P(st.size(), 0.0);
    double R_left = w_m * L / 2.0;
    for (std::size_t i = 1; i + 1 < st.size(); ++i) {
      P[i] = F[i] + (h.upper_clamp + h.dropper_mass * l0[i] / 2) * g;
      R_left += P[i] * (L - st[i]) / L;
    }
    const auto moment = [&](double x) {
      double m = R_left * x - w_m * x * x / 2.0;
      for (std::size_t i = 1; i + 1 < st.size(); ++i)
        if (st[i] < x) m -= P[i] * (x - st[i]);
      return m;
    };
    const double shift_m = R_left / h.T_m * lambda_m;  // θ = R_left/H at the support
    for (std::size_t i = 1; i + 1 < st.size(); ++i) {
      const double z_m = z_left + shift_m + (z_right - z_left) * st[i] / L - moment(st[i]) / h.T_m;
      l0[i] = h.dropper_stiffness > 0.0 ? (z_m - z[i]) - F[i] / h.dropper_stiffness
                                        : (z_m - z[i]) / (1.0 + F[i] / h.dropper_EA);
    }
  }
  double worst_force = 0.0;
  for (std::size_t i = 1; i + 1 < st.size(); ++i) {
    const std::size_t k = h.first_dropper + i - 1;
    worst_force =
        std::max(worst_force, std::abs(s.statics.axial_force[c.droppers[k].element] / F[i] - 1));
    const double found = s.report.dropper_lengths[k];
    worst = std::max(worst, std::abs(found - l0[i]));
    EXPECT_NEAR(found, l0[i], tolerance) << "dropper at s = " << st[i] << " m";
    EXPECT_EQ(c.droppers[k].unstretched_length, found);
    EXPECT_NEAR(s.statics.axial_force[c.droppers[k].element], F[i], h.force_rtol * F[i]);
  }
  std::printf(
      "  span at x0 = %g m: largest |l0 - hand computation| %.3f mm, dropper force %.2f %%\n", x0,
      1e3 * worst, 1e2 * worst_force);
  return worst;
}

TEST(ShapeFinding, MiddleSpanAgreesWithATautStringHandComputation) {
  // 0.25 m elements: the rounding of the messenger's kink at a support spreads over about
  // an element, so on coarser meshes the lengths differ by more (measured: 5.0 mm at 1 m,
  // 1.9 mm at 0.5 m, 0.88 mm at 0.25 m, 0.68 mm at 0.1 m, 0.67 mm at 0.05 m).
  const Shaped s = shape({"catenary.element_length=0.25"});
  compare_span_with_hand_computation(s, HandDesign{}, 1.5e-3);
}

// A design that hangs the first and last droppers of every span at the registration
// height with its pre-sag midway between them (presag_between: end_droppers), and
// different clamps on the two wires: the same hand computation holds.
TEST(ShapeFinding, EndDropperParabolaAndSeparateClampsAgreeWithTheHandComputation) {
  const Shaped s = shape({"catenary.element_length=0.25", "catenary.presag_between=end_droppers",
                          "catenary.droppers.clamp_mass={contact_wire: 0.165, messenger: 0.195}"});
  expect_design_heights(s, 1e-3);
  EXPECT_EQ(s.model.catenary->droppers[9].design_z, 0.0);
  HandDesign h;
  h.lower_clamp = 0.165;
  h.upper_clamp = 0.195;
  compare_span_with_hand_computation(s, h, 1.5e-3);
}

// The benchmark catenary (meshes/benchmark_catenary.yaml: 55 m spans, design heights
// between the end droppers, droppers of fixed EA with mass, separate clamps) cut to three
// spans: its middle span against the hand computation (docs/validation.md, "Dropper
// lengths of the benchmark catenary", where the ten-span line is compared).
TEST(ShapeFinding, BenchmarkCatenaryAgreesWithTheHandComputation) {
  const std::string benchmark =
      (fs::path(CATENA_SOURCE_DIR) / "meshes" / "benchmark_catenary.yaml").string();
  const Shaped s = shape_scene(benchmark, {"catenary.spans=3", "catenary.evaluation_spans=[2, 2]"});
  expect_design_heights(s, 1e-3);
  HandDesign h;
  h.L = h.x0 = 55.0;
  h.T_c = 22000.0;
  h.mass_m = 1.08;
  h.EI_c = 179.0;
  h.EI_m = 111.2;
  h.dropper_stiffness = 0.0;
  h.dropper_EA = 2.0e5;
  h.dropper_mass = 0.117;
  h.lower_clamp = 0.165;
  h.upper_clamp = 0.195;
  // The end droppers hang at the registration height: the string's forces are up to
  // 2.05 % (1.07 N, an end dropper) above the model's; with a hundredth of the contact
  // wire's EI 1.03 %, so half of it is the wire's bending, which the string leaves out.
  h.force_rtol = 0.025;
  compare_span_with_hand_computation(s, h, 1.5e-3);
}

// The stitch wires of test_model_catenary_builder.cpp: 18 m at x = 60 and 120 m, typical
// Bz II 35 mm^2 data (meshes/stitched_catenary.yaml), each carrying the droppers at 5 m
// either side of its support.
const std::string stitch =
    "catenary.stitch={length: 18, tension: 2800, EA: 3.5e6, EI: 11, mass_per_length: 0.31}";

double mean_axial_force(const Shaped& s, const CatenaryWire& wire) {
  double sum = 0.0, length = 0.0;
  for (const int e : wire.elements) {
    const auto& n = s.model.elements[e].nodes;
    const double l = (s.model.nodes[n[1]].position - s.model.nodes[n[0]].position).norm();
    sum += s.statics.axial_force[e] * l;
    length += l;
  }
  return sum / length;
}

// Shape finding sets a wire's prestrain, or a cable dropper's length, on all its elements
// as one edit (model::edit_shared): they keep sharing one properties block, as the scene
// reader made them (model/shared_props.hpp; every rank holds every element).
void expect_one_block(const Model& m, const std::vector<int>& elements, const char* what) {
  ASSERT_FALSE(elements.empty()) << what;
  for (const int e : elements)
    EXPECT_TRUE(m.elements[e].props.same_block(m.elements[elements.front()].props))
        << what << ": element " << e;
}

TEST(ShapeFinding, StitchWiresReachTheDesignHeightsAndTheirTension) {
  const Shaped s = shape({stitch});
  const CatenaryLayout& c = *s.model.catenary;
  EXPECT_LT(s.report.max_height_error, 1e-4);
  EXPECT_LE(s.report.n_iterations, 10);
  expect_design_heights(s, 1e-3);
  ASSERT_EQ(s.report.stitch_tensions.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const double independent = mean_axial_force(s, c.stitch_wires[k].wire);
    std::printf("  stitch wire %zu: %.3f N (report), %.3f N (independent solve)\n", k + 1,
                s.report.stitch_tensions[k], independent);
    EXPECT_NEAR(s.report.stitch_tensions[k], 2800.0, 0.28);  // tension_rtol 1e-4
    EXPECT_NEAR(independent, 2800.0, 0.28);
  }
  EXPECT_NEAR(s.report.messenger_tension, 16000.0, 1.6);
  EXPECT_NEAR(s.report.contact_wire_tension, 20000.0, 2.0);
  expect_one_block(s.model, c.contact_wire.elements, "contact wire");
  expect_one_block(s.model, c.messenger.elements, "messenger");
  for (const CatenaryStitch& stitch_wire : c.stitch_wires)
    expect_one_block(s.model, stitch_wire.wire.elements, "stitch wire");
  // The stitch wires' tensions differ from the messenger's: their own blocks.
  EXPECT_FALSE(s.model.elements[c.stitch_wires[0].wire.elements[0]].props.same_block(
      s.model.elements[c.messenger.elements[0]].props));
  // Every dropper carries tension, the stitch droppers included.
  for (const CatenaryDropper& d : c.droppers)
    EXPECT_GT(s.statics.axial_force[d.element], 0.0)
        << "x = " << s.model.nodes[d.contact_node].position.x();
}

// The stitch wire as a taut string: between its clamps (heights from the solve) it carries
// its two droppers' forces plus their clamp masses and its own weight at horizontal
// tension H ≈ T_s (its slopes are below 0.05, so H and the mean axial force differ by
// 0.1 %), and sags below the chord by M(x)/H, M the moment of a simply supported beam of
// the clamps' span; its bending (λ = √(EI/T_s) = 0.063 m) rounds the kink under a dropper
// load F, which lifts the wire there by F λ/(2 H) (0.8 mm). The dropper's length is the
// stitch's height there less the contact wire's design height less its stretch F/k. A stitch
// dropper is about 0.3 m shorter than the same dropper hanging from the messenger: the stitch wire
// dips below the messenger (which at the clamp is already lower than at the support) by F (a/2 − 4
// m)/T_s.
TEST(ShapeFinding, StitchDroppersAgreeWithATautStringHandComputation) {
  // 0.25 m elements: the cable rounds the stitch wire's kink under a dropper over an
  // element where its bending length is shorter (measured largest |l0 − hand computation|:
  // 1.27 mm at 1 m, 0.51 mm at 0.5 m, 0.20 mm at 0.25 m, 0.12 mm at 0.1 m, 0.11 mm at
  // 0.05 m; without the bending term F λ/(2H) below, 0.77 mm at 0.05 m).
  const Shaped s = shape({stitch, "catenary.element_length=0.25"});
  const Shaped bare = shape({"catenary.element_length=0.25"});
  const CatenaryLayout& c = *s.model.catenary;
  const double lambda = std::sqrt(11.0 / 2800.0);
  const double g = 9.81, H = 2800.0, k_dropper = 1.0e5, clamp = 0.2 * g, w = 0.31 * g;
  double worst = 0.0;
  for (std::size_t k = 0; k < c.stitch_wires.size(); ++k) {
    const CatenaryStitch& wire = c.stitch_wires[k];
    const Vec3 a = s.model.nodes[wire.clamp_nodes[0]].position;
    const Vec3 b = s.model.nodes[wire.clamp_nodes[1]].position;
    const double za = z_of(s.statics, wire.clamp_nodes[0]);
    const double zb = z_of(s.statics, wire.clamp_nodes[1]);
    const double L = b.x() - a.x();
    std::vector<double> x, F;  // the carried droppers: distance from clamp a, load
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < c.droppers.size(); ++i) {
      if (c.droppers[i].stitch != static_cast<int>(k)) continue;
      index.push_back(i);
      x.push_back(s.model.nodes[c.droppers[i].contact_node].position.x() - a.x());
      F.push_back(s.statics.axial_force[c.droppers[i].element] + clamp);
    }
    ASSERT_EQ(x.size(), 2u);
    double R_a = w * L / 2.0;
    for (std::size_t j = 0; j < x.size(); ++j) R_a += F[j] * (L - x[j]) / L;
    for (std::size_t j = 0; j < x.size(); ++j) {
      double M = R_a * x[j] - w * x[j] * x[j] / 2.0;
      for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i] < x[j]) M -= F[i] * (x[j] - x[i]);
      const double z_stitch = za + (zb - za) * x[j] / L - M / H + F[j] * lambda / (2.0 * H);
      const CatenaryDropper& d = c.droppers[index[j]];
      const double l0 = z_stitch - d.design_z - (F[j] - clamp) / k_dropper;
      const double found = s.report.dropper_lengths[index[j]];
      worst = std::max(worst, std::abs(found - l0));
      EXPECT_NEAR(found, l0, 0.5e-3) << "dropper at x = " << a.x() + x[j];
      EXPECT_LT(found, bare.report.dropper_lengths[index[j]] - 0.2) << "x = " << a.x() + x[j];
    }
  }
  std::printf("  stitch droppers: largest |l0 - hand computation| %.3f mm\n", 1e3 * worst);
}

TEST(ShapeFinding, SpatialStaggeredCatenaryWithStitchWiresReachesTheDesignHeights) {
  const Shaped s = shape({stitch, "catenary.dimension=3", "catenary.stagger=0.3"});
  EXPECT_LT(s.report.max_height_error, 1e-4);
  expect_design_heights(s, 1e-3);
  for (const double t : s.report.stitch_tensions) EXPECT_NEAR(t, 2800.0, 0.28);
}

TEST(ShapeFinding, SpatialStaggeredCatenaryReachesTheDesignHeights) {
  const Shaped s = shape({"catenary.dimension=3", "catenary.stagger=0.3"});
  EXPECT_LT(s.report.max_height_error, 1e-4);
  expect_design_heights(s, 1e-3);
}

}  // namespace

// A pantograph pressing on the wire (and a moving load on it) are not part of the design
// shape: with them in the scene shape finding gives the same lengths to 1e-9 m (without
// leaving them out, a pantograph standing in a span shortens that span's droppers).
TEST(ShapeFinding, PantographsAndMovingLoadsDoNotChangeTheLengths) {
  const Shaped bare = shape();
  const Shaped loaded =
      shape({"pantographs=[{name: p, path: contact_wire, speed: 0, start: 90, static_force: 300, "
             "model: en50318}]"});
  ASSERT_EQ(bare.report.dropper_lengths.size(), loaded.report.dropper_lengths.size());
  for (std::size_t i = 0; i < bare.report.dropper_lengths.size(); ++i)
    EXPECT_NEAR(loaded.report.dropper_lengths[i], bare.report.dropper_lengths[i], 1e-9) << i;
  // The pantograph is still in the model, and lifts the wire where it stands.
  ASSERT_EQ(loaded.model.contacts.size(), 1u);
}

// droppers.model: cable with the same stiffness and mass as a bar model: shape finding
// reaches the design heights within 1 mm in an independent static solve, each chain's
// unstretched length L/(1 + ε_p) is the reported one, its EA is stiffness·l0, and the
// lengths and the droppers' pull on the contact wire equal the bars' (the static
// problems differ only in where the droppers' weight acts: lumped at the ends, or along
// the chain, which hangs straight).
TEST(ShapeFinding, CableDroppersMatchBarDroppersOfTheSameMass) {
  const std::vector<std::string> mass{"catenary.droppers.mass_per_length=0.089"};
  std::vector<std::string> cable = mass;
  cable.insert(cable.end(), {"catenary.droppers.model=cable", "catenary.droppers.EI=0.02",
                             "catenary.droppers.elements=3"});
  const Shaped bars = shape(mass);
  const Shaped cables = shape(cable);
  expect_design_heights(cables, 1e-3);
  const CatenaryLayout& c = *cables.model.catenary;
  ASSERT_EQ(cables.report.dropper_lengths.size(), bars.report.dropper_lengths.size());
  double worst_length = 0.0, worst_force = 0.0;
  for (std::size_t i = 0; i < c.droppers.size(); ++i) {
    const double l0 = cables.report.dropper_lengths[i];
    expect_one_block(cables.model, c.droppers[i].elements, "dropper chain");
    if (i > 0 && l0 != cables.report.dropper_lengths[i - 1]) {  // lengths of their own
      EXPECT_FALSE(cables.model.elements[c.droppers[i].element].props.same_block(
          cables.model.elements[c.droppers[i - 1].element].props));
    }
    for (const int e : c.droppers[i].elements) {
      const auto& props = std::get<CableProps>(*cables.model.elements[e].props);
      EXPECT_NEAR(c.droppers[i].mesh_length / (1.0 + props.prestrain), l0, 1e-12);
      EXPECT_DOUBLE_EQ(props.EA, 1.0e5 * l0);
    }
    worst_length = std::max(worst_length, std::abs(l0 - bars.report.dropper_lengths[i]));
    // The lowest cable element's mid-point force less the weight of the chain's lowest
    // sixth (3 elements) is the pull on the contact wire; the bar's force less nothing,
    // its lower half-weight being lumped on the wire node: compare both with the
    // contact-wire node's share, i.e. the bar force plus half the weight minus a sixth.
    const double weight = 0.089 * l0 * 9.81;
    const double cable_pull = cables.statics.axial_force[c.droppers[i].element] - weight / 6.0;
    const double bar_pull =
        bars.statics.axial_force[bars.model.catenary->droppers[i].element] - weight / 2.0;
    worst_force = std::max(worst_force, std::abs(cable_pull - bar_pull));
    EXPECT_NEAR(cable_pull, bar_pull, 0.05) << "dropper " << i;
  }
  std::printf("  cable vs bar droppers: lengths within %.3g mm, pull within %.3g N\n",
              1e3 * worst_length, worst_force);
  EXPECT_LT(worst_length, 1e-4);
}

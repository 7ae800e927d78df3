// Static elasticity (catenary/static_elasticity.hpp) against closed forms, through the same
// routine `catena elasticity` calls.
//
// A wire of tension T pinned at both ends (span L), pushed by a point force F at x = a:
//   * the taut string, T w'' = −F δ(x − a):            w(a) = F a (L − a) / (T L);
//   * the tensioned Euler–Bernoulli beam with moment-free ends (the ANCF cable's model),
//     EI w'''' − T w'' = F δ(x − a), w = w'' = 0 at the ends: with λ = √(EI/T),
//       w(a) = F/T · [a (L − a)/L − λ sinh(a/λ) sinh((L − a)/λ) / sinh(L/λ)]
//     (the string's Green's function plus −(F λ/T) sinh(k x<) sinh(k (L − x>))/sinh(kL),
//     k = 1/λ, which keeps w' continuous and gives the jump EI [w'''] = F).
// The force is small (10 N: the wire's extra stretch changes T by 3e-5), so the linear
// forms hold. Points at nodes, inside elements and 1 m from a support.
//
// On the three-span EN 50318 catenary (tests/data/good_scenes/catenary_3span.yaml, shaped
// first): at nodes, the same uplift as two independent static solves (without and with a
// nodal force); larger at mid-span than at the steady arm, plausible in size, linear in F
// up to 100 N and not beyond, where tension-only droppers go slack. With stitch wires the
// same catenary is softer at the supports and its elasticity more uniform over the span.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "catena/catenary/shape_finding.hpp"
#include "catena/catenary/static_elasticity.hpp"
#include "catena/model/scene_reader.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"
#include "static_solution.hpp"

namespace {

namespace fs = std::filesystem;
using namespace catena;

// A wire of span L pinned at both ends, straight along x, tension T (prestrain T/EA), no
// gravity: the EN 50318 contact wire's data unless changed.
struct Wire {
  double L = 60.0, T = 20000.0, EA = 1.8e7, EI = 195.0;
  int n = 120;
  model::Model model() const {
    model::Model m;
    m.gravity = Vec3::Zero();
    model::CableProps cable;
    cable.EA = EA;
    cable.EI = EI;
    cable.mass_per_length = 1.35;
    cable.prestrain = T / EA;
    const std::vector<int> nodes = test::add_line(m, {0, 0, 0}, {L, 0, 0}, n, cable);
    test::set_reference_frames(m);
    test::pin(m, nodes.front());
    test::pin(m, nodes.back());
    return m;
  }
};

std::vector<int> all_elements(const model::Model& m) {
  std::vector<int> path;
  for (std::size_t e = 0; e < m.elements.size(); ++e) path.push_back(static_cast<int>(e));
  return path;
}

double string_deflection(double F, double T, double L, double a) {
  return F * a * (L - a) / (T * L);
}

double tensioned_beam_deflection(double F, double T, double EI, double L, double a) {
  const double lambda = std::sqrt(EI / T);
  // sinh(a/λ) sinh((L−a)/λ)/sinh(L/λ) without overflow (L/λ ~ 600).
  const double layer = 0.5 * (1.0 - std::exp(-2.0 * a / lambda)) *
                       (1.0 - std::exp(-2.0 * (L - a) / lambda)) /
                       (1.0 - std::exp(-2.0 * L / lambda));
  return F / T * (a * (L - a) / L - lambda * layer);
}

catenary::ElasticityReport wire_elasticity(const Wire& wire, const std::vector<double>& positions,
                                           double F) {
  test::ensure_petsc();
  const model::Model m = wire.model();
  catenary::ElasticityProbe probe;
  probe.path = all_elements(m);
  probe.positions = positions;
  probe.force = Vec3(0.0, 0.0, F);
  return catenary::static_elasticity(MPI_COMM_WORLD, m, probe);
}

const std::vector<double> kWirePoints{0.0, 1.0, 7.25, 15.0, 30.0, 44.6, 59.0, 60.0};

TEST(StaticElasticity, TautStringClosedFormWithin1Percent) {
  Wire wire;
  wire.EI = 0.2;  // λ = 3 mm: bending changes the string's w by Fλ/(2T), 0.15 % at 1 m
  // 0.05 m elements: the cable's slope is continuous at the loaded node, so it rounds the
  // string's kink over an element, which costs about F h / (12 T) of w (measured: 4 % at
  // 1 m from a support with h = 0.5 m).
  wire.n = 1200;
  const double F = 10.0;
  const catenary::ElasticityReport r = wire_elasticity(wire, kWirePoints, F);
  ASSERT_EQ(r.points.size(), kWirePoints.size());
  for (const catenary::ElasticityPoint& p : r.points) {
    const double exact = string_deflection(F, wire.T, wire.L, p.position);
    std::printf("  x = %5.2f m: uplift %.6e m, string %.6e m, elasticity %.6f mm/N\n", p.position,
                p.uplift, exact, 1e3 * p.elasticity);
    EXPECT_DOUBLE_EQ(p.elasticity, p.uplift / F);
    if (exact == 0.0)
      EXPECT_EQ(p.uplift, 0.0) << "at a pinned end";
    else
      EXPECT_NEAR(p.uplift / exact, 1.0, 0.01) << "x = " << p.position;
  }
}

TEST(StaticElasticity, TensionedBeamClosedForm) {
  Wire wire;     // the EN 50318 contact wire: EI = 195 N m², λ = 0.099 m
  wire.n = 600;  // 0.1 m elements: the bending layer under the load is resolved
  const double F = 10.0;
  const catenary::ElasticityReport r = wire_elasticity(wire, kWirePoints, F);
  for (const catenary::ElasticityPoint& p : r.points) {
    if (p.position == 0.0 || p.position == wire.L) continue;
    const double exact = tensioned_beam_deflection(F, wire.T, wire.EI, wire.L, p.position);
    const double string = string_deflection(F, wire.T, wire.L, p.position);
    std::printf("  x = %5.2f m: uplift / beam %.6f, linear / beam %.6f, string / beam %.6f\n",
                p.position, p.uplift / exact, p.linear_elasticity * F / exact, string / exact);
    EXPECT_NEAR(p.uplift / exact, 1.0, 2e-3) << "x = " << p.position;
    // The closed form is the linear theory of a tensioned beam: the tangent's answer.
    EXPECT_NEAR(p.linear_elasticity * F / exact, 1.0, 2e-3) << "x = " << p.position;
    EXPECT_EQ(p.slackened, 0);
  }
}

// The probe's position is a time (static_elasticity.hpp): a prescribed constraint, which
// moves with t, must stay where the static solve (t = 0) holds it. The wire's end held by
// one, moving at 1 m/s, gives the same elasticity as the pinned end.
TEST(StaticElasticity, TimeDependentConstraintsStayPut) {
  Wire wire;
  const std::vector<double> x{10.0, 30.0, 59.5};
  const double F = 10.0;
  const catenary::ElasticityReport pinned = wire_elasticity(wire, x, F);
  model::Model m = wire.model();
  const int end = static_cast<int>(m.nodes.size()) - 1;
  std::erase_if(m.supports, [&](const model::Support& s) { return s.node == end; });
  model::Constraint moving;
  moving.type = model::ConstraintType::prescribed;
  moving.node_a = end;
  moving.velocity = Vec3(0.0, 0.0, 1.0);  // m/s
  m.constraints.push_back(moving);
  catenary::ElasticityProbe probe;
  probe.path = all_elements(m);
  probe.positions = x;
  probe.force = Vec3(0.0, 0.0, F);
  const catenary::ElasticityReport held = catenary::static_elasticity(MPI_COMM_WORLD, m, probe);
  for (std::size_t i = 0; i < x.size(); ++i)
    EXPECT_NEAR(held.points[i].uplift / pinned.points[i].uplift, 1.0, 1e-8) << "x = " << x[i];
}

model::Model shape_catenary(const std::vector<std::string>& overrides) {
  test::ensure_petsc();
  const std::string scene =
      (fs::path(CATENA_TEST_DATA) / "good_scenes" / "catenary_3span.yaml").string();
  model::Model shaped = model::read_scene(scene, overrides);
  catenary::find_catenary_shape(MPI_COMM_WORLD, shaped);
  return shaped;
}

// The three-span catenary, shaped once for the tests below.
const model::Model& shaped_catenary() {
  static const model::Model m = shape_catenary({});
  return m;
}

// The contact-wire node at (x, 0, 0).
int contact_node_at(const model::Model& m, double x) {
  for (const int e : m.catenary->contact_wire.elements)
    for (const int n : m.elements[static_cast<std::size_t>(e)].nodes)
      if ((m.nodes[static_cast<std::size_t>(n)].position - Vec3(x, 0, 0)).norm() < 1e-9) return n;
  ADD_FAILURE() << "no contact-wire node at x = " << x;
  return 0;
}

catenary::ElasticityReport catenary_elasticity(const std::vector<double>& positions, double F,
                                               const model::Model& m = shaped_catenary()) {
  catenary::ElasticityProbe probe;
  probe.path = m.catenary->contact_wire.elements;
  probe.positions = positions;
  probe.force = Vec3(0.0, 0.0, F);
  return catenary::static_elasticity(MPI_COMM_WORLD, m, probe);
}

// At nodes the probe is a nodal force: two independent static solves from the reference
// configuration, without and with a 100 N nodal load, give the same uplift as Newton from
// the unloaded equilibrium.
TEST(StaticElasticity, CatenaryAgreesWithIndependentStaticSolves) {
  const model::Model& m = shaped_catenary();
  const double F = 100.0;
  const std::vector<double> x{60.0, 62.0, 65.0, 90.0};  // steady arm, mid-element, dropper, mid
  const catenary::ElasticityReport r = catenary_elasticity(x, F);
  const test::GatheredStatic base = test::solve_static(MPI_COMM_WORLD, m);
  for (std::size_t i = 0; i < x.size(); ++i) {
    model::Model loaded = m;
    const int node = contact_node_at(m, x[i]);
    loaded.nodal_loads.push_back({node, Vec3(0.0, 0.0, F)});
    const test::GatheredStatic pushed = test::solve_static(MPI_COMM_WORLD, loaded);
    const double uplift = pushed.positions[3 * node + 2] - base.positions[3 * node + 2];
    std::printf("  x = %4.1f m: routine %.9f mm/N, two static solves %.9f mm/N\n", x[i],
                1e3 * r.points[i].elasticity, 1e3 * uplift / F);
    EXPECT_NEAR(r.points[i].uplift / uplift, 1.0, 1e-6) << "x = " << x[i];
  }
}

TEST(StaticElasticity, CatenaryMidSpanSofterThanSupportAndLinearForSmallForces) {
  const model::Model& m = shaped_catenary();
  const double support =
      catenary::path_arc_length_at(m, m.catenary->contact_wire.elements, m.registration_nodes[1]);
  ASSERT_NEAR(support, 60.0, 1e-9);
  const std::vector<double> x{support, support + 30.0};  // steady arm, mid-span of span 2
  std::vector<std::vector<double>> e;                    // mm/N, per force, per point
  const std::vector<double> forces{10.0, 20.0, 100.0, 200.0};
  for (const double F : forces) {
    const catenary::ElasticityReport r = catenary_elasticity(x, F);
    e.push_back({1e3 * r.points[0].elasticity, 1e3 * r.points[1].elasticity});
    std::printf("  %5.0f N: steady arm %.5f mm/N, mid-span %.5f mm/N\n", F, e.back()[0],
                e.back()[1]);
  }
  EXPECT_GT(e[2][1], e[2][0]);  // 100 N: mid-span softer than the steady arm
  EXPECT_GT(e[2][0], 0.1);
  EXPECT_LT(e[2][1], 1.0);
  // Linear for small forces, and the default 100 N still measures the small-force value;
  // at 200 N the two droppers beside the steady arm (55 N each at rest, 14 N under 100 N
  // there) go slack and the steady arm's elasticity rises by a quarter.
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(e[1][i] / e[0][i], 1.0, 0.01);
    EXPECT_NEAR(e[2][i] / e[0][i], 1.0, 0.01);
  }
  EXPECT_GT(e[3][0] / e[0][0], 1.1);
}

// The linear elasticity (Pᵀ K₀⁻¹ P / |F|²) is the limit of small forces: independent of
// the force, met by the Newton solution at 10 N, and what the 200 N probe departs from at
// the steady arm, where it slackens the two droppers beside it (counted per point; at
// mid-span 200 N slackens the dropper there: 0.4496 against 0.4334 mm/N linear).
TEST(StaticElasticity, LinearElasticityIsTheSmallForceLimitAndSlackDroppersAreCounted) {
  const model::Model& m = shaped_catenary();
  const double support =
      catenary::path_arc_length_at(m, m.catenary->contact_wire.elements, m.registration_nodes[1]);
  const std::vector<double> x{support, support + 30.0};  // steady arm, mid-span of span 2
  const catenary::ElasticityReport small = catenary_elasticity(x, 10.0);
  const catenary::ElasticityReport large = catenary_elasticity(x, 200.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double linear = small.points[i].linear_elasticity;
    std::printf(
        "  x = %5.1f m: linear %.6f mm/N; 10 N %.6f mm/N (%d slack), 200 N %.6f mm/N "
        "(%d slack)\n",
        x[i], 1e3 * linear, 1e3 * small.points[i].elasticity, small.points[i].slackened,
        1e3 * large.points[i].elasticity, large.points[i].slackened);
    EXPECT_NEAR(large.points[i].linear_elasticity / linear, 1.0, 1e-9);
    EXPECT_NEAR(small.points[i].elasticity / linear, 1.0, 0.01);
    EXPECT_EQ(small.points[i].slackened, 0);
  }
  EXPECT_GE(large.points[0].slackened, 2);  // the droppers either side of the steady arm
  EXPECT_GT(large.points[0].elasticity / large.points[0].linear_elasticity, 1.1);
}

// A stitch wire (18 m, 2800 N, as in meshes/stitched_catenary.yaml) hangs the droppers
// next to the support from a soft wire instead of from the messenger, which its support
// holds: the contact wire there gives way more under an upward force, while mid-span, out
// of the stitch wire's reach, hardly changes. So the elasticity at the steady arm rises and
// the span's elasticity becomes more uniform (max/min falls) — the reason stitch wires are
// fitted. Span 2 of the three-span catenary, a point every metre, 20 N (small enough that
// no dropper slackens: linear to 1 % against 10 N at the steady arm, checked below).
TEST(StaticElasticity, StitchWiresSoftenTheSupportsAndEvenTheSpan) {
  const model::Model& bare = shaped_catenary();
  const model::Model stitched = shape_catenary(
      {"catenary.stitch={length: 18, tension: 2800, EA: 3.5e6, EI: 11, mass_per_length: 0.31}"});
  std::vector<double> x;
  for (int i = 0; i <= 60; ++i) x.push_back(60.0 + i);
  const double F = 20.0;
  struct Curve {
    double support = 0.0, mid = 0.0, min = 1e9, max = 0.0;  // mm/N
  };
  const auto curve = [&](const model::Model& m) {
    const catenary::ElasticityReport r = catenary_elasticity(x, F, m);
    Curve c;
    for (const catenary::ElasticityPoint& p : r.points) {
      c.min = std::min(c.min, 1e3 * p.elasticity);
      c.max = std::max(c.max, 1e3 * p.elasticity);
    }
    c.support = 1e3 * r.points.front().elasticity;
    c.mid = 1e3 * r.points[30].elasticity;
    return c;
  };
  const Curve without = curve(bare), with = curve(stitched);
  for (const auto& [name, c] : {std::pair{"without", without}, std::pair{"with", with}})
    std::printf(
        "  %-7s stitch wires: steady arm %.4f, mid-span %.4f, min %.4f, max %.4f mm/N, "
        "max/min %.3f, u %.3f\n",
        name, c.support, c.mid, c.min, c.max, c.max / c.min, (c.max - c.min) / (c.max + c.min));
  EXPECT_GT(with.support, 1.3 * without.support);
  EXPECT_LT(with.max / with.min, 0.85 * without.max / without.min);
  EXPECT_NEAR(with.mid / without.mid, 1.0, 0.1);
  // 20 N measures the small-force value at the steady arm, where the stitch droppers are.
  const double small = 1e3 * catenary_elasticity({60.0}, 10.0, stitched).points[0].elasticity;
  EXPECT_NEAR(with.support / small, 1.0, 0.01);
}

}  // namespace

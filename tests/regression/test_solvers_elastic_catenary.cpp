// Elastic catenary: the ANCF cable's static equilibrium against the closed form
// (tests/support/elastic_catenary.hpp). Shape and end forces within 1e-6 relative on a
// converged mesh; the spatial convergence rate is observed, not assumed. The static
// solver's own closed-form start (solvers/statics/hanging_cable_guess.hpp) against the
// same truth, when it applies, and what it saves.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>
#include <vector>

#include "catena/solvers/statics/hanging_cable_guess.hpp"
#include "elastic_catenary.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"
#include "static_solution.hpp"

using catena::Vec3;

namespace {

struct CatenaryCase {
  Vec3 a{0, 0, 0}, b{100, 0, 10};  // inclined span, m
  double L0 = 102.0;               // unstretched length, m (slack: chord ≈ 100.5 m)
  double EA = 2.0e6, EI = 1e-2;    // N, N·m² (EI tiny: the closed form has none)
  double mu = 1.2, g = 9.81;       // kg/m, m/s²
};

struct Errors {
  double shape = 0, force = 0;
};

// A line of the case, pinned at both ends, as the tests build it; its nodes in `nodes`.
catena::model::Model case_model(const CatenaryCase& c, int n_elements, std::vector<int>& nodes) {
  catena::model::Model m;
  m.gravity = Vec3(0, 0, -c.g);
  catena::model::CableProps props;
  props.EA = c.EA;
  props.EI = c.EI;
  props.mass_per_length = c.mu;
  props.prestrain = (c.b - c.a).norm() / c.L0 - 1.0;
  nodes = catena::test::add_line(m, c.a, c.b, n_elements, props);
  catena::test::set_reference_frames(m);
  catena::test::pin(m, nodes.front());
  catena::test::pin(m, nodes.back());
  m.static_options.initial_load_step = 0.25;
  return m;
}

Errors solve_and_compare(const CatenaryCase& c, int n_elements) {
  std::vector<int> nodes;
  const catena::model::Model m = case_model(c, n_elements, nodes);
  const auto sol = catena::test::solve_static(MPI_COMM_WORLD, m);
  const catena::test::ElasticCatenary exact(c.a, c.b, c.L0, c.EA, c.mu * c.g, Vec3(0, 0, -1));
  Errors e;
  for (int i = 0; i <= n_elements; ++i) {
    const double s = c.L0 * i / n_elements;
    const Vec3 x(sol.positions[3 * nodes[i]], sol.positions[3 * nodes[i] + 1],
                 sol.positions[3 * nodes[i] + 2]);
    e.shape = std::max(e.shape, (x - exact.position(s)).norm() / c.L0);
  }
  const auto reaction = [&](int node) {
    return Vec3(sol.reaction_force[3 * node], sol.reaction_force[3 * node + 1],
                sol.reaction_force[3 * node + 2]);
  };
  const double scale = exact.reaction_a().norm();
  e.force = std::max((reaction(nodes.front()) - exact.reaction_a()).norm(),
                     (reaction(nodes.back()) - exact.reaction_b()).norm()) /
            scale;
  return e;
}

}  // namespace

TEST(ElasticCatenary, MatchesClosedFormAndConverges) {
  catena::test::ensure_petsc();
  const CatenaryCase c;
  const int meshes[] = {8, 16, 32, 64};
  std::vector<Errors> errors;
  for (int n : meshes) {
    errors.push_back(solve_and_compare(c, n));
    std::printf("  elastic catenary n = %3d: shape error %.3e, end-force error %.3e\n", n,
                errors.back().shape, errors.back().force);
  }
  // Converged mesh: within 1e-6 relative (shape against L0, forces against |t(0)|).
  EXPECT_LT(errors.back().shape, 1e-6);
  EXPECT_LT(errors.back().force, 1e-6);
  // Observed order of the shape error between the two coarsest meshes (cubic Hermite:
  // at least 3 expected; asserted ≥ 2.5).
  const double rate = std::log2(errors[0].shape / errors[1].shape);
  std::printf("  observed shape convergence rate %.2f\n", rate);
  EXPECT_GT(rate, 2.5);
}

namespace {

// The mooring line of the issue that asked for the guess: 1000 m of chain (EA 6.4e10 N,
// 120 kg/m) between anchors 800 m apart.
CatenaryCase mooring_line() {
  CatenaryCase c;
  c.b = Vec3(800, 0, 0);
  c.L0 = 1000.0;
  c.EA = 6.4e10;
  c.EI = 1e5;
  c.mu = 120.0;
  return c;
}

}  // namespace

// The solver's closed form (Irvine's, in the plane of chord and load, solved for the
// tension components) against the test's own (vector form, Greco et al.): positions along
// a slack inclined cable, a taut one and the mooring line to 1e-10 of the length, and the
// tangent dp/ds0 against central differences of the test's positions.
TEST(ElasticCatenary, SolverClosedFormMatchesTheIndependentOne) {
  CatenaryCase taut;
  taut.L0 = 100.0;  // chord 100.5 m: stretched
  for (const CatenaryCase& c : {CatenaryCase{}, taut, mooring_line()}) {
    const double q = c.mu * c.g;
    const catena::test::ElasticCatenary exact(c.a, c.b, c.L0, c.EA, q, Vec3(0, 0, -1));
    std::vector<double> s;
    for (int i = 0; i <= 20; ++i) s.push_back(c.L0 * i / 20.0);
    const auto points =
        catena::solvers::elastic_catenary_points(c.a, c.b, c.L0, c.EA, q, Vec3(0, 0, -1), s);
    ASSERT_TRUE(points.has_value());
    double position = 0.0, tangent = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      position = std::max(position, ((*points)[i].position - exact.position(s[i])).norm() / c.L0);
      // Second-order differences: central inside, one-sided (three points) at the ends.
      const double h = 1e-4 * c.L0;
      const auto p = [&](double x) { return exact.position(x); };
      Vec3 fd = (p(s[i] + h) - p(s[i] - h)) / (2 * h);
      if (i == 0) fd = (-3 * p(0) + 4 * p(h) - p(2 * h)) / (2 * h);
      if (i + 1 == s.size()) fd = (3 * p(c.L0) - 4 * p(c.L0 - h) + p(c.L0 - 2 * h)) / (2 * h);
      tangent = std::max(tangent, ((*points)[i].tangent - fd).norm());
    }
    std::printf("  L0 %g m, chord %g m: position error %.2e, tangent error %.2e\n", c.L0,
                (c.b - c.a).norm(), position, tangent);
    EXPECT_LT(position, 1e-10);
    EXPECT_LT(tangent, 1e-6);
  }
}

// The mooring line, 100 elements: from the guess the solver takes the whole load in one
// step and a few Newton iterations, where the load path from the straight reference needs
// dozens of steps; both reach the same equilibrium, which matches the closed form.
TEST(ElasticCatenary, StaticSolveFromTheGuessTakesAFewNewtonIterations) {
  catena::test::ensure_petsc();
  const CatenaryCase c = mooring_line();
  std::vector<int> nodes;
  catena::model::Model m = case_model(c, 100, nodes);
  m.static_options.initial_load_step = 0.1;
  m.static_options.max_load_steps = 2000;
  const auto path = catena::test::solve_static(MPI_COMM_WORLD, m);
  const auto guess = *catena::solvers::hanging_cable_guess(m);
  const auto fast = catena::test::solve_static(
      MPI_COMM_WORLD, m, [&](const catena::assembly::SecondOrderSystem& system, Vec q) {
        catena::solvers::set_guess(system, guess, q);
      });
  std::printf("  load path: %d steps, %d Newton iterations; from the guess: %d, %d\n",
              path.report.n_load_steps, path.report.n_newton_iterations, fast.report.n_load_steps,
              fast.report.n_newton_iterations);
  EXPECT_EQ(path.report.guess, catena::solvers::GuessOutcome::none);
  EXPECT_EQ(fast.report.guess, catena::solvers::GuessOutcome::accepted);
  EXPECT_EQ(fast.report.n_load_steps, 1);
  EXPECT_LE(fast.report.n_newton_iterations, 5);
  EXPECT_GT(path.report.n_newton_iterations, 50);
  const catena::test::ElasticCatenary exact(c.a, c.b, c.L0, c.EA, c.mu * c.g, Vec3(0, 0, -1));
  double between = 0.0, closed_form = 0.0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto at = [&](const catena::test::GatheredStatic& g) {
      const int k = nodes[i];
      return Vec3(g.positions[3 * k], g.positions[3 * k + 1], g.positions[3 * k + 2]);
    };
    between = std::max(between, (at(fast) - at(path)).norm());
    closed_form = std::max(
        closed_form, (at(fast) - exact.position(c.L0 * static_cast<double>(i) / 100.0)).norm());
  }
  std::printf("  |guess run - path run| %.2e m, |guess run - closed form| %.2e m\n", between,
              closed_form);
  EXPECT_LT(between, 1e-6);
  EXPECT_LT(closed_form, 1e-3);  // 100 elements of 10 m
}

// A guess Newton cannot use — the catenary turned upside down, an arch in compression —
// is rejected (it converges, if at all, to an unstable equilibrium) and the load path
// takes over: the same equilibrium as without the guess.
TEST(ElasticCatenary, AnUnusableGuessIsRejectedAndThePathTakesOver) {
  catena::test::ensure_petsc();
  const CatenaryCase c;
  std::vector<int> nodes;
  const catena::model::Model m = case_model(c, 16, nodes);
  auto arch = *catena::solvers::hanging_cable_guess(m);
  for (catena::solvers::NodeGuess& g : arch) {
    const Vec3 chord_point = c.a + (c.b - c.a) * ((g.position - c.a).x() / (c.b - c.a).x());
    g.position.z() = 2.0 * chord_point.z() - g.position.z();
    g.slope.z() = 2.0 * (c.b - c.a).z() / (c.b - c.a).x() * g.slope.x() - g.slope.z();
  }
  const auto plain = catena::test::solve_static(MPI_COMM_WORLD, m);
  const auto rejected = catena::test::solve_static(
      MPI_COMM_WORLD, m, [&](const catena::assembly::SecondOrderSystem& system, Vec q) {
        catena::solvers::set_guess(system, arch, q);
      });
  EXPECT_EQ(rejected.report.guess, catena::solvers::GuessOutcome::rejected);
  EXPECT_EQ(rejected.report.n_rejected_steps, plain.report.n_rejected_steps + 1);
  for (std::size_t k = 0; k < plain.positions.size(); ++k)
    EXPECT_NEAR(rejected.positions[k], plain.positions[k], 1e-9);
}

// The guess applies only to lines hanging under gravity alone between pinned ends.
TEST(ElasticCatenary, GuessAppliesOnlyToLinesHangingUnderGravityAlone) {
  const CatenaryCase c;
  std::vector<int> nodes;
  const catena::model::Model m = case_model(c, 8, nodes);
  ASSERT_TRUE(catena::solvers::hanging_cable_guess(m).has_value());
  EXPECT_EQ(catena::solvers::hanging_cable_guess(m)->size(), nodes.size());
  using Change = std::function<void(catena::model::Model&)>;
  const std::vector<std::pair<const char*, Change>> changes{
      {"a point mass",
       [&](auto& x) {
         x.point_masses.push_back({nodes[3], 1.0});
       }},
      {"a nodal load",
       [&](auto& x) {
         x.nodal_loads.push_back({nodes[3], Vec3(0, 0, -5)});
       }},
      {"a free end", [&](auto& x) { x.supports.pop_back(); }},
      {"a clamped end", [&](auto& x) { x.supports.back().slope_direction = true; }},
      {"another section",
       [&](auto& x) {
         std::get<catena::model::CableProps>(x.elements[2].props.edit()).prestrain += 1e-3;
       }},
      {"a branch",
       [&](auto& x) {
         x.nodes.push_back({999, Vec3(50, 0, -5)});
         auto element = x.elements[0];
         element.nodes = {nodes[4], static_cast<int>(x.nodes.size()) - 1};
         x.elements.push_back(element);
       }},
      {"a wind load", [&](auto& x) { x.elements[1].distributed_load = Vec3(0, 10, 0); }},
      {"no gravity", [&](auto& x) { x.gravity = Vec3::Zero(); }},
  };
  for (const auto& [what, change] : changes) {
    catena::model::Model changed = m;
    change(changed);
    EXPECT_FALSE(catena::solvers::hanging_cable_guess(changed).has_value()) << what;
  }
}

// Elastic catenary: the ANCF cable's static equilibrium against the closed form
// (tests/support/elastic_catenary.hpp). Shape and end forces within 1e-6 relative on a
// converged mesh; the spatial convergence rate is observed, not assumed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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

Errors solve_and_compare(const CatenaryCase& c, int n_elements) {
  catena::model::Model m;
  m.gravity = Vec3(0, 0, -c.g);
  catena::model::CableProps props;
  props.EA = c.EA;
  props.EI = c.EI;
  props.mass_per_length = c.mu;
  props.prestrain = (c.b - c.a).norm() / c.L0 - 1.0;
  const auto nodes = catena::test::add_line(m, c.a, c.b, n_elements, props);
  catena::test::set_reference_frames(m);
  catena::test::pin(m, nodes.front());
  catena::test::pin(m, nodes.back());
  m.static_options.initial_load_step = 0.25;

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

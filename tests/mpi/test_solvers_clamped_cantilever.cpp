// A clamp holds a slope's direction, not its length (model::Support::slope_direction):
// the Gerstmayr–Irschik cantilever (J. Sound Vib. 318 (2008) 461–487; L = 2 m, EA =
// 2.07e9 N, EI = 1.725e6 N·m², dead tip load 3 EI/L²) along an oblique axis, clamped as
// `fix: clamped` clamps, solved by the production static solver on 1, 2 and 3 ranks:
//  - the tip converges at fourth order to the continuum of the bending law (the
//    extensible elastica, extensible_elastica.hpp), whatever the axis: the slope's three
//    components share one stretch unknown, r_x = s·t;
//  - the clamp's reaction balances the load: force −P n̂ and couple −r_tip × P n̂ about
//    the root;
//  - the system's tangent (with the linked slope's coefficients) matches central
//    differences of its residual;
//  - the same answer on every rank count (against MPI_COMM_SELF).
// A clamp fixing the whole slope would hold the root's strain at zero and converge at
// first order (1.2e-5 m at 64 elements, test_elements_gerstmayr_irschik).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "extensible_elastica.hpp"
#include "fd_jacobian.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"
#include "static_solution.hpp"
#include "system_fd_jacobian.hpp"

using catena::Vec3;
namespace model = catena::model;
namespace ct = catena::test;

namespace {

constexpr double kLength = ct::kGerstmayrIrschik.length, kEA = ct::kGerstmayrIrschik.EA,
                 kEI = ct::kGerstmayrIrschik.EI, kLoad = ct::kGerstmayrIrschik.load;
// The axis and the load's direction: oblique to every global axis, orthogonal.
const Vec3 kAxis = Vec3(1, 2, 2) / 3.0, kNormal = Vec3(2, 1, -2) / 3.0;
const Vec3 kRoot(0.5, -1.0, 3.0);

model::Model cantilever(int n_elements) {
  model::Model m;
  m.gravity = Vec3::Zero();
  model::CableProps cable;
  cable.EA = kEA;
  cable.EI = kEI;
  cable.mass_per_length = 78.5;
  const auto nodes = ct::add_line(m, kRoot, kRoot + kLength * kAxis, n_elements, cable);
  ct::set_reference_frames(m);
  ct::clamp_direction(m, nodes.front());
  m.nodal_loads.push_back({nodes.back(), kLoad * kNormal});
  m.static_options.initial_load_step = 0.25;
  return m;
}

Vec3 at(const std::vector<double>& v, int node) {
  return {v[3 * static_cast<size_t>(node)], v[3 * static_cast<size_t>(node) + 1],
          v[3 * static_cast<size_t>(node) + 2]};
}

bool root_rank() {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank == 0;
}

}  // namespace

TEST(ClampedCantilever, ObliqueClampConvergesAtFourthOrder) {
  ct::ensure_petsc();
  const ct::CantileverTip exact =
      ct::elastica_tip({kLength, kEA, kEI, kLoad}, catena::CurvatureMeasure::reference_length);
  std::vector<double> errors;
  for (int n : {8, 16, 32}) {
    const model::Model m = cantilever(n);
    const ct::GatheredStatic s = ct::solve_static(MPI_COMM_WORLD, m);
    ASSERT_EQ(s.report.load_factor, 1.0) << n;  // a failed solve throws
    const Vec3 tip = at(s.positions, n) - kRoot;
    const double ux = kLength - tip.dot(kAxis), uy = tip.dot(kNormal);
    errors.push_back(std::hypot(ux - exact.ux, uy - exact.uy));
    EXPECT_LT(std::abs(tip.dot(kAxis.cross(kNormal))), 1e-9) << "stays in its plane";
    if (root_rank()) std::printf("%2d elements: tip error %.3e m\n", n, errors.back());
    // The clamped slope keeps its direction and stretches: |r_x| − 1 = N/EA = 0 at the
    // root (the section force there is P n̂, ⊥ the axis).
    const Vec3 slope = at(s.slopes, 0);
    EXPECT_LT((slope.normalized() - kAxis).norm(), 1e-12);
    // The clamp's reaction (the force and couple it applies) balances the load: −P n̂,
    // and minus the load's moment about the root.
    const Vec3 force = at(s.reaction_force, 0), moment = at(s.reaction_moment, 0);
    EXPECT_LT((force + kLoad * kNormal).norm(), 1e-6 * kLoad);
    const Vec3 load_moment = tip.cross(kLoad * kNormal);
    EXPECT_LT((moment + load_moment).norm(), 1e-6 * load_moment.norm()) << n;
  }
  for (size_t i = 0; i + 1 < errors.size(); ++i)
    EXPECT_GT(std::log2(errors[i] / errors[i + 1]), 3.5);
  EXPECT_LT(errors.back(), 1e-7);
}

TEST(ClampedCantilever, SameOnEveryRankCount) {
  ct::ensure_petsc();
  const model::Model m = cantilever(16);
  const ct::GatheredStatic world = ct::solve_static(MPI_COMM_WORLD, m);
  const ct::GatheredStatic self = ct::solve_static(MPI_COMM_SELF, m);
  EXPECT_EQ(world.n_dofs, self.n_dofs);
  EXPECT_EQ(world.n_dofs, 17 * 6 - 5);  // the clamp leaves the slope's stretch free
  double diff = 0.0;
  for (size_t i = 0; i < world.positions.size(); ++i)
    diff = std::max(diff, std::abs(world.positions[i] - self.positions[i]));
  EXPECT_LT(diff, 1e-10 * kLength);
}

// ∂f/∂q assembled with the linked slope's coefficients against central differences of the
// residual, at a deformed state (every unknown perturbed, the stretch too).
TEST(ClampedCantilever, TangentMatchesFiniteDifferences) {
  ct::ensure_petsc();
  const model::Model m = cantilever(4);
  catena::assembly::SecondOrderSystem system(PETSC_COMM_SELF, m);
  std::vector<double> x = ct::reference_unknowns(system);
  for (size_t i = 0; i < x.size(); ++i) x[i] += 1e-3 * std::sin(1.0 + static_cast<double>(i));
  // The clamped node's first slope slot is the stretch unknown, 1 at the reference.
  const PetscInt stretch = system.dof_map().global_dof(0, 3);
  ASSERT_GE(stretch, 0);
  EXPECT_EQ(system.dof_map().global_dof(0, 4), stretch);
  EXPECT_EQ(system.dof_map().global_dof(0, 5), stretch);
  EXPECT_NEAR(x[static_cast<size_t>(stretch)], 1.0, 1e-2);
  EXPECT_EQ(system.describe_dof(stretch), "node 1 (stretch of the clamped slope)");
  const ct::SystemJacobians j = ct::system_jacobians(system, x);
  EXPECT_LT(ct::relative_max_difference(j.analytic, j.finite_difference), 1e-6);
}

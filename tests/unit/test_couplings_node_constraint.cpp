// A constraint alone: its residual g and forces Gᵀλ, its matrix against finite
// differences, and the acceleration of a prescribed motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "catena/couplings/node_constraint.hpp"
#include "fd_jacobian.hpp"

namespace catena {
namespace {

using couplings::JacobianCoefficients;
using couplings::MatrixRequest;
using couplings::NodeConstraint;

model::Model two_nodes(model::ConstraintType type) {
  model::Model m;
  for (int i = 0; i < 2; ++i) {
    model::Node n;
    n.id = i + 1;
    n.position = Vec3(1.0 + i, 2.0, 3.0);
    m.nodes.push_back(n);
  }
  model::Constraint c;
  c.type = type;
  c.node_a = 0;
  if (type == model::ConstraintType::coincident) c.node_b = 1;
  c.velocity = Vec3(0.5, 0, 0);
  c.amplitude = Vec3(0, 0.1, 0.2);
  c.frequency = 1.5;
  m.constraints.push_back(c);
  return m;
}

TEST(NodeConstraint, CoincidentJoinsTwoNodes) {
  const model::Model m = two_nodes(model::ConstraintType::coincident);
  const NodeConstraint c(m, 0);
  ASSERT_EQ(c.dofs().size(), 9u);
  EXPECT_EQ(c.dofs()[0].kind, couplings::DofKey::Kind::multiplier);
  // [λ, r_A, r_B]
  const std::vector<double> q{10, 20, 30, 1.0, 2.0, 3.0, 1.5, 2.5, 3.5};
  std::vector<double> f(9);
  couplings::Scratch scratch;
  c.evaluate({q, {}, {}, 0.0}, f.data(), {}, scratch);
  const std::vector<double> expected{-0.5, -0.5, -0.5, 10, 20, 30, -10, -20, -30};
  for (size_t i = 0; i < 9; ++i) EXPECT_DOUBLE_EQ(f[i], expected[i]) << i;
}

TEST(NodeConstraint, PrescribedMotionFollowsItsTarget) {
  const model::Model m = two_nodes(model::ConstraintType::prescribed);
  const NodeConstraint c(m, 0);
  ASSERT_EQ(c.dofs().size(), 6u);
  const double t = 0.3, w = 2.0 * M_PI * 1.5;
  const Vec3 target = Vec3(1, 2, 3) + Vec3(0.5, 0, 0) * t + Vec3(0, 0.1, 0.2) * std::sin(w * t);
  const std::vector<double> q{0, 0, 0, target[0], target[1], target[2]};
  std::vector<double> f(6);
  couplings::Scratch scratch;
  c.evaluate({q, {}, {}, t}, f.data(), {}, scratch);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], 0.0, 1e-14);
  // The acceleration is the target's second derivative (central differences).
  const double h = 1e-4;
  auto target_at = [&](double s) -> Vec3 {
    return Vec3(0.5, 0, 0) * s + Vec3(0, 0.1, 0.2) * std::sin(w * s);
  };
  const Vec3 fd = (target_at(t + h) - 2.0 * target_at(t) + target_at(t - h)) / (h * h);
  std::array<double, 3> target_a{};
  c.acceleration_target({q, {}, {}, t}, target_a);
  const Vec3 a(target_a[0], target_a[1], target_a[2]);
  EXPECT_LT((a - fd).norm(), 1e-5 * fd.norm());
  const NodeConstraint pinned(two_nodes(model::ConstraintType::pinned), 0);
  std::array<double, 3> none{1.0, 1.0, 1.0};
  pinned.acceleration_target({q, {}, {}, t}, none);
  EXPECT_EQ(Vec3(none[0], none[1], none[2]).norm(), 0.0);
}

TEST(NodeConstraint, MatrixIsLambdaGTransposePlusGAndMatchesFiniteDifferences) {
  const model::Model m = two_nodes(model::ConstraintType::coincident);
  const NodeConstraint c(m, 0);
  const std::vector<double> q{10, -20, 30, 1.0, 2.1, 3.0, 1.5, 2.5, 3.5};
  couplings::Scratch scratch;
  auto residual = [&](const std::vector<double>& x, std::vector<double>& f) {
    f.assign(9, 0.0);
    c.evaluate({x, {}, {}, 0.0}, f.data(), {}, scratch);
  };
  const std::vector<double> fd = test::central_difference_jacobian(residual, q, 9);
  std::vector<double> J(81), L(81);
  const MatrixRequest requests[2] = {{couplings::kStaticJacobian, J.data()},
                                     {JacobianCoefficients{0.0, 0.0, 0.0, 1.0, 0.0}, L.data()}};
  c.evaluate({q, {}, {}, 0.0}, nullptr, requests, scratch);
  EXPECT_LT(test::relative_max_difference(J, fd), 1e-9);
  // Gᵀ alone: the multiplier columns of the nodal rows only.
  for (int r = 0; r < 9; ++r)
    for (int col = 0; col < 9; ++col)
      if (r < 3 || col >= 3) {
        EXPECT_EQ(L[r * 9 + col], 0.0) << r << "," << col;
      }
  // Every nonzero lies in the declared pattern.
  std::vector<std::pair<int, int>> entries;
  c.pattern(entries);
  for (int r = 0; r < 9; ++r)
    for (int col = 0; col < 9; ++col)
      if (J[r * 9 + col] != 0.0) {
        EXPECT_NE(std::find(entries.begin(), entries.end(), std::pair{r, col}), entries.end());
      }
}

}  // namespace
}  // namespace catena

// A rigid body's frame constraints alone (couplings/body_frame_constraint.hpp): g and Gᵀλ
// at an orthonormal and a distorted frame, the whole matrix (Σ λ_k H_k, Gᵀ, G) against
// central differences, its pattern, and the acceleration target γ against the second
// time derivative of g along a trajectory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "catena/couplings/body_frame_constraint.hpp"
#include "fd_jacobian.hpp"

namespace catena {
namespace {

using couplings::BodyFrameConstraint;
using couplings::MatrixRequest;

model::Model one_body() {
  model::Model m;
  m.nodes.push_back(model::Node{1, Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()});
  for (const auto type :
       {model::ConstraintType::frame_lengths, model::ConstraintType::frame_angles}) {
    model::Constraint c;
    c.type = type;
    c.node_a = 0;
    m.constraints.push_back(c);
  }
  return m;
}

// [λ (3), e1, e2, e3] with the axes of a rotation about (1, 2, 3) by 0.7 rad, each
// distorted by `distortion`.
std::vector<double> state(double distortion) {
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<double> q{3.0, -2.0, 0.5};
  for (int a = 0; a < 3; ++a)
    for (int d = 0; d < 3; ++d) q.push_back(R(d, a) + distortion * std::sin(1.0 + 3 * a + d));
  return q;
}

TEST(BodyFrameConstraint, VanishesOnAnOrthonormalFrameAndMeasuresADistortedOne) {
  const model::Model m = one_body();
  couplings::Scratch scratch;
  for (int c = 0; c < 2; ++c) {
    const BodyFrameConstraint frame(m, c);
    ASSERT_EQ(frame.dofs().size(), 12u);
    EXPECT_FALSE(frame.linear());
    std::vector<double> f(12);
    frame.evaluate({state(0.0), {}, {}, 0.0}, f.data(), {}, scratch);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], 0.0, 1e-15) << c << " " << k;
    const std::vector<double> q = state(0.05);
    frame.evaluate({q, {}, {}, 0.0}, f.data(), {}, scratch);
    auto axis = [&](int a) { return Vec3(q[3 + 3 * a], q[4 + 3 * a], q[5 + 3 * a]); };
    if (c == 0)
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], 0.5 * (axis(k).squaredNorm() - 1.0), 1e-15);
    else {
      EXPECT_NEAR(f[0], axis(1).dot(axis(2)), 1e-15);
      EXPECT_NEAR(f[1], axis(2).dot(axis(0)), 1e-15);
      EXPECT_NEAR(f[2], axis(0).dot(axis(1)), 1e-15);
    }
  }
}

TEST(BodyFrameConstraint, MatrixMatchesFiniteDifferencesAndLiesInItsPattern) {
  const model::Model m = one_body();
  couplings::Scratch scratch;
  for (int c = 0; c < 2; ++c) {
    const BodyFrameConstraint frame(m, c);
    const std::vector<double> q = state(0.05);
    auto residual = [&](const std::vector<double>& x, std::vector<double>& f) {
      f.assign(12, 0.0);
      frame.evaluate({x, {}, {}, 0.0}, f.data(), {}, scratch);
    };
    const std::vector<double> fd = test::central_difference_jacobian(residual, q, 12);
    std::vector<double> J(144);
    const MatrixRequest request[1] = {{couplings::kStaticJacobian, J.data()}};
    frame.evaluate({q, {}, {}, 0.0}, nullptr, request, scratch);
    EXPECT_LT(test::relative_max_difference(J, fd), 1e-9) << c;
    // The parts by their coefficients: c_K alone is Σ λ_k H_k, symmetric, nodal block only.
    std::vector<double> K(144);
    const MatrixRequest only_k[1] = {{{1.0, 0.0, 0.0, 0.0, 0.0}, K.data()}};
    frame.evaluate({q, {}, {}, 0.0}, nullptr, only_k, scratch);
    for (int r = 0; r < 12; ++r)
      for (int col = 0; col < 12; ++col) {
        EXPECT_EQ(K[r * 12 + col], K[col * 12 + r]);
        if (r < 3 || col < 3) {
          EXPECT_EQ(K[r * 12 + col], 0.0);
        }
      }
    std::vector<std::pair<int, int>> entries;
    frame.pattern(entries);
    for (int r = 0; r < 12; ++r)
      for (int col = 0; col < 12; ++col)
        if (J[r * 12 + col] != 0.0 || K[r * 12 + col] != 0.0) {
          EXPECT_NE(std::find(entries.begin(), entries.end(), std::pair{r, col}), entries.end())
              << c << ": " << r << "," << col;
        }
  }
}

// Along e_k(t) (any smooth motion, rigid or not), d²g/dt² = G ë + vᵀ H v, so
// γ = −vᵀ H v = G ë − d²g/dt²: both sides by central differences in t.
TEST(BodyFrameConstraint, AccelerationTargetIsGAccelerationMinusTheSecondDerivativeOfG) {
  const model::Model m = one_body();
  couplings::Scratch scratch;
  auto q_at = [](double t) {
    std::vector<double> q{0.0, 0.0, 0.0};
    for (int k = 0; k < 9; ++k) q.push_back(std::cos(0.3 * k) + 0.4 * std::sin((1.0 + k) * t));
    return q;
  };
  const double t = 0.8, h = 1e-4;
  std::vector<double> v(12, 0.0), a(12, 0.0);
  for (int k = 3; k < 12; ++k) {
    v[k] = (q_at(t + h)[k] - q_at(t - h)[k]) / (2 * h);
    a[k] = (q_at(t + h)[k] - 2 * q_at(t)[k] + q_at(t - h)[k]) / (h * h);
  }
  for (int c = 0; c < 2; ++c) {
    const BodyFrameConstraint frame(m, c);
    auto g = [&](double s) {
      std::vector<double> f(12);
      frame.evaluate({q_at(s), {}, {}, 0.0}, f.data(), {}, scratch);
      return std::vector<double>(f.begin(), f.begin() + 3);
    };
    std::vector<double> G(144);
    const MatrixRequest request[1] = {{{0.0, 0.0, 0.0, 0.0, 1.0}, G.data()}};
    const std::vector<double> q = q_at(t);
    frame.evaluate({q, {}, {}, 0.0}, nullptr, request, scratch);
    std::array<double, 3> target{};
    frame.acceleration_target({q, v, {}, t}, target);
    const std::vector<double> gp = g(t + h), g0 = g(t), gm = g(t - h);
    for (int k = 0; k < 3; ++k) {
      double Ga = 0.0;
      for (int col = 3; col < 12; ++col) Ga += G[k * 12 + col] * a[col];
      const double g_tt = (gp[k] - 2 * g0[k] + gm[k]) / (h * h);
      EXPECT_NEAR(target[static_cast<size_t>(k)], Ga - g_tt, 1e-5) << c << " " << k;
    }
  }
}

}  // namespace
}  // namespace catena

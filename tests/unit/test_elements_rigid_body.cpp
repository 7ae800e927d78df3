// The rigid body's inertia in natural coordinates (elements/rigid_body.hpp) against a body
// made of point masses: for any rates (ṙ, ė1, ė2, ė3) — rigid or not — the kinetic energy
// ½ vᵀ M v equals Σ ½ m_i |ṙ + ξ_ik ė_k|², and the weight equals Σ m_i g at the points
// x_i = r + ξ_ik e_k, with m, centre of mass and inertia tensor computed from the points.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/elements/rigid_body.hpp"

namespace catena {
namespace {

struct Particle {
  double m;
  Vec3 xi;  // body coordinates from the body's point r
};

std::vector<Particle> cloud() {
  std::vector<Particle> p;
  for (int i = 0; i < 7; ++i)
    p.push_back(
        {0.5 + 0.3 * i, Vec3(std::sin(1.3 * i) + 0.2, 0.7 * std::cos(2.1 * i), 0.4 * i - 1.0)});
  return p;
}

TEST(RigidBodyInertia, KineticEnergyAndWeightEqualThoseOfItsPointMasses) {
  const std::vector<Particle> points = cloud();
  double m = 0.0;
  Vec3 first = Vec3::Zero();
  for (const Particle& p : points) {
    m += p.m;
    first += p.m * p.xi;
  }
  const Vec3 c = first / m;
  Mat3 inertia = Mat3::Zero();  // about the centre of mass: Σ m (|ρ|² 1 − ρ ρᵀ)
  for (const Particle& p : points) {
    const Vec3 rho = p.xi - c;
    inertia += p.m * (rho.squaredNorm() * Mat3::Identity() - rho * rho.transpose());
  }
  const Vec3 g(0.3, -0.2, -9.81);
  const elements::RigidBodyInertia body(m, c, inertia, g);
  std::vector<double> M(144);
  body.mass(M.data());
  for (int trial = 0; trial < 3; ++trial) {
    std::vector<double> v(12);
    for (int k = 0; k < 12; ++k) v[k] = std::sin(0.7 * k + 1.9 * trial) * (1.0 + k % 3);
    double from_matrix = 0.0;
    for (int r = 0; r < 12; ++r)
      for (int col = 0; col < 12; ++col) from_matrix += 0.5 * v[r] * M[r * 12 + col] * v[col];
    double from_points = 0.0;
    for (const Particle& p : points) {
      Vec3 rate(v[0], v[1], v[2]);
      for (int k = 0; k < 3; ++k) rate += p.xi[k] * Vec3(v[3 + 3 * k], v[4 + 3 * k], v[5 + 3 * k]);
      from_points += 0.5 * p.m * rate.squaredNorm();
    }
    EXPECT_NEAR(from_matrix, from_points, 1e-12 * from_points) << trial;
  }
  // f = −∂(potential)/∂q·(−1): the generalised weight Σ m_i g ⊗ (1, ξ_i), negated.
  std::vector<double> f(12), K(144, 1.0);
  const std::vector<double> q(12, 0.0);
  body.evaluate({q, {}, elements::LoadPath(1.0)}, {true, true, false},
                {f.data(), K.data(), nullptr});
  for (int d = 0; d < 3; ++d) {
    double weight = 0.0;
    for (const Particle& p : points) weight += p.m * g[d];
    EXPECT_NEAR(f[d], -weight, 1e-12 * m * g.norm());
    for (int k = 0; k < 3; ++k) {
      double generalised = 0.0;
      for (const Particle& p : points) generalised += p.m * p.xi[k] * g[d];
      EXPECT_NEAR(f[3 + 3 * k + d], -generalised, 1e-12 * m * g.norm()) << k << " " << d;
    }
  }
  for (double k : K) EXPECT_EQ(k, 0.0);
}

}  // namespace
}  // namespace catena

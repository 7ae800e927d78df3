// The cut end of a tensioned cable (elements/absorbing_end.hpp): its dashpot has the line's
// axial impedance √(EA m') along the end force and its transverse impedance √(T m'/λ)
// across it, its force is C v − F₀, and K = ∂f/∂q (zero), C = ∂f/∂v against central
// differences. That the dashpot absorbs the waves of a real line: the app test
// absorbing_end (tests/app/check_absorbing_end.py).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/elements/absorbing_end.hpp"
#include "element_checks.hpp"

namespace catena {
namespace {

using elements::AbsorbingEnd;
using elements::cable_end_law;

constexpr double kEA = 1.8e7, kMass = 1.35, kT = 2.0e4;

TEST(AbsorbingEnd, DashpotHasTheLineImpedancesAlongAndAcrossTheEndForce) {
  const Vec3 t = Vec3(0.9, -0.3, 0.2).normalized();
  const elements::AbsorbingEndLaw law = cable_end_law(kT * t, kEA, kMass);
  const double axial = std::sqrt(kEA * kMass);                       // 4929.5 N s/m
  const double transverse = std::sqrt(kT * kMass / (1 + kT / kEA));  // 164.2 N s/m
  EXPECT_NEAR(axial, 4929.5, 0.1);
  EXPECT_NEAR(transverse, 164.23, 0.01);
  const Vec3 n1 = t.cross(Vec3::UnitZ()).normalized(), n2 = t.cross(n1);
  EXPECT_NEAR((law.damping * t - axial * t).norm(), 0.0, 1e-9 * axial);
  EXPECT_NEAR((law.damping * n1 - transverse * n1).norm(), 0.0, 1e-9 * axial);
  EXPECT_NEAR((law.damping * n2 - transverse * n2).norm(), 0.0, 1e-9 * axial);
  EXPECT_NEAR((law.damping - law.damping.transpose()).norm(), 0.0, 1e-12 * axial);
  EXPECT_NEAR((law.force - kT * t).norm(), 0.0, 1e-12 * kT);
}

TEST(AbsorbingEnd, ForceIsDashpotMinusEndForceAndJacobiansMatchDifferences) {
  const Vec3 F(1.9e4, 300.0, -2500.0), G(0.0, 0.4, -1.5);
  elements::AbsorbingEndLaw law = cable_end_law(F, kEA, kMass);
  law.slope_force = G;
  const AbsorbingEnd end(law);
  // [r, r_x]: the slope's velocity meets no dashpot.
  const std::vector<double> q{60.0, 0.1, -0.2, 1.0, 0.01, -0.02}, v{0.3, -1.2, 0.7, 0.5, -0.4, 0.2};
  const std::vector<double> f = test::element_force(end, q, v, 1.0);
  const Vec3 expected = end.law().damping * Vec3(v[0], v[1], v[2]) - F;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(f[k], expected[k], 1e-9 * F.norm()) << k;
    EXPECT_DOUBLE_EQ(f[3 + k], -G[k]) << k;
  }
  const std::vector<double> at_rest = test::element_force(end, q, {}, 1.0);
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(at_rest[k], -F[k]) << k;
  const test::JacobianCheck check = test::check_element_jacobians(end, q, v, 1.0);
  EXPECT_LT(check.stiffness, 1e-8);
  EXPECT_LT(check.damping, 1e-8);
}

TEST(AbsorbingEnd, WithoutItsLawItDoesNothing) {
  // Until the system calibrates it from the run's initial state.
  const AbsorbingEnd end(elements::AbsorbingEndLaw{});
  const std::vector<double> f =
      test::element_force(end, {1.0, 2.0, 3.0, 1.0, 0.0, 0.0}, {4.0, 5.0, 6.0, 0.1, 0.2, 0.3}, 1.0);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(f[k], 0.0);
  EXPECT_TRUE(end.has_damping());  // asked once, at the system's construction
}

}  // namespace
}  // namespace catena

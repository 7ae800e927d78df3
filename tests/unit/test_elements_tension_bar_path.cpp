// A bar whose unstretched length l0 differs from its mesh length L (a shaped dropper)
// moves from L to l0 along the static load path with the loads: no force in the
// reference configuration at λ = 0, N = EA (l/l0 − 1) at λ = 1, the Jacobian exact at
// every point of the path, and mass and weight from l0 throughout.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "catena/elements/tension_bar.hpp"
#include "element_checks.hpp"

namespace el = catena::elements;
using catena::Vec3;

namespace {

constexpr double kMesh = 1.2, kL0 = 0.7, kEA = 7.0e4;  // m, m, N (a dropper, k = 1e5 N/m)

el::TensionBar shaped_dropper() {
  return el::TensionBar(kL0, {kEA, 0.2, 0.0, true}, Vec3(0, 0, -10), kMesh);
}

double axial_force(const el::TensionBar& bar, double length, double loads) {
  const std::vector<double> q = {0, 0, 0, 0, 0, length};
  return bar.section_result({q, {}, el::LoadPath(1.0, loads, 1.0)}).axial_force;
}

}  // namespace

TEST(TensionBarOnTheLoadPath, UnstretchedLengthMovesFromMeshLengthWithTheLoads) {
  const el::TensionBar bar = shaped_dropper();
  EXPECT_EQ(axial_force(bar, kMesh, 0.0), 0.0);  // stress-free reference
  EXPECT_NEAR(axial_force(bar, kMesh, 1.0), kEA * (kMesh / kL0 - 1.0), 1e-9);
  const double l0_half = kMesh + 0.5 * (kL0 - kMesh);
  EXPECT_NEAR(axial_force(bar, kMesh, 0.5), kEA * (kMesh / l0_half - 1.0), 1e-9);
  // Tension-only against the unstretched length of the path point.
  EXPECT_EQ(axial_force(bar, 0.9, 0.0), 0.0);
  EXPECT_GT(axial_force(bar, 0.9, 1.0), 0.0);
  // Without a mesh length the bar is at l0 everywhere on the path.
  const el::TensionBar plain(kL0, {kEA, 0.2, 0.0, true}, Vec3(0, 0, -10));
  EXPECT_NEAR(axial_force(plain, kMesh, 0.0), kEA * (kMesh / kL0 - 1.0), 1e-9);
}

TEST(TensionBarOnTheLoadPath, MassAndWeightFromTheUnstretchedLength) {
  const el::TensionBar bar = shaped_dropper();
  std::vector<double> M(36);
  bar.mass(M.data());
  EXPECT_DOUBLE_EQ(M[0], 0.5 * 0.2 * kL0);
  const auto f = catena::test::element_force(bar, {0, 0, 0, 0, 0, kMesh}, {}, 1.0);
  EXPECT_NEAR(f[2], -kEA * (kMesh / kL0 - 1.0) + 0.5 * 0.2 * kL0 * 10, 1e-9);
}

TEST(TensionBarOnTheLoadPath, JacobianMatchesFiniteDifferencesAlongThePath) {
  const el::TensionBar bar = shaped_dropper();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (const double loads : {0.0, 0.3, 1.0}) {
    std::vector<double> q = {0, 0, 0, 0.05, 0.02, 1.1}, v(6, 0.0);
    for (double& x : q) x += u(rng);
    const auto c = catena::test::check_element_jacobians(bar, q, v, el::LoadPath(1.0, loads, 1.0));
    EXPECT_LT(c.stiffness, 1e-6) << "loads " << loads;
  }
}

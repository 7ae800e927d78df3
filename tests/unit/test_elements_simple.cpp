// Bars, springs, point masses and nodal forces: Jacobians vs FD, slack behaviour.
#include <gtest/gtest.h>

#include <random>

#include "catena/elements/linear_spring.hpp"
#include "catena/elements/point_mass.hpp"
#include "catena/elements/tension_bar.hpp"
#include "element_checks.hpp"

using catena::Vec3;
namespace el = catena::elements;

TEST(TensionBar, JacobiansMatchFiniteDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  const el::TensionBar bar(1.2, {1e5, 0.5, 30.0, false}, Vec3(0, 0, -9.81));
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<double> q = {0, 0, 0, 0.3, 0.2, 1.3}, v(6);
    for (double& x : q) x += u(rng);
    for (double& x : v) x = 10 * u(rng);
    const auto c = catena::test::check_element_jacobians(bar, q, v, 0.7);
    EXPECT_LT(c.stiffness, 1e-6);
    EXPECT_LT(c.damping, 1e-6);
  }
}

TEST(TensionBar, SlackBarCarriesNoForce) {
  const el::TensionBar bar(1.0, {1e5, 0.0, 30.0, true}, Vec3::Zero());
  const std::vector<double> q = {0, 0, 0, 0, 0, 0.9}, v = {0, 0, 0, 0, 0, 1.0};
  for (double f : catena::test::element_force(bar, q, v, 1.0)) EXPECT_EQ(f, 0.0);
  EXPECT_EQ(bar.section_result({q, {}, {}}).axial_force, 0.0);
  // Taut: N = EA ε.
  const std::vector<double> taut = {0, 0, 0, 0, 0, 1.01};
  EXPECT_NEAR(bar.section_result({taut, {}, {}}).axial_force, 1e5 * 0.01, 1e-6);
}

TEST(TensionBar, LumpedMassAndWeight) {
  const el::TensionBar bar(2.0, {1e5, 0.3, 0.0, false}, Vec3(0, 0, -10));
  std::vector<double> M(36);
  bar.mass(M.data());
  EXPECT_DOUBLE_EQ(M[0], 0.3);
  EXPECT_DOUBLE_EQ(M[35], 0.3);
  const auto f = catena::test::element_force(bar, {0, 0, 0, 0, 0, 2.0}, {}, 1.0);
  EXPECT_NEAR(f[2], 3.0, 1e-12);  // f = −λ m g: weight 3 N downward → +3 in f
}

TEST(LinearSpring, JacobiansAndForces) {
  const el::LinearSpring spring(Vec3(0, 0, 0), Vec3(1, 0, 0), {Vec3(1e3, 2e3, 3e3), Vec3(1, 2, 3)});
  const std::vector<double> q = {0.1, 0, 0, 1.3, 0.2, -0.1}, v = {0, 1, 0, 0, 0, 2};
  const auto c = catena::test::check_element_jacobians(spring, q, v, 1.0);
  EXPECT_LT(c.stiffness, 1e-8);
  EXPECT_LT(c.damping, 1e-8);
  const auto f = catena::test::element_force(spring, q, v, 1.0);
  EXPECT_NEAR(f[3], 1e3 * 0.2, 1e-9);          // stretch 0.2 beyond the reference offset
  EXPECT_NEAR(f[4], 2e3 * 0.2 - 2 * 1, 1e-9);  // k Δy + c Δv_y
}

TEST(GroundSpring, ForceAndJacobian) {
  const el::GroundSpring gs(Vec3(1, 2, 3), {Vec3(0, 0, 5e4), Vec3(0, 0, 10)});
  const std::vector<double> q = {1, 2, 3.01}, v = {0, 0, 0.5};
  const auto f = catena::test::element_force(gs, q, v, 1.0);
  EXPECT_NEAR(f[2], 5e4 * 0.01 + 10 * 0.5, 1e-9);
  const auto c = catena::test::check_element_jacobians(gs, q, v, 1.0);
  EXPECT_LT(c.stiffness, 1e-8);
}

TEST(PointMassAndNodalForce, ScaleWithLoadFactor) {
  const el::PointMass m(2.0, Vec3(0, 0, -9.81));
  EXPECT_NEAR(catena::test::element_force(m, {0, 0, 0}, {}, 0.5)[2], 0.5 * 2.0 * 9.81, 1e-12);
  const el::NodalForce load(Vec3(0, 0, 100));
  EXPECT_NEAR(catena::test::element_force(load, {0, 0, 0}, {}, 0.25)[2], -25.0, 1e-12);
}

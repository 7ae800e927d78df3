// A node against a rigid plane (elements/surface_contact.hpp): no force on the free side or
// when the damping would pull; in contact the normal force k·(−g) − c·ġ along n, friction
// μN against the sliding velocity (regularised), and K = ∂f/∂x, C = ∂f/∂v against central
// differences, sliding, creeping inside the stick range and without friction, on a plane
// whose normal is not a coordinate axis.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "catena/elements/surface_contact.hpp"
#include "fd_jacobian.hpp"

namespace catena {
namespace {

using elements::LocalOutput;
using elements::LocalState;
using elements::Request;
using elements::SurfaceContact;
using elements::SurfaceContactLaw;

SurfaceContactLaw tilted(double friction) {
  SurfaceContactLaw law;
  law.point = Vec3(0.3, -0.2, 1.0);
  law.normal = Vec3(0.2, -0.1, 1.0).normalized();
  law.stiffness = 5.0e4;
  law.damping = 120.0;
  law.friction = friction;
  law.stick_speed = 0.05;
  return law;
}

std::vector<double> force(const SurfaceContact& c, const std::vector<double>& x,
                          const std::vector<double>& v) {
  std::vector<double> f(3);
  c.evaluate(LocalState{x, v, {}}, Request{true, false, false}, LocalOutput{f.data()});
  return f;
}

// A point `depth` behind the plane (negative: in front), moved along the plane by `along`.
std::vector<double> at(const SurfaceContactLaw& law, double depth, const Vec3& along) {
  const Vec3 x = law.point - depth * law.normal.normalized() + along;
  return {x[0], x[1], x[2]};
}

TEST(SurfaceContact, NoForceOnTheFreeSideOrWhenTheDashpotWouldPull) {
  const SurfaceContactLaw law = tilted(0.4);
  const SurfaceContact c(law);
  const Vec3 n = law.normal.normalized();
  const std::vector<double> away{n[0], n[1], n[2]};  // 1 m/s off the plane
  for (double f : force(c, at(law, -1e-3, Vec3(0.1, 0.2, 0.0)), {0.5, 0.0, -0.3}))
    EXPECT_EQ(f, 0.0);
  // 1 mm deep (50 N of spring), leaving at 1 m/s (120 N of dashpot): no pull.
  for (double f : force(c, at(law, 1e-3, Vec3::Zero()), away)) EXPECT_EQ(f, 0.0);
  EXPECT_EQ(c.normal_force(at(law, 1e-3, Vec3::Zero()), away), 0.0);
  EXPECT_NEAR(c.normal_force(at(law, 1e-3, Vec3::Zero()), {}), 50.0, 1e-9);
}

TEST(SurfaceContact, ForceIsTheLaw) {
  const SurfaceContactLaw law = tilted(0.4);
  const SurfaceContact c(law);
  const Vec3 n = law.normal.normalized();
  const Vec3 slide = Vec3(1.0, 2.0, 0.0) - Vec3(1.0, 2.0, 0.0).dot(n) * n;  // along the plane
  const Vec3 velocity = slide - 0.1 * n;                                    // and into it
  const std::vector<double> v{velocity[0], velocity[1], velocity[2]};
  const std::vector<double> f = force(c, at(law, 2e-3, Vec3::Zero()), v);
  const double N = 5.0e4 * 2e-3 + 120.0 * 0.1;
  const Vec3 expected =
      -N * n + 0.4 * N * slide / std::sqrt(slide.squaredNorm() + 0.05 * 0.05);  // f = −F
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[static_cast<size_t>(k)], expected[k], 1e-10);
}

TEST(SurfaceContact, JacobiansMatchCentralDifferences) {
  for (const double friction : {0.0, 0.4}) {
    const SurfaceContactLaw law = tilted(friction);
    const SurfaceContact c(law);
    const Vec3 n = law.normal.normalized();
    const Vec3 slide = Vec3(0.7, -0.4, 0.2) - Vec3(0.7, -0.4, 0.2).dot(n) * n;
    // Sliding fast, and creeping inside the stick range (|v_t| below the stick speed).
    for (const double scale : {1.0, 0.03}) {
      const Vec3 velocity = scale * slide - 0.05 * n;
      const std::vector<double> x = at(law, 3e-3, Vec3(0.1, 0.0, -0.02));
      const std::vector<double> v{velocity[0], velocity[1], velocity[2]};
      std::vector<double> K(9), C(9), f(3);
      c.evaluate(LocalState{x, v, {}}, Request{true, true, true},
                 LocalOutput{f.data(), K.data(), C.data()});
      const auto by_x = [&](const std::vector<double>& y, std::vector<double>& out) {
        out = force(c, y, v);
      };
      const auto by_v = [&](const std::vector<double>& w, std::vector<double>& out) {
        out = force(c, x, w);
      };
      EXPECT_LT(test::relative_max_difference(K, test::central_difference_jacobian(by_x, x, 3)),
                1e-7)
          << "friction " << friction << ", slide " << scale;
      EXPECT_LT(
          test::relative_max_difference(C, test::central_difference_jacobian(by_v, v, 3, 1e-7)),
          1e-6)
          << "friction " << friction << ", slide " << scale;
    }
  }
}

TEST(SurfaceContact, NothingOutOfContactAndNoMass) {
  const SurfaceContact c(tilted(0.4));
  std::vector<double> K(9, 1.0), C(9, 1.0), M(9, 1.0), f(3, 1.0);
  c.evaluate(LocalState{at(tilted(0.4), -0.01, Vec3::Zero()), std::vector<double>{1, 2, 3}, {}},
             Request{true, true, true}, LocalOutput{f.data(), K.data(), C.data()});
  c.mass(M.data());
  for (const auto* a : {&K, &C, &M, &f})
    for (double x : *a) EXPECT_EQ(x, 0.0);
}

}  // namespace
}  // namespace catena

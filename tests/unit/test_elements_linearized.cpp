// An element linearised about a state (elements/linearized.hpp) against the nonlinear
// element it wraps: at the state itself the same force, stiffness and damping; nearby its
// force differs from the nonlinear one by O(|Δq|²) (the error falls 4-fold when Δq
// halves), and its matrices stay those of the state whatever the current one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "catena/elements/ancf_cable.hpp"
#include "catena/elements/linearized.hpp"
#include "element_checks.hpp"

using catena::Vec3;
namespace el = catena::elements;

namespace {

constexpr double kLength = 0.5;
// A contact-wire section at 20 kN with Kelvin–Voigt damping (so C ≠ 0).
const el::CableSection kWire{1.8e7, 195.0, 1.35, 1e-3, 20000.0 / 1.8e7};

std::unique_ptr<el::Element> cable() {
  return std::make_unique<el::AncfCable>(kLength, kWire, Vec3(0, 0, -9.81), Vec3::Zero());
}

// A sagging, slightly twisted state (not the reference) to linearise about.
std::vector<double> bent_state() {
  return {0, 0, 0, 0.999, 0.01, -0.04, kLength, 0.003, -0.01, 1.001, -0.005, 0.04};
}

double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace

TEST(Linearized, EqualsTheElementAtItsState) {
  const std::vector<double> q0 = bent_state();
  const el::Linearized linear(cable(), q0);
  const auto inner = cable();
  std::vector<double> f(12), K(144), C(144), f0(12), K0(144), C0(144), M(144), M0(144);
  linear.evaluate({q0, {}, {}}, {true, true, true}, {f.data(), K.data(), C.data()});
  inner->evaluate({q0, {}, {}}, {true, true, true}, {f0.data(), K0.data(), C0.data()});
  linear.mass(M.data());
  inner->mass(M0.data());
  EXPECT_EQ(f, f0);
  EXPECT_EQ(K, K0);
  EXPECT_EQ(C, C0);
  EXPECT_EQ(M, M0);
  EXPECT_GT(*std::max_element(C0.begin(), C0.end()), 0.0);  // the damping is exercised
}

TEST(Linearized, ForceIsSecondOrderCloseAndMatricesStayConstant) {
  const std::vector<double> q0 = bent_state();
  const el::Linearized linear(cable(), q0);
  const auto inner = cable();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> direction(12), velocity(12);
  for (double& x : direction) x = 1e-3 * u(rng);
  for (double& x : velocity) x = 0.1 * u(rng);
  std::vector<double> K0(144), C0(144), f_unused(12);
  inner->evaluate({q0, {}, {}}, {false, true, true}, {f_unused.data(), K0.data(), C0.data()});
  double previous = 0.0;
  for (const double scale : {4.0, 2.0, 1.0}) {
    std::vector<double> q = q0;
    for (int i = 0; i < 12; ++i) q[i] += scale * direction[i];
    // Without velocity: the force's error is the curvature of f, O(|Δq|²).
    const std::vector<double> f_lin = catena::test::element_force(linear, q, {}, el::LoadPath());
    const std::vector<double> f_nl = catena::test::element_force(*inner, q, {}, el::LoadPath());
    const double error = max_abs_difference(f_lin, f_nl);
    if (previous > 0.0) {
      const double ratio = previous / error;
      EXPECT_GT(ratio, 3.6) << "scale " << scale;
      EXPECT_LT(ratio, 4.4) << "scale " << scale;
    }
    previous = error;
    // The velocity's force is C0 v at any state; the matrices are those of q0.
    const std::vector<double> f_v =
        catena::test::element_force(linear, q, velocity, el::LoadPath());
    for (int i = 0; i < 12; ++i) {
      double cv = 0.0;
      for (int j = 0; j < 12; ++j) cv += C0[i * 12 + j] * velocity[j];
      EXPECT_NEAR(f_v[i] - f_lin[i], cv, 1e-9 * (1.0 + std::abs(cv)));
    }
    std::vector<double> K(144), C(144), f(12);
    linear.evaluate({q, velocity, {}}, {true, true, true}, {f.data(), K.data(), C.data()});
    EXPECT_EQ(K, K0);
    EXPECT_EQ(C, C0);
  }
}

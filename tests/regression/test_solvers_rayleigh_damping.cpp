// Rayleigh damping D = α M + β K_ref gives a mode of the linearised system the damping
// ratio ζ(ω) = α/(2ω) + βω/2 (Clough & Penzien). The taut wire's first mode, plucked at
// small amplitude and integrated by the trapezoidal rule (HHT with α = 0: no numerical
// damping), decays at that ratio: ζ is measured from the logarithmic decrement of the
// mid-span's successive maxima over four periods, for a mass-proportional, a
// stiffness-proportional and a mixed pair of coefficients.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "petsc_test_session.hpp"

namespace model = catena::model;

namespace {

// ζ measured on the taut wire with Rayleigh coefficients (α, β) on every element.
double measured_first_mode_ratio(double alpha, double beta, double& omega) {
  const catena::test::TautString string;
  omega = 2.0 * std::numbers::pi * string.first_frequency();
  model::Model m = string.model();
  for (model::ElementDesc& e : m.elements)
    std::get<model::CableProps>(e.props.edit()).rayleigh = {alpha, beta};
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  string.pluck(system, q.get(), 0.01);
  catena::solvers::HhtOptions options;
  options.alpha = 0.0;
  const double period = 2.0 * std::numbers::pi / omega, dt = period / 400.0;
  catena::solvers::HhtIntegrator hht(system, options);
  hht.set_state(0.0, q.get(), v.get(), nullptr);
  const PetscInt g = system.dof_map().global_dof(string.n / 2, 2);
  // Successive maxima of the mid-span displacement, refined by the parabola through the
  // three samples around each.
  std::vector<double> peaks;
  double z0 = catena::test::global_value(system.comm(), hht.q(), g), z1 = z0;
  while (peaks.size() < 5 && hht.time() < 10.0 * period) {
    catena::test::advance_fixed(hht, dt, 1);
    const double z2 = catena::test::global_value(system.comm(), hht.q(), g);
    if (z1 > z0 && z1 >= z2 && z1 > 0) {
      const double curvature = z0 - 2 * z1 + z2, slope = 0.5 * (z2 - z0);
      peaks.push_back(z1 - 0.5 * slope * slope / curvature);
    }
    z0 = z1;
    z1 = z2;
  }
  EXPECT_EQ(peaks.size(), 5u);
  // δ = ln(A_k / A_{k+1}) = 2πζ / √(1 − ζ²).
  const double delta =
      std::log(peaks.front() / peaks.back()) / static_cast<double>(peaks.size() - 1);
  return delta / std::sqrt(4.0 * std::numbers::pi * std::numbers::pi + delta * delta);
}

}  // namespace

TEST(RayleighDamping, TautWireFirstModeDecaysAtTheRayleighRatio) {
  catena::test::ensure_petsc();
  const double omega = 2.0 * std::numbers::pi * catena::test::TautString{}.first_frequency();
  struct Case {
    const char* label;
    double alpha, beta;
  };
  // ζ = 0.02 at ω1 from each term alone and 0.01 + 0.01 from both.
  const Case cases[] = {{"mass", 0.04 * omega, 0.0},
                        {"stiffness", 0.0, 0.04 / omega},
                        {"mixed", 0.02 * omega, 0.02 / omega}};
  for (const Case& c : cases) {
    double w = 0.0;
    const double zeta = measured_first_mode_ratio(c.alpha, c.beta, w);
    const double expected = c.alpha / (2.0 * w) + c.beta * w / 2.0;
    std::printf("  %-9s alpha %.4g 1/s, beta %.4g s: zeta %.6f (expected %.6f)\n", c.label, c.alpha,
                c.beta, zeta, expected);
    EXPECT_NEAR(zeta, expected, 0.01 * expected) << c.label;
  }
}

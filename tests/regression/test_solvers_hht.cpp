// HHT-α on an undamped oscillator (a point mass on an elastic support) through the whole
// system (assembly, SNES, MUMPS): observed order 2 against the exact solution, exact
// energy conservation of the trapezoidal rule (α = 0), and the spectral radius at
// h·ω → ∞ against (1 + α)/(1 − α).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

using catena::Vec3;
namespace model = catena::model;

namespace {

constexpr double kMass = 2.0;
constexpr double kOmega = 2.0 * std::numbers::pi;  // period 1 s
constexpr double kX0 = 0.1;                        // m, initial displacement

struct History {
  std::vector<double> x, v;
};

History simulate(double alpha, double dt, int n_steps, double atol = 1e-8) {
  const model::Model m = catena::test::oscillator(kMass, kOmega);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  const PetscInt g = system.dof_map().global_dof(0, 0);
  catena::test::set_global_value(q.get(), g, kX0);
  catena::solvers::HhtOptions options;
  options.alpha = alpha;
  options.atol = atol;
  catena::solvers::HhtIntegrator hht(system, options);
  hht.set_state(0.0, q.get(), v.get(), nullptr);
  History run;
  run.x.push_back(catena::test::global_value(system.comm(), hht.q(), g));
  run.v.push_back(catena::test::global_value(system.comm(), hht.v(), g));
  for (int i = 0; i < n_steps; ++i) {
    catena::test::advance_fixed(hht, dt, 1);
    run.x.push_back(catena::test::global_value(system.comm(), hht.q(), g));
    run.v.push_back(catena::test::global_value(system.comm(), hht.v(), g));
  }
  return run;
}

}  // namespace

TEST(Hht, SecondOrderOnTheOscillator) {
  catena::test::ensure_petsc();
  for (double alpha : {0.0, -0.1, -1.0 / 3.0}) {
    std::vector<double> errors;
    for (int n : {64, 128, 256}) {
      const History run = simulate(alpha, 1.0 / n, n);
      // Error of the whole state (x, v/ω) at t = 1 s: x alone sits at a turning point
      // there, where a phase error enters only quadratically.
      const double x_exact = kX0 * std::cos(kOmega), v_exact = -kX0 * kOmega * std::sin(kOmega);
      errors.push_back(std::hypot(run.x.back() - x_exact, (run.v.back() - v_exact) / kOmega));
    }
    const double order = std::log2(errors[1] / errors[2]);
    std::printf("  alpha %+.3f: errors %.3e %.3e %.3e, observed order %.2f\n", alpha, errors[0],
                errors[1], errors[2], order);
    EXPECT_NEAR(order, 2.0, 0.3);
  }
}

TEST(Hht, TrapezoidalRuleConservesEnergy) {
  catena::test::ensure_petsc();
  const History run = simulate(0.0, 1.0 / 50, 10000);
  const double k = kMass * kOmega * kOmega;
  const double e0 = 0.5 * k * kX0 * kX0;
  double worst = 0.0;
  for (size_t i = 0; i < run.x.size(); ++i) {
    const double e = 0.5 * kMass * run.v[i] * run.v[i] + 0.5 * k * run.x[i] * run.x[i];
    worst = std::max(worst, std::abs(e - e0) / e0);
  }
  std::printf("  alpha = 0, 10^4 steps: worst relative energy drift %.2e\n", worst);
  EXPECT_LT(worst, 1e-10);
}

TEST(Hht, SpectralRadiusAtInfiniteStiffness) {
  catena::test::ensure_petsc();
  for (double alpha : {-0.05, -0.1, -0.2, -1.0 / 3.0}) {
    // h·ω = 1e4. Fit log|z_n| = a + n log ρ + c log n over the tail, z the energy norm:
    // the limit's eigenvalue may be double, which adds the n factor.
    const History run = simulate(alpha, 1e4 / kOmega, 120, 0.0);
    const int first = 20, last = 120;
    Eigen::MatrixXd A(last - first + 1, 3);
    Eigen::VectorXd b(last - first + 1);
    for (int n = first; n <= last; ++n) {
      const double z = std::hypot(run.x[n], run.v[n] / kOmega);
      A.row(n - first) << 1.0, n, std::log(static_cast<double>(n));
      b(n - first) = std::log(z);
    }
    const Eigen::Vector3d fit = A.colPivHouseholderQr().solve(b);
    const double rho = std::exp(fit(1)), expected = (1 + alpha) / (1 - alpha);
    std::printf("  alpha %+.3f: spectral radius %.5f (theory %.5f)\n", alpha, rho, expected);
    EXPECT_NEAR(rho, expected, 2e-3);
  }
}

TEST(Hht, RejectsAlphaOutsideRange) {
  catena::test::ensure_petsc();
  const model::Model m = catena::test::oscillator(kMass, kOmega);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::solvers::HhtOptions options;
  options.alpha = -0.4;
  EXPECT_THROW(catena::solvers::HhtIntegrator(system, options), catena::InputError);
  options.alpha = 0.1;
  EXPECT_THROW(catena::solvers::HhtIntegrator(system, options), catena::InputError);
}

TEST(Hht, TautWireFirstFrequency) {
  // Pinned pre-tensioned wire plucked in its first mode (small amplitude, linear regime):
  // the period of the mid-span motion against the tensioned Euler–Bernoulli beam
  // (catena::test::TautString). Within 0.1 %; 60 elements put the converged discrete
  // frequency 2.3e-5 above the closed form (test_solvers_irk), and the trapezoidal rule's
  // period elongation at 400 steps per period, −(ωh)²/12 = −2.1e-5, happens to offset it.
  catena::test::ensure_petsc();
  const catena::test::TautString string;
  const double f1 = string.first_frequency();
  const model::Model m = string.model();
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  string.pluck(system, q.get(), 0.01);
  catena::solvers::HhtOptions options;
  options.alpha = 0.0;
  const double dt = 1.0 / (f1 * 400);
  catena::solvers::HhtIntegrator hht(system, options);
  hht.set_state(0.0, q.get(), v.get(), nullptr);
  // Downward zero crossings of the mid-span displacement, linearly interpolated.
  const PetscInt g = system.dof_map().global_dof(string.n / 2, 2);
  std::vector<double> crossings;
  double previous = catena::test::global_value(system.comm(), hht.q(), g);
  while (crossings.size() < 4) {
    catena::test::advance_fixed(hht, dt, 1);
    const double z = catena::test::global_value(system.comm(), hht.q(), g);
    if (previous > 0 && z <= 0) crossings.push_back(hht.time() - dt * z / (z - previous));
    previous = z;
  }
  const double period =
      (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  std::printf("  taut wire: f1 = %.6f Hz (closed form %.6f Hz, difference %.2e)\n", 1 / period, f1,
              (1 / period - f1) / f1);
  EXPECT_NEAR(1 / period, f1, 1e-3 * f1);
}

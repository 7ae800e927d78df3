// Implicit Runge–Kutta (K-form) through the whole system (assembly, SNES, MUMPS) for every
// tableau: observed order on the undamped oscillator against its exact solution, the
// taut string's first frequency against the closed form, Gauss's conservation of a linear
// system's energy, the Radau IIA embedded estimate's order, dense output, and simplified
// Newton's reuse of one factorisation over many steps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;
using catena::test::global_value;

namespace {

constexpr double kMass = 2.0;
constexpr double kOmega = 2.0 * std::numbers::pi;  // period 1 s
constexpr double kX0 = 0.1;                        // m

using Method = catena::test::TableauChoice;

std::string method_name(const testing::TestParamInfo<Method>& info) {
  return catena::test::tableau_label(info.param);
}

solvers::IrkOptions options_for(const Method& m) {
  solvers::IrkOptions o;
  o.family = m.family;
  o.stages = m.stages;
  o.atol = 1e-13;  // the oscillator is linear: Newton reaches round-off in one iteration
  o.rtol = 1e-14;
  return o;
}

// Error of the state (x, v/ω) at t = 1 s after n steps.
double oscillator_error(const Method& method, int n) {
  const catena::model::Model m = catena::test::oscillator(kMass, kOmega);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  const PetscInt g = system.dof_map().global_dof(0, 0);
  catena::test::set_global_value(q.get(), g, kX0);
  solvers::IrkIntegrator irk(system, options_for(method));
  irk.set_state(0.0, q.get(), v.get(), nullptr);
  catena::test::advance_fixed(irk, 1.0 / n, n);
  const double x = global_value(MPI_COMM_WORLD, irk.q(), g);
  const double vx = global_value(MPI_COMM_WORLD, irk.v(), g);
  return std::hypot(x - kX0 * std::cos(kOmega), (vx + kX0 * kOmega * std::sin(kOmega)) / kOmega);
}

class EveryMethod : public testing::TestWithParam<Method> {};

TEST_P(EveryMethod, ObservedOrderOnTheOscillator) {
  catena::test::ensure_petsc();
  const Method method = GetParam();
  const int p = solvers::make_tableau(method.family, method.stages).order;
  // The first step-count pair in the asymptotic range (error < 1e-3) whose finer error is
  // still well above round-off (> 1e-12).
  double coarse = oscillator_error(method, 4);
  for (int n = 4; n <= 2048; n *= 2) {
    const double fine = oscillator_error(method, 2 * n);
    if (coarse < 1e-3 && fine > 1e-12) {
      const double order = std::log2(coarse / fine);
      std::printf("  %s: n = %d, %d: errors %.3e %.3e, observed order %.2f (theory %d)\n",
                  catena::test::tableau_label(method).c_str(), n, 2 * n, coarse, fine, order, p);
      EXPECT_NEAR(order, p, 0.3);
      return;
    }
    coarse = fine;
  }
  ADD_FAILURE() << "no step-count pair in the asymptotic range";
}

TEST_P(EveryMethod, TautStringFirstFrequency) {
  // Mid-span zero crossings of the plucked first mode: frequency within 0.1 % of the
  // closed form (60 elements: the high-order methods converge to 2.3e-5 above it).
  catena::test::ensure_petsc();
  const Method method = GetParam();
  const catena::test::TautString string;
  const double f1 = string.first_frequency();
  const catena::model::Model m = string.model();
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  string.pluck(system, q.get(), 0.01);
  solvers::IrkOptions o = options_for(method);
  o.atol = 1e-8;
  o.rtol = 1e-10;
  solvers::IrkIntegrator irk(system, o);
  irk.set_state(0.0, q.get(), v.get(), nullptr);
  const PetscInt g = system.dof_map().global_dof(string.n / 2, 2);
  // 50 steps per period for order ≥ 3; the first- and second-order methods need 400 for
  // their phase error, O((ωh)²), to fall well below 0.1 %.
  const int p = solvers::make_tableau(method.family, method.stages).order;
  const double dt = 1.0 / (f1 * (p >= 3 ? 50 : 400));
  std::vector<double> crossings;
  double previous = global_value(MPI_COMM_WORLD, irk.q(), g);
  while (crossings.size() < 3) {
    catena::test::advance_fixed(irk, dt, 1);
    const double z = global_value(MPI_COMM_WORLD, irk.q(), g);
    if (previous > 0 && z <= 0) {
      // Refine the crossing on the dense output by bisection.
      double a = irk.previous_time(), b = irk.time();
      catena::VecHandle qi = system.create_vector();
      for (int it = 0; it < 50; ++it) {
        const double mid = 0.5 * (a + b);
        irk.interpolate(mid, qi.get(), nullptr);
        (global_value(MPI_COMM_WORLD, qi.get(), g) > 0 ? a : b) = mid;
      }
      crossings.push_back(0.5 * (a + b));
    }
    previous = z;
  }
  const double period = (crossings.back() - crossings.front()) / 2.0;
  std::printf("  %s: f1 = %.6f Hz (closed form %.6f, difference %.2e)\n",
              catena::test::tableau_label(method).c_str(), 1 / period, f1, (1 / period - f1) / f1);
  EXPECT_NEAR(1 / period, f1, 1e-3 * f1);
}

INSTANTIATE_TEST_SUITE_P(Catena, EveryMethod, testing::ValuesIn(catena::test::every_tableau()),
                         method_name);

}  // namespace

TEST(Irk, GaussConservesTheEnergyOfALinearSystem) {
  // Gauss methods conserve quadratic invariants exactly: 2·10^4 steps of 1/50 period (400
  // periods; a method that damps or excites, Radau IIA or a non-symplectic explicit one,
  // is off by orders of magnitude more than 1e-10 long before).
  catena::test::ensure_petsc();
  const catena::model::Model m = catena::test::oscillator(kMass, kOmega);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  const PetscInt g = system.dof_map().global_dof(0, 0);
  catena::test::set_global_value(q.get(), g, kX0);
  solvers::IrkIntegrator irk(system, options_for({solvers::TableauFamily::gauss, 2}));
  irk.set_state(0.0, q.get(), v.get(), nullptr);
  const double k = kMass * kOmega * kOmega, e0 = 0.5 * k * kX0 * kX0;
  double worst = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    catena::test::advance_fixed(irk, 1.0 / 50, 1);
    if (i % 100 != 99) continue;
    const double x = global_value(MPI_COMM_WORLD, irk.q(), g);
    const double vx = global_value(MPI_COMM_WORLD, irk.v(), g);
    worst = std::max(worst, std::abs(0.5 * kMass * vx * vx + 0.5 * k * x * x - e0) / e0);
  }
  const auto& c = irk.counters();
  std::printf(
      "  gauss_2, 2e4 steps: worst relative energy error %.2e; %ld factorisations, "
      "%ld Newton iterations\n",
      worst, c.factorizations, c.newton_iterations);
  EXPECT_LT(worst, 1e-10);
  // Simplified Newton keeps one factorisation for the whole constant-step run.
  EXPECT_EQ(c.factorizations, 1);
}

TEST(Irk, RadauEmbeddedEstimateHasOrderSPlusOne) {
  catena::test::ensure_petsc();
  for (int s : {1, 3, 5}) {
    const catena::model::Model m = catena::test::oscillator(kMass, kOmega);
    catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
    catena::VecHandle q = system.create_vector(), v = system.create_vector();
    system.reference_state(q.get());
    catena::test::set_global_value(q.get(), system.dof_map().global_dof(0, 0), kX0);
    solvers::IrkIntegrator irk(system, options_for({solvers::TableauFamily::radau_iia, s}));
    solvers::ErrorTolerance tol;  // atol only: the estimate's size in metres
    tol.rtol = 0.0;
    tol.atol = 1.0;
    std::vector<double> estimates;
    for (double h : {0.02, 0.01}) {
      irk.set_state(0.0, q.get(), v.get(), nullptr);
      estimates.push_back(irk.attempt(h, &tol).error);
    }
    const double order = std::log2(estimates[0] / estimates[1]);
    std::printf("  radau_iia_%d: estimates %.3e %.3e, order %.2f (theory %d)\n", s, estimates[0],
                estimates[1], order, s + 1);
    EXPECT_NEAR(order, s + 1, 0.3);
  }
}

TEST(Irk, DenseOutputIsContinuousAndAccurate) {
  // Between step ends the dense output of Radau IIA (s = 3) follows the exact solution to
  // the collocation polynomial's order, and meets the step's end values exactly.
  catena::test::ensure_petsc();
  const catena::model::Model m = catena::test::oscillator(kMass, kOmega);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector(),
                    qi = system.create_vector(), vi = system.create_vector();
  system.reference_state(q.get());
  const PetscInt g = system.dof_map().global_dof(0, 0);
  catena::test::set_global_value(q.get(), g, kX0);
  solvers::IrkIntegrator irk(system, options_for({solvers::TableauFamily::radau_iia, 3}));
  irk.set_state(0.0, q.get(), v.get(), nullptr);
  double worst = 0.0, end_gap = 0.0;
  for (int i = 0; i < 50; ++i) {
    catena::test::advance_fixed(irk, 0.02, 1);
    for (double theta : {0.25, 0.5, 0.75}) {
      const double t = irk.previous_time() + theta * 0.02;
      irk.interpolate(t, qi.get(), vi.get());
      worst = std::max(
          worst, std::abs(global_value(MPI_COMM_WORLD, qi.get(), g) - kX0 * std::cos(kOmega * t)));
    }
    irk.interpolate(irk.time(), qi.get(), vi.get());
    end_gap = std::max(end_gap, std::abs(global_value(MPI_COMM_WORLD, qi.get(), g) -
                                         global_value(MPI_COMM_WORLD, irk.q(), g)));
  }
  std::printf("  radau_iia_3 dense output: worst error %.2e m, gap at step ends %.1e m\n", worst,
              end_gap);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(end_gap, 1e-14);
}

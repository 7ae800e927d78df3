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
#include "catena/solvers/hht_integrator.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

using catena::Vec3;
namespace model = catena::model;

namespace {

constexpr double kMass = 2.0;
constexpr double kOmega = 2.0 * std::numbers::pi;  // period 1 s
constexpr double kX0 = 0.1;                          // m, initial displacement

model::Model oscillator() {
  model::Model m;
  m.gravity = Vec3::Zero();
  m.nodes.push_back({1, Vec3(0, 0, 0), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()});
  m.point_masses.push_back({0, kMass});
  const double k = kMass * kOmega * kOmega;
  m.elastic_supports.push_back({0, Vec3(k, k, k), Vec3::Zero()});
  return m;
}

// Value of the x DOF of node 0 on every rank.
double x_of(const catena::assembly::SecondOrderSystem& system, Vec q) {
  const PetscInt g = system.dof_map().global_dof(0, 0);
  PetscInt lo = 0, hi = 0;
  VecGetOwnershipRange(q, &lo, &hi);
  double local = 0.0, value = 0.0;
  if (g >= lo && g < hi) VecGetValues(q, 1, &g, &local);
  MPI_Allreduce(&local, &value, 1, MPI_DOUBLE, MPI_SUM, system.comm());
  return value;
}

struct History {
  std::vector<double> x, v;
};

History simulate(double alpha, double dt, int n_steps, double atol = 1e-8) {
  const model::Model m = oscillator();
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  const PetscInt g = system.dof_map().global_dof(0, 0);
  PetscInt lo = 0, hi = 0;
  VecGetOwnershipRange(q.get(), &lo, &hi);
  if (g >= lo && g < hi) VecSetValue(q.get(), g, kX0, INSERT_VALUES);
  VecAssemblyBegin(q.get());
  VecAssemblyEnd(q.get());
  catena::solvers::HhtOptions options;
  options.alpha = alpha;
  options.dt = dt;
  options.atol = atol;
  catena::solvers::HhtIntegrator hht(system, options);
  hht.initialize(0.0, q.get(), v.get());
  History run;
  run.x.push_back(x_of(system, hht.q()));
  run.v.push_back(x_of(system, hht.v()));
  for (int i = 0; i < n_steps; ++i) {
    hht.step();
    run.x.push_back(x_of(system, hht.q()));
    run.v.push_back(x_of(system, hht.v()));
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
  const model::Model m = oscillator();
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::solvers::HhtOptions options;
  options.alpha = -0.4;
  EXPECT_THROW(catena::solvers::HhtIntegrator(system, options), catena::InputError);
  options.alpha = 0.1;
  EXPECT_THROW(catena::solvers::HhtIntegrator(system, options), catena::InputError);
}

TEST(Hht, TautWireFirstFrequency) {
  // Pinned pre-tensioned wire plucked in its first mode (small amplitude, linear regime):
  // the period of the mid-span motion against the tensioned Euler–Bernoulli beam,
  // f₁ = 1/(2L)·sqrt(T/μ)·sqrt(1 + π²EI/(TL²)) (../shared/reference/analytic.md), with μ
  // the mass per tensioned length (Catena's μ is per unstretched length). Within 0.1 %.
  catena::test::ensure_petsc();
  const double L = 60.0, T = 20000.0, EA = 1.8e7, EI = 195.0, mu = 1.35, A = 0.01;
  const double eps = T / EA;
  const double mu_tensioned = mu / (1.0 + eps);
  const double f1 = 1.0 / (2 * L) * std::sqrt(T / mu_tensioned) *
                    std::sqrt(1 + std::numbers::pi * std::numbers::pi * EI / (T * L * L));
  const int n = 60;
  model::Model m;
  m.gravity = Vec3::Zero();
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {L, 0, 0}, n,
                                            model::CableProps{EA, EI, mu, 0.0, eps});
  catena::test::set_reference_frames(m);
  catena::test::pin(m, nodes.front());
  catena::test::pin(m, nodes.back());
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  // First mode shape: z = A sin(πx/L), slope ∂z/∂x = A π/L cos(πx/L).
  const auto& dofs = system.dof_map();
  PetscInt lo = 0, hi = 0;
  VecGetOwnershipRange(q.get(), &lo, &hi);
  for (int i = 0; i <= n; ++i) {
    const double x = L * i / n, k = std::numbers::pi / L;
    const PetscInt gz = dofs.global_dof(i, 2), gs = dofs.global_dof(i, 5);
    if (gz >= lo && gz < hi) VecSetValue(q.get(), gz, A * std::sin(k * x), INSERT_VALUES);
    if (gs >= lo && gs < hi) VecSetValue(q.get(), gs, A * k * std::cos(k * x), INSERT_VALUES);
  }
  VecAssemblyBegin(q.get());
  VecAssemblyEnd(q.get());
  catena::solvers::HhtOptions options;
  options.alpha = 0.0;
  options.dt = 1.0 / (f1 * 400);
  catena::solvers::HhtIntegrator hht(system, options);
  hht.initialize(0.0, q.get(), v.get());
  // Downward zero crossings of the mid-span displacement, linearly interpolated.
  auto mid_z = [&] {
    const PetscInt g = dofs.global_dof(n / 2, 2);
    double local = 0.0, value = 0.0;
    if (g >= lo && g < hi) VecGetValues(hht.q(), 1, &g, &local);
    MPI_Allreduce(&local, &value, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return value;
  };
  std::vector<double> crossings;
  double previous = mid_z();
  while (crossings.size() < 4) {
    hht.step();
    const double z = mid_z();
    if (previous > 0 && z <= 0)
      crossings.push_back(hht.time() - options.dt * z / (z - previous));
    previous = z;
  }
  const double period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
  std::printf("  taut wire: f1 = %.6f Hz (closed form %.6f Hz, difference %.2e)\n", 1 / period,
              f1, (1 / period - f1) / f1);
  EXPECT_NEAR(1 / period, f1, 1e-3 * f1);
}

// The multistep integrators (MultistepIntegrator: variable-step BDF and Park's method)
// through the whole system (assembly, SNES, MUMPS) on a point mass on an elastic support,
// x'' = −ω² x, against independent truth:
// - observed orders at fixed steps against the exact solution: 1 (BDF-1), 2 (BDF-2, Park);
// - at constant steps the solution's growth per step is the largest root of the method's
//   characteristic polynomial ρ(z)² + (hω)² z^{2k} = 0 (ρ from the published constant-step
//   coefficients, not from the code under test): decay for the A-stable BDF-2 and Park,
//   growth for BDF-3 at hω = 1 (not A-stable: Dahlquist's barrier);
// - the embedded error estimate against the true local error of one step taken from the
//   exact solution's history;
// - Adams–Bashforth–Moulton (PECE, AdamsPeceIntegrator) the same way: orders 1 and 2, the
//   growth per step of its recurrence (decay inside its stability limit hω = 1.28, growth
//   outside), Milne's estimate, and the limit it reports from ω_max and the damping rate.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/multistep/adams_pece_integrator.hpp"
#include "catena/solvers/time/multistep/multistep_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;

namespace {

constexpr double kMass = 2.0;
constexpr double kOmega = 2.0 * std::numbers::pi;  // period 1 s
constexpr double kX0 = 0.1;                        // m, at rest

struct Method {
  solvers::MultistepFamily family;
  int order;
  const char* label;
};

solvers::MultistepOptions options_of(const Method& m) {
  solvers::MultistepOptions o;
  o.family = m.family;
  o.order = m.order;
  o.atol = 1e-13;
  o.rtol = 1e-14;
  o.max_newton_iterations = 20;
  return o;
}

// The oscillator and one integrator on it, started from (x0, 0) at t = 0.
struct Oscillator {
  catena::model::Model model = catena::test::oscillator(kMass, kOmega);  // outlives the system
  catena::assembly::SecondOrderSystem system{MPI_COMM_WORLD, model};
  PetscInt g = system.dof_map().global_dof(0, 0);

  catena::VecHandle state(double x, double v) {
    catena::VecHandle q = system.create_vector();
    system.reference_state(q.get());
    catena::test::set_global_value(q.get(), g, x);
    catena::VecHandle u = system.create_vector();
    catena::test::set_global_value(u.get(), g, v);
    velocity_ = std::move(u);
    return q;
  }
  Vec velocity() const { return velocity_.get(); }
  double x(Vec q) const { return catena::test::global_value(system.comm(), q, g); }

 private:
  catena::VecHandle velocity_;
};

// x0 cos(ωt + φ): from rest with φ = 0.
double exact_x(double t, double phase = 0.0) { return kX0 * std::cos(kOmega * t + phase); }
double exact_v(double t, double phase = 0.0) {
  return -kOmega * kX0 * std::sin(kOmega * t + phase);
}

// The largest root magnitude of ρ(z)² + (hω)² z^{2k}, ρ(z) = Σ_j a_j z^{k−j} with the
// constant-step coefficients a (h·w) of the formula.
double largest_root(const std::vector<double>& a, double wh) {
  const int k = static_cast<int>(a.size()) - 1;
  // Coefficients of z^{2k} ... z^0 of ρ(z)².
  std::vector<double> p(static_cast<std::size_t>(2 * k + 1), 0.0);
  for (int i = 0; i <= k; ++i)
    for (int j = 0; j <= k; ++j) p[static_cast<std::size_t>(i + j)] += a[i] * a[j];
  p[0] += wh * wh;
  const int n = 2 * k;
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) companion(0, j) = -p[static_cast<std::size_t>(j + 1)] / p[0];
  for (int i = 1; i < n; ++i) companion(i, i - 1) = 1.0;
  double largest = 0.0;
  for (const std::complex<double>& z : companion.eigenvalues())
    largest = std::max(largest, std::abs(z));
  return largest;
}

}  // namespace

TEST(Multistep, ObservedOrdersOnTheOscillator) {
  catena::test::ensure_petsc();
  const Method methods[] = {{solvers::MultistepFamily::bdf, 1, "bdf1"},
                            {solvers::MultistepFamily::bdf, 2, "bdf2"},
                            {solvers::MultistepFamily::park, 2, "park"}};
  for (const Method& method : methods) {
    std::vector<double> errors;
    for (int n : {100, 200, 400}) {
      Oscillator o;
      catena::VecHandle q = o.state(kX0, 0.0);
      solvers::MultistepIntegrator in(o.system, options_of(method));
      in.set_state(0.0, q.get(), o.velocity(), nullptr);
      catena::test::advance_fixed(in, 1.0 / n, n);
      const double ex = o.x(in.q()) - exact_x(1.0);
      const double ev = (o.x(in.v()) - exact_v(1.0)) / kOmega;
      errors.push_back(std::hypot(ex, ev));
    }
    const double p1 = std::log2(errors[0] / errors[1]), p2 = std::log2(errors[1] / errors[2]);
    std::printf("%-5s errors %.3e %.3e %.3e m, observed orders %.3f %.3f\n", method.label,
                errors[0], errors[1], errors[2], p1, p2);
    EXPECT_NEAR(p2, method.order, 0.1) << method.label;
  }
}

TEST(Multistep, GrowthPerStepIsTheCharacteristicRoot) {
  catena::test::ensure_petsc();
  struct Case {
    Method method;
    std::vector<double> a;  // constant-step h·w (published)
    double wh;
  };
  const Case cases[] = {
      {{solvers::MultistepFamily::bdf, 2, "bdf2"}, {1.5, -2.0, 0.5}, 0.5},
      {{solvers::MultistepFamily::bdf, 2, "bdf2"}, {1.5, -2.0, 0.5}, 2.0},
      {{solvers::MultistepFamily::park, 2, "park"}, {10.0 / 6, -2.5, 1.0, -1.0 / 6}, 0.5},
      {{solvers::MultistepFamily::park, 2, "park"}, {10.0 / 6, -2.5, 1.0, -1.0 / 6}, 2.0},
      {{solvers::MultistepFamily::bdf, 3, "bdf3"}, {11.0 / 6, -3.0, 1.5, -1.0 / 3}, 1.0},
  };
  for (const Case& c : cases) {
    Oscillator o;
    catena::VecHandle q = o.state(kX0, 0.0);
    solvers::MultistepIntegrator in(o.system, options_of(c.method));
    in.set_state(0.0, q.get(), o.velocity(), nullptr);
    const double h = c.wh / kOmega;
    std::vector<double> x{o.x(in.q())};
    for (int i = 0; i < 120; ++i) {
      catena::test::advance_fixed(in, h, 1);
      x.push_back(o.x(in.q()));
    }
    // For a sequence dominated by one root pair r e^{±iθ}, x_n² − x_{n+1} x_{n−1} ∝ r^{2n};
    // from step 40 on the start's and the parasitic roots have died out.
    auto casorati = [&](int n) {
      return x[static_cast<std::size_t>(n)] * x[static_cast<std::size_t>(n)] -
             x[static_cast<std::size_t>(n + 1)] * x[static_cast<std::size_t>(n - 1)];
    };
    const double measured = std::pow(casorati(110) / casorati(50), 1.0 / (2.0 * 60));
    const double expected = largest_root(c.a, c.wh);
    std::printf("%-5s omega h = %.1f: growth per step %.6f, characteristic root %.6f\n",
                c.method.label, c.wh, measured, expected);
    EXPECT_NEAR(measured, expected, 1e-4) << c.method.label << " at omega h = " << c.wh;
    if (c.method.order == 3)
      EXPECT_GT(measured, 1.0) << "BDF-3 grows on the imaginary axis";
    else
      EXPECT_LT(measured, 1.0) << c.method.label << " damps";
  }
}

// One step from the exact history (q and v of the exact solution at the formula's past
// times, given through the restart interface): the estimate against q₁ − x(t₁). The phase
// π/4 keeps every derivative of the solution of the same size near t = 0, so the leading
// term of each error dominates (from rest, x''' ∝ sin ωt is small there and BDF-2's
// leading term with it).
TEST(Multistep, EmbeddedEstimateMatchesTheLocalError) {
  catena::test::ensure_petsc();
  const Method methods[] = {{solvers::MultistepFamily::bdf, 1, "bdf1"},
                            {solvers::MultistepFamily::bdf, 2, "bdf2"},
                            {solvers::MultistepFamily::bdf, 3, "bdf3"},
                            {solvers::MultistepFamily::park, 2, "park"}};
  for (const Method& method : methods) {
    for (const double wh : {0.02, 0.01}) {
      const double h = wh / kOmega;
      Oscillator o;
      constexpr double phase = std::numbers::pi / 4;
      catena::VecHandle q = o.state(exact_x(0.0, phase), exact_v(0.0, phase));
      // Run a few steps for a complete history, then put the exact solution into it.
      solvers::MultistepIntegrator first(o.system, options_of(method));
      first.set_state(0.0, q.get(), o.velocity(), nullptr);
      catena::test::advance_fixed(first, h, 4);
      catena::solvers::ResumeState saved;
      first.save_resume_state(saved);
      std::vector<catena::VecHandle> exact;
      const auto known = saved.integer("multistep.known");
      for (std::int64_t j = 0; j < known; ++j) {
        const std::string i = std::to_string(j);
        const double t = saved.real("multistep.t" + i);
        exact.push_back(o.state(exact_x(t, phase), exact_v(t, phase)));
        saved.vectors["multistep.q" + i] = exact.back().get();
        exact.push_back(o.system.create_vector());
        VecCopy(o.velocity(), exact.back().get());
        saved.vectors["multistep.v" + i] = exact.back().get();
      }
      const double t0 = saved.real("multistep.t0");
      catena::VecHandle q0 = o.state(exact_x(t0, phase), exact_v(t0, phase));
      solvers::MultistepIntegrator in(o.system, options_of(method));
      in.set_state(t0, q0.get(), o.velocity(), nullptr);
      in.restore_resume_state(saved);
      solvers::ErrorTolerance tol;
      tol.rtol = 1e-300;
      tol.atol = 1.0;
      catena::VecHandle reference = o.system.create_vector();
      o.system.reference_state(reference.get());
      tol.reference = reference.get();
      const solvers::StepOutcome out = in.attempt(h, &tol);
      ASSERT_TRUE(out.converged) << method.label;
      PetscInt size = 0;
      VecGetSize(in.q(), &size);
      // The weighted norm of the estimate with atol = 1: |e_x| / sqrt(N).
      const double estimate = out.error * std::sqrt(static_cast<double>(size));
      const double local = std::abs(o.x(in.pending_q()) - exact_x(t0 + h, phase));
      std::printf("%-5s omega h = %.2f: estimate %.3e m, local error %.3e m, ratio %.3f\n",
                  method.label, wh, estimate, local, estimate / local);
      EXPECT_GT(estimate / local, 0.9) << method.label << " at omega h = " << wh;
      EXPECT_LT(estimate / local, 1.1) << method.label << " at omega h = " << wh;
    }
  }
}

namespace {

// An integrator of either kind, for the tests shared by both.
std::unique_ptr<solvers::TimeIntegrator> make_adams(catena::assembly::SecondOrderSystem& system,
                                                    int order) {
  solvers::AdamsPeceOptions o;
  o.order = order;
  return std::make_unique<solvers::AdamsPeceIntegrator>(system, o);
}

// The largest root of PECE's recurrence for y' = z y, AB weights b, AM weights a (constant
// steps, published coefficients), over z = ±i hω.
double pece_largest_root(const std::vector<double>& b, const std::vector<double>& a, double wh) {
  const std::complex<double> z(0.0, wh);
  const int k = static_cast<int>(b.size());
  // c[i]: coefficient of y_{n+1−i}: y_{n+1} = y_n + z a₀ (y_n + z Σ b_j y_{n−j}) + z Σ a_j
  // y_{n+1−j}.
  std::vector<std::complex<double>> c(static_cast<std::size_t>(k + 1), 0.0);
  c[0] = 1.0;
  c[1] -= 1.0 + z * a[0];
  for (int j = 0; j < k; ++j) c[static_cast<std::size_t>(1 + j)] -= z * a[0] * z * b[j];
  for (int j = 1; j < k; ++j) c[static_cast<std::size_t>(j)] -= z * a[j];
  Eigen::MatrixXcd companion = Eigen::MatrixXcd::Zero(k, k);
  for (int j = 0; j < k; ++j) companion(0, j) = -c[static_cast<std::size_t>(j + 1)] / c[0];
  for (int i = 1; i < k; ++i) companion(i, i - 1) = 1.0;
  double largest = 0.0;
  for (const std::complex<double>& r : companion.eigenvalues())
    largest = std::max(largest, std::abs(r));
  return largest;
}

}  // namespace

TEST(AdamsPece, ObservedOrdersOnTheOscillator) {
  catena::test::ensure_petsc();
  for (int order : {1, 2}) {
    std::vector<double> errors;
    for (int n : {100, 200, 400}) {
      Oscillator o;
      catena::VecHandle q = o.state(kX0, 0.0);
      auto in = make_adams(o.system, order);
      in->set_state(0.0, q.get(), o.velocity(), nullptr);
      catena::test::advance_fixed(*in, 1.0 / n, n);
      errors.push_back(
          std::hypot(o.x(in->q()) - exact_x(1.0), (o.x(in->v()) - exact_v(1.0)) / kOmega));
    }
    const double p = std::log2(errors[1] / errors[2]);
    std::printf("abm%d  errors %.3e %.3e %.3e m, observed order %.3f\n", order, errors[0],
                errors[1], errors[2], p);
    EXPECT_NEAR(p, order, 0.1) << order;
  }
}

TEST(AdamsPece, GrowthPerStepIsTheRecurrencesRootAndTheLimitIsReported) {
  catena::test::ensure_petsc();
  const std::vector<double> bashforth{1.5, -0.5}, moulton{0.5, 0.5};  // AB-2, trapezoid
  for (const double wh : {0.5, 1.2, 1.35}) {
    Oscillator o;
    catena::VecHandle q = o.state(kX0, 0.0);
    auto in = make_adams(o.system, 2);
    in->set_state(0.0, q.get(), o.velocity(), nullptr);
    // The limit 1.28/ω_max (no damping: ν_max = 0).
    EXPECT_NEAR(in->stable_step() * kOmega, 1.28, 1e-4);
    const double h = wh / kOmega;
    std::vector<double> x{o.x(in->q())};
    for (int i = 0; i < 120; ++i) {
      catena::test::advance_fixed(*in, h, 1);
      x.push_back(o.x(in->q()));
    }
    auto casorati = [&](int n) {
      return x[static_cast<std::size_t>(n)] * x[static_cast<std::size_t>(n)] -
             x[static_cast<std::size_t>(n + 1)] * x[static_cast<std::size_t>(n - 1)];
    };
    const double measured = std::pow(casorati(110) / casorati(50), 1.0 / (2.0 * 60));
    const double expected = pece_largest_root(bashforth, moulton, wh);
    std::printf("abm2  omega h = %.2f: growth per step %.6f, recurrence root %.6f\n", wh, measured,
                expected);
    EXPECT_NEAR(measured, expected, 1e-4) << wh;
    EXPECT_EQ(measured > 1.0, wh > 1.28) << wh;
  }
  // With a dashpot whose rate c/m exceeds ω, the limit is set by the damping rate.
  catena::model::Model m = catena::test::oscillator(kMass, kOmega);
  const double c = 3.0 * kMass * kOmega;  // ν = c/m = 3ω
  m.elastic_supports.front().damping = catena::Vec3(c, c, c);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  auto in = make_adams(system, 1);
  in->set_state(0.0, q.get(), v.get(), nullptr);
  EXPECT_NEAR(in->stable_step(), 1.0 / (c / kMass), 1e-4 / (c / kMass));
}

TEST(AdamsPece, MilneEstimateMatchesTheLocalError) {
  catena::test::ensure_petsc();
  constexpr double phase = std::numbers::pi / 4;
  for (int order : {1, 2}) {
    for (const double wh : {0.02, 0.01}) {
      const double h = wh / kOmega;
      Oscillator o;
      catena::VecHandle q = o.state(exact_x(0.0, phase), exact_v(0.0, phase));
      auto first = make_adams(o.system, order);
      first->set_state(0.0, q.get(), o.velocity(), nullptr);
      catena::test::advance_fixed(*first, h, 4);
      catena::solvers::ResumeState saved;
      first->save_resume_state(saved);
      // The exact solution's v and a at the history's times.
      std::vector<catena::VecHandle> exact;
      for (std::int64_t j = 0; j < saved.integer("abm.known"); ++j) {
        const std::string i = std::to_string(j);
        const double t = saved.real("abm.t" + i);
        exact.push_back(o.state(exact_v(t, phase), -kOmega * kOmega * exact_x(t, phase)));
        saved.vectors["abm.v" + i] = exact.back().get();
        exact.push_back(o.system.create_vector());
        VecCopy(o.velocity(), exact.back().get());
        saved.vectors["abm.a" + i] = exact.back().get();
      }
      const double t0 = saved.real("abm.t0");
      catena::VecHandle q0 = o.state(exact_x(t0, phase), exact_v(t0, phase));
      auto in = make_adams(o.system, order);
      in->set_state(t0, q0.get(), o.velocity(), nullptr);
      in->restore_resume_state(saved);
      solvers::ErrorTolerance tol;
      tol.rtol = 1e-300;
      tol.atol = 1.0;
      catena::VecHandle reference = o.system.create_vector();
      o.system.reference_state(reference.get());
      tol.reference = reference.get();
      const solvers::StepOutcome out = in->attempt(h, &tol);
      ASSERT_TRUE(out.converged);
      PetscInt size = 0;
      VecGetSize(in->q(), &size);
      const double estimate = out.error * std::sqrt(static_cast<double>(size));
      const double local = std::abs(o.x(in->pending_q()) - exact_x(t0 + h, phase));
      std::printf("abm%d  omega h = %.2f: estimate %.3e m, local error %.3e m, ratio %.3f\n", order,
                  wh, estimate, local, estimate / local);
      EXPECT_GT(estimate / local, 0.8) << order << " at omega h = " << wh;
      EXPECT_LT(estimate / local, 1.25) << order << " at omega h = " << wh;
    }
  }
}

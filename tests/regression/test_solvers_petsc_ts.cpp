// The PETSc TS bridge (PetscTsIntegrator) through the whole system: observed orders on
// the undamped oscillator for several TS types (fixed steps), alpha2 with HHT parameters
// against our HhtIntegrator (the same method), BDF against Radau IIA on a damped,
// geometrically nonlinear taut string, the attempt/accept contract with the TS history
// kept, dense output, and a Newton failure reported in the outcome.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "catena/solvers/time/petsc_ts/petsc_ts_integrator.hpp"
#include "catena/solvers/time/transient_solver.hpp"
#include "dynamics_fixtures.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;
using catena::test::global_value;

namespace {

constexpr double kMass = 2.0;
constexpr double kOmega = 2.0 * std::numbers::pi;  // period 1 s
constexpr double kX0 = 0.1;                        // m

using OptionList = std::vector<std::pair<std::string, std::string>>;

// Options set in PETSc's database for one scope (the bridge reads the plain TS prefix).
class ScopedOptions {
 public:
  explicit ScopedOptions(OptionList options) : options_(std::move(options)) {
    for (const auto& [name, value] : options_)
      PetscOptionsSetValue(nullptr, name.c_str(), value.empty() ? nullptr : value.c_str());
  }
  ~ScopedOptions() {
    for (const auto& [name, value] : options_) PetscOptionsClearValue(nullptr, name.c_str());
  }
  ScopedOptions(const ScopedOptions&) = delete;
  ScopedOptions& operator=(const ScopedOptions&) = delete;

 private:
  OptionList options_;
};

solvers::PetscTsOptions tight(double alpha = -0.1) {
  solvers::PetscTsOptions o;
  o.alpha = alpha;
  o.atol = 1e-13;  // the oscillator is linear: Newton reaches round-off in one iteration
  o.rtol = 1e-14;
  return o;
}

struct Oscillator {
  catena::model::Model model = catena::test::oscillator(kMass, kOmega);
  catena::assembly::SecondOrderSystem system{MPI_COMM_WORLD, model};
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  PetscInt g = system.dof_map().global_dof(0, 0);

  Oscillator() {
    system.reference_state(q.get());
    catena::test::set_global_value(q.get(), g, kX0);
  }
  double x(Vec state) const { return global_value(MPI_COMM_WORLD, state, g); }
  // Error of the state (x, v/ω) at time t against x = x0 cos ωt.
  double error(const solvers::TimeIntegrator& in) const {
    const double t = in.time();
    return std::hypot(x(in.q()) - kX0 * std::cos(kOmega * t),
                      (x(in.v()) + kX0 * kOmega * std::sin(kOmega * t)) / kOmega);
  }
};

double oscillator_error(int n, double alpha = -0.1) {
  Oscillator o;
  solvers::PetscTsIntegrator ts(o.system, tight(alpha));
  ts.set_state(0.0, o.q.get(), o.v.get(), nullptr);
  catena::test::advance_fixed(ts, 1.0 / n, n);
  return o.error(ts);
}

struct TsMethod {
  std::string label;
  OptionList options;
  int order;
};

std::string method_name(const testing::TestParamInfo<TsMethod>& info) { return info.param.label; }

class EveryTsType : public testing::TestWithParam<TsMethod> {};

TEST_P(EveryTsType, ObservedOrderOnTheOscillator) {
  catena::test::ensure_petsc();
  const TsMethod& m = GetParam();
  const ScopedOptions options(m.options);
  {
    Oscillator o;
    solvers::PetscTsIntegrator ts(o.system, tight());
    EXPECT_EQ(ts.order(), m.order) << ts.name();
  }
  // The first step-count pair in the asymptotic range (coarse error below 1e-2) whose
  // finer error is well above round-off.
  double coarse = oscillator_error(16);
  for (int n = 16; n <= 16384; n *= 2) {
    const double fine = oscillator_error(2 * n);
    if (coarse < 1e-2 && fine > 1e-11) {
      const double order = std::log2(coarse / fine);
      std::printf("  petsc(%s): n = %d, %d: errors %.3e %.3e, observed order %.2f (theory %d)\n",
                  m.label.c_str(), n, 2 * n, coarse, fine, order, m.order);
      EXPECT_NEAR(order, m.order, 0.3);
      return;
    }
    coarse = fine;
  }
  ADD_FAILURE() << "no step-count pair in the asymptotic range";
}

INSTANTIATE_TEST_SUITE_P(
    Catena, EveryTsType,
    testing::Values(
        TsMethod{"alpha2", {}, 2},
        TsMethod{"bdf2", {{"-ts_type", "bdf"}, {"-ts_bdf_order", "2"}}, 2},
        TsMethod{"cn", {{"-ts_type", "cn"}}, 2}, TsMethod{"beuler", {{"-ts_type", "beuler"}}, 1},
        TsMethod{"theta_midpoint", {{"-ts_type", "theta"}, {"-ts_theta_theta", "0.5"}}, 2},
        TsMethod{"rosw_ra34pw2", {{"-ts_type", "rosw"}, {"-ts_rosw_type", "ra34pw2"}}, 3},
        TsMethod{"rosw_2p", {{"-ts_type", "rosw"}, {"-ts_rosw_type", "2p"}}, 2},
        TsMethod{"rosw_4l", {{"-ts_type", "rosw"}, {"-ts_rosw_type", "4l"}}, 4},
        TsMethod{"alpha", {{"-ts_type", "alpha"}}, 2}),
    method_name);

}  // namespace

TEST(PetscTs, BdfAboveOrderTwoIsLimitedByItsStart) {
  // PETSc's BDF restarts with one backward-Euler half step and raises its order one step
  // at a time; the start's O(h²) local error then bounds the global error: BDF4 shows
  // order 2 on the oscillator (why the tests above use -ts_bdf_order 2).
  catena::test::ensure_petsc();
  const ScopedOptions options(OptionList{{"-ts_type", "bdf"}, {"-ts_bdf_order", "4"}});
  const double coarse = oscillator_error(128), fine = oscillator_error(256);
  const double order = std::log2(coarse / fine);
  std::printf("  petsc(bdf), order 4: n = 128, 256: errors %.3e %.3e, observed order %.2f\n",
              coarse, fine, order);
  EXPECT_NEAR(order, 2.0, 0.3);
}

TEST(PetscTs, RefusesTypesItCannotRun) {
  catena::test::ensure_petsc();
  // A Rosenbrock tableau with explicit stages (the identity-mass assumption of arkimex).
  for (const char* type : {"arkimex", "irk", "rk", "euler", "rosw"}) {
    const ScopedOptions options(OptionList{{"-ts_type", type}, {"-ts_rosw_type", "ark3"}});
    Oscillator o;
    try {
      solvers::PetscTsIntegrator ts(o.system, tight());
      ADD_FAILURE() << type << " accepted";
    } catch (const catena::InputError& e) {
      std::printf("  %s: %s\n", type, e.what());
      EXPECT_NE(std::string(e.what()).find("accepted: alpha2"), std::string::npos);
    }
  }
  Oscillator o;
  solvers::PetscTsOptions bad;
  bad.alpha = -0.5;
  EXPECT_THROW(solvers::PetscTsIntegrator(o.system, bad), catena::InputError);
}

TEST(PetscTs, RosenbrockStagesAreLinearSolves) {
  // A Rosenbrock method solves each stage once with the step's Jacobian (SNES ksponly):
  // ra34pw2 has 4 stages, so 4 residual evaluations and 1 Jacobian per step.
  catena::test::ensure_petsc();
  const ScopedOptions options(OptionList{{"-ts_type", "rosw"}, {"-ts_rosw_type", "ra34pw2"}});
  Oscillator o;
  solvers::PetscTsIntegrator ts(o.system, tight());
  ts.set_state(0.0, o.q.get(), o.v.get(), nullptr);
  catena::test::advance_fixed(ts, 0.01, 10);
  EXPECT_EQ(ts.counters().residual_evaluations, 40);
  EXPECT_EQ(ts.counters().factorizations, 10);
}

namespace {
class SampleError : public solvers::TransientObserver {
 public:
  explicit SampleError(const Oscillator& o) : o_(o) {}
  void sample(double t, Vec q, Vec) override {
    ++samples;
    worst = std::max(worst, std::abs(o_.x(q) - kX0 * std::cos(kOmega * t)));
  }
  int samples = 0;
  double worst = 0.0;

 private:
  const Oscillator& o_;
};
}  // namespace

TEST(PetscTs, AdaptiveStepDoubling) {
  // Through the driver: step doubling (no embedded estimate) rejects and restores states
  // (set_state) and discards attempts; a 100× tighter tolerance must pay off.
  catena::test::ensure_petsc();
  for (const char* type : {"bdf", "rosw", "alpha2"}) {
    const ScopedOptions options(OptionList{{"-ts_type", type}});
    std::vector<double> worst;
    for (double atol : {1e-5, 1e-7}) {
      Oscillator o;
      solvers::PetscTsIntegrator ts(o.system, tight());
      ts.set_state(0.0, o.q.get(), o.v.get(), nullptr);
      solvers::TransientOptions run;
      run.t_end = 2.0;
      run.sample_interval = 0.01;
      run.step.adaptive = true;
      run.step.dt = 1e-3;
      run.step.rtol = 0.0;
      run.step.atol = atol;
      SampleError observer(o);
      const solvers::TransientReport r = solvers::run_transient(o.system, ts, run, observer);
      std::printf("  %s, atol %.0e: %ld steps (%ld rejected), worst sampled error %.2e m\n", type,
                  atol, r.steps_accepted, r.steps_rejected, observer.worst);
      EXPECT_NEAR(r.t_reached, 2.0, 1e-12);
      EXPECT_EQ(observer.samples, 201);
      worst.push_back(observer.worst);
    }
    EXPECT_LT(worst[1], worst[0] / 10);
  }
}

TEST(PetscTs, Alpha2WithHhtParametersIsHht) {
  // The same method: PETSc's generalised-α with alpha_m = 1, alpha_f = 1 + α,
  // γ = ½ − α, β = (1 − α)²/4 and the start-up acceleration replaced by the consistent
  // one reproduces HhtIntegrator step by step on a linear problem.
  catena::test::ensure_petsc();
  for (double alpha : {0.0, -0.1, -1.0 / 3.0}) {
    Oscillator o;
    solvers::PetscTsIntegrator ts(o.system, tight(alpha));
    solvers::HhtOptions h;
    h.alpha = alpha;
    h.atol = 1e-13;
    h.rtol = 1e-14;
    solvers::HhtIntegrator hht(o.system, h);
    ts.set_state(0.0, o.q.get(), o.v.get(), nullptr);
    hht.set_state(0.0, o.q.get(), o.v.get(), nullptr);
    double worst = 0.0;
    for (int i = 0; i < 200; ++i) {
      catena::test::advance_fixed(ts, 0.01, 1);
      catena::test::advance_fixed(hht, 0.01, 1);
      worst = std::max({worst, std::abs(o.x(ts.q()) - o.x(hht.q())),
                        std::abs(o.x(ts.v()) - o.x(hht.v())) / kOmega});
    }
    std::printf("  alpha %+.3f: 200 steps, largest |alpha2 - hht| %.2e m (error %.2e m)\n", alpha,
                worst, o.error(hht));
    EXPECT_LT(worst, 1e-12);
  }
}

TEST(PetscTs, BdfConvergesToRadauOnADampedString) {
  // The taut string (60 m, 20 kN) plucked at 0.5 m, so that the tension varies, with
  // Kelvin–Voigt axial damping (τ = 1 ms: the axial modes are overdamped, a stiff C).
  // BDF2 at h and h/2 against Radau IIA s = 3 at h (error O(h⁵), negligible here): the
  // difference must shrink at BDF2's order, i.e. both solve the same damped problem.
  catena::test::ensure_petsc();
  const catena::test::TautString string;
  catena::model::Model m = string.model();
  for (auto& e : m.elements)
    std::get<catena::model::CableProps>(e.props.edit()).damping_time = 1e-3;
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  string.pluck(system, q.get(), 0.5);
  const double t_end = 0.25, h = 1.0 / 400;

  solvers::IrkOptions radau_options;
  radau_options.family = solvers::TableauFamily::radau_iia;
  radau_options.stages = 3;
  solvers::IrkIntegrator radau(system, radau_options);
  radau.set_state(0.0, q.get(), v.get(), nullptr);
  catena::test::advance_fixed(radau, h, static_cast<int>(std::lround(t_end / h)));

  const ScopedOptions options(OptionList{{"-ts_type", "bdf"}, {"-ts_bdf_order", "2"}});
  std::vector<double> differences;
  catena::VecHandle diff = system.create_vector();
  for (double step : {h, h / 2}) {
    solvers::PetscTsIntegrator bdf(system, solvers::PetscTsOptions{});
    bdf.set_state(0.0, q.get(), v.get(), nullptr);
    catena::test::advance_fixed(bdf, step, static_cast<int>(std::lround(t_end / step)));
    VecWAXPY(diff.get(), -1.0, radau.q(), bdf.q());
    double norm = 0.0;
    VecNorm(diff.get(), NORM_INFINITY, &norm);
    differences.push_back(norm);
  }
  const double order = std::log2(differences[0] / differences[1]);
  std::printf("  damped string: |bdf2 - radau_iia_3| = %.3e, %.3e m (h, h/2), order %.2f\n",
              differences[0], differences[1], order);
  EXPECT_NEAR(order, 2.0, 0.3);
  EXPECT_LT(differences[1], 1e-3 * 0.5);
}

TEST(PetscTs, DiscardedAttemptsKeepStateAndHistory) {
  // attempt() leaves the current state alone, and a discarded attempt (a rejected step)
  // does not disturb BDF's back values or alpha2's acceleration: the run equals one
  // without the discarded attempts, to the last bit for the rolled-back types.
  catena::test::ensure_petsc();
  for (const char* type : {"bdf", "alpha2", "alpha", "cn", "rosw"}) {
    const ScopedOptions options(OptionList{{"-ts_type", type}});
    Oscillator o;
    solvers::PetscTsIntegrator plain(o.system, tight()), discarding(o.system, tight());
    plain.set_state(0.0, o.q.get(), o.v.get(), nullptr);
    discarding.set_state(0.0, o.q.get(), o.v.get(), nullptr);
    double worst = 0.0;
    for (int i = 0; i < 40; ++i) {
      catena::test::advance_fixed(plain, 0.01, 1);
      if (i % 3 == 2) {
        const double x_before = o.x(discarding.q());
        ASSERT_TRUE(discarding.attempt(0.03, nullptr).converged);
        EXPECT_EQ(o.x(discarding.q()), x_before);
        ASSERT_TRUE(discarding.attempt(0.005, nullptr).converged);
      }
      catena::test::advance_fixed(discarding, 0.01, 1);
      worst = std::max(worst, std::abs(o.x(plain.q()) - o.x(discarding.q())));
    }
    std::printf("  %s: largest difference with discarded attempts %.2e m\n", type, worst);
    // cn and rosw restart after a discard (no history to keep): identical too.
    EXPECT_LT(worst, 1e-15);
  }
}

TEST(PetscTs, DenseOutput) {
  // Between step ends: BDF's and Rosenbrock's TSInterpolate (back-value polynomial,
  // tableau interpolant), alpha2's and cn's cubic Hermite. Errors against x0 cos ωt at the
  // step quarters, h = 0.01 (ωh = 0.063), and the values at the step ends.
  catena::test::ensure_petsc();
  for (const char* type : {"bdf", "rosw", "alpha2", "cn"}) {
    const ScopedOptions options(OptionList{{"-ts_type", type}});
    Oscillator o;
    solvers::PetscTsIntegrator ts(o.system, tight());
    ts.set_state(0.0, o.q.get(), o.v.get(), nullptr);
    catena::VecHandle qi = o.system.create_vector(), vi = o.system.create_vector();
    double worst_inside = 0.0, worst_end = 0.0, end_gap = 0.0;
    for (int i = 0; i < 50; ++i) {
      catena::test::advance_fixed(ts, 0.01, 1);
      for (double theta : {0.25, 0.5, 0.75}) {
        const double t = ts.previous_time() + theta * 0.01;
        ts.interpolate(t, qi.get(), vi.get());
        worst_inside = std::max(worst_inside, std::abs(o.x(qi.get()) - kX0 * std::cos(kOmega * t)));
      }
      worst_end = std::max(worst_end, std::abs(o.x(ts.q()) - kX0 * std::cos(kOmega * ts.time())));
      ts.interpolate(ts.time(), qi.get(), vi.get());
      end_gap = std::max(end_gap, std::abs(o.x(qi.get()) - o.x(ts.q())));
    }
    std::printf("  %s: dense output error %.2e m inside steps, %.2e m at step ends, gap %.1e m\n",
                type, worst_inside, worst_end, end_gap);
    // Inside a step the dense output is no worse than the method at the step ends (plus
    // the interpolant's own O(h³..h⁴) error).
    EXPECT_LT(worst_inside, 1.5 * worst_end + 1e-6);
    EXPECT_LT(end_gap, 1e-13);
  }
}

TEST(PetscTs, NewtonFailureIsReportedNotThrown) {
  // One Newton iteration allowed on the large-amplitude string with a long step: the TS
  // step fails, the outcome says why, and the state is untouched; smaller steps proceed.
  catena::test::ensure_petsc();
  const catena::test::TautString string;
  const catena::model::Model m = string.model();
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  string.pluck(system, q.get(), 2.0);
  const ScopedOptions options(OptionList{{"-ts_type", "bdf"}});
  solvers::PetscTsOptions o;
  o.max_newton_iterations = 1;
  solvers::PetscTsIntegrator bdf(system, o);
  bdf.set_state(0.0, q.get(), v.get(), nullptr);
  const solvers::StepOutcome failed = bdf.attempt(0.2, nullptr);
  std::printf("  failure: %s (worst DOF %ld)\n", failed.failure.c_str(),
              static_cast<long>(failed.worst_dof));
  EXPECT_FALSE(failed.converged);
  EXPECT_NE(failed.failure.find("Newton"), std::string::npos);
  EXPECT_GE(failed.worst_dof, 0);
  EXPECT_EQ(bdf.time(), 0.0);
  EXPECT_EQ(bdf.counters().newton_failures, 1);
  solvers::PetscTsOptions relaxed;
  solvers::PetscTsIntegrator retry(system, relaxed);
  retry.set_state(0.0, q.get(), v.get(), nullptr);
  EXPECT_NO_THROW(catena::test::advance_fixed(retry, 1e-3, 5));
}

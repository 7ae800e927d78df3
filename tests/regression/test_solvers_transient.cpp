// The step-control driver: adaptive steps meet their tolerance (embedded estimates and
// step doubling), output samples land on the fixed output times with dense-output
// accuracy, a stop request ends the run between steps, and an unreachable tolerance ends
// with an error naming time, step and the minimum; a multistep method's steps never grow
// faster than its formula's zero-stability cap, and still grow where the cap is small; a
// fixed step that fails now and then is halved and the run goes on, one that fails at every
// step stops the run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "catena/core/error.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "catena/solvers/time/multistep/multistep_integrator.hpp"
#include "catena/solvers/time/transient_solver.hpp"
#include "dynamics_fixtures.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;

namespace {

constexpr double kMass = 2.0, kOmega = 2.0 * std::numbers::pi, kX0 = 0.1;

// Records samples of the x DOF and steps; optionally asks to stop after n steps.
class Recorder : public solvers::TransientObserver {
 public:
  Recorder(MPI_Comm comm, PetscInt g) : comm_(comm), g_(g) {}
  void sample(double t, Vec q, Vec) override {
    times.push_back(t);
    x.push_back(catena::test::global_value(comm_, q, g_));
  }
  void step(const solvers::StepRecord& r) override { steps.push_back(r); }
  bool stop_requested() override {
    return stop_after > 0 && static_cast<int>(steps.size()) >= stop_after;
  }
  std::vector<double> times, x;
  std::vector<solvers::StepRecord> steps;
  int stop_after = 0;

 private:
  MPI_Comm comm_;
  PetscInt g_;
};

struct OscillatorRun {
  solvers::TransientReport report;
  double worst_sample_error = 0.0;
  Recorder recorder{MPI_COMM_WORLD, 0};
};

template <class Integrator, class Options>
OscillatorRun run_oscillator(const Options& integrator_options,
                             const solvers::TransientOptions& options, int stop_after = 0) {
  const catena::model::Model m = catena::test::oscillator(kMass, kOmega);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  const PetscInt g = system.dof_map().global_dof(0, 0);
  catena::test::set_global_value(q.get(), g, kX0);
  Integrator integrator(system, integrator_options);
  integrator.set_state(0.0, q.get(), v.get(), nullptr);
  OscillatorRun run;
  run.recorder = Recorder(MPI_COMM_WORLD, g);
  run.recorder.stop_after = stop_after;
  run.report = solvers::run_transient(system, integrator, options, run.recorder);
  for (size_t i = 0; i < run.recorder.times.size(); ++i)
    run.worst_sample_error =
        std::max(run.worst_sample_error,
                 std::abs(run.recorder.x[i] - kX0 * std::cos(kOmega * run.recorder.times[i])));
  return run;
}

solvers::TransientOptions adaptive(double rtol, double atol, solvers::ErrorEstimate e) {
  solvers::TransientOptions o;
  o.t_end = 2.0;
  o.sample_interval = 0.01;
  o.step.adaptive = true;
  o.step.dt = 1e-3;
  o.step.rtol = rtol;
  o.step.atol = atol;
  o.step.estimate = e;
  return o;
}

}  // namespace

TEST(Transient, AdaptiveErrorFollowsTheTolerance) {
  catena::test::ensure_petsc();
  struct Case {
    const char* name;
    solvers::ErrorEstimate estimate;
    int which;  // 0 HHT, 1 Radau IIA 3, 2 Gauss 2
  };
  for (const Case& c : {Case{"hht embedded", solvers::ErrorEstimate::embedded, 0},
                        Case{"radau_iia_3 embedded", solvers::ErrorEstimate::embedded, 1},
                        Case{"gauss_2 step doubling", solvers::ErrorEstimate::step_doubling, 2}}) {
    std::vector<double> errors;
    std::vector<long> steps;
    for (double tol : {1e-5, 1e-7}) {
      const solvers::TransientOptions o = adaptive(0.0, tol, c.estimate);
      OscillatorRun run;
      if (c.which == 0) {
        solvers::HhtOptions h;
        h.alpha = -0.05;
        run = run_oscillator<solvers::HhtIntegrator>(h, o);
      } else {
        solvers::IrkOptions i;
        i.family = c.which == 1 ? solvers::TableauFamily::radau_iia : solvers::TableauFamily::gauss;
        i.stages = c.which == 1 ? 3 : 2;
        i.atol = 1e-12;
        run = run_oscillator<solvers::IrkIntegrator>(i, o);
      }
      EXPECT_FALSE(run.report.interrupted);
      EXPECT_NEAR(run.report.t_reached, 2.0, 1e-12);
      // Samples at exactly 0, 0.01, ..., 2.0.
      ASSERT_EQ(run.recorder.times.size(), 201u);
      for (size_t k = 0; k < run.recorder.times.size(); ++k)
        EXPECT_NEAR(run.recorder.times[k], 0.01 * static_cast<double>(k), 1e-12);
      errors.push_back(run.worst_sample_error);
      steps.push_back(run.report.steps_accepted);
      std::printf("  %s, atol %.0e: %ld steps (%ld rejected), worst sampled error %.2e m\n", c.name,
                  tol, run.report.steps_accepted, run.report.steps_rejected,
                  run.worst_sample_error);
    }
    // A 100× tighter tolerance buys accuracy and costs steps; the global error stays within
    // the sum of the local tolerances (steps × atol, with a factor 5 for propagation).
    EXPECT_LT(errors[1], errors[0] / 10);
    EXPECT_GT(steps[1], steps[0]);
    EXPECT_LT(errors[1], 5.0 * static_cast<double>(steps[1]) * 1e-7);
  }
}

TEST(Transient, StopRequestEndsTheRunBetweenSteps) {
  catena::test::ensure_petsc();
  solvers::TransientOptions o;
  o.t_end = 1.0;
  o.step.dt = 1e-2;
  const OscillatorRun run = run_oscillator<solvers::HhtIntegrator>(solvers::HhtOptions{}, o, 7);
  EXPECT_TRUE(run.report.interrupted);
  EXPECT_EQ(run.report.steps_accepted, 7);
  EXPECT_NEAR(run.report.t_reached, 0.07, 1e-12);
}

TEST(Transient, UnreachableToleranceStopsAtTheMinimumStep) {
  catena::test::ensure_petsc();
  solvers::TransientOptions o = adaptive(0.0, 1e-30, solvers::ErrorEstimate::embedded);
  o.step.dt_min = 1e-6;
  try {
    run_oscillator<solvers::HhtIntegrator>(solvers::HhtOptions{}, o);
    FAIL() << "expected a NumericalError";
  } catch (const catena::NumericalError& e) {
    const std::string what = e.what();
    std::printf("  message: %s\n", what.c_str());
    EXPECT_NE(what.find("below its minimum at t = "), std::string::npos);
    EXPECT_NE(what.find("dt_min = 1e-06"), std::string::npos);
    EXPECT_NE(what.find("error estimate"), std::string::npos);
  }
}

// HHT whose Newton "fails" on any step longer than `longest` (as a factorisation that
// cannot pivot made every step of dt fail): the driver halves such steps until they pass.
class FailsLongSteps : public solvers::TimeIntegrator {
 public:
  FailsLongSteps(catena::assembly::SecondOrderSystem& system, double longest)
      : inner_(system, solvers::HhtOptions{}), longest_(longest) {}
  std::string name() const override { return inner_.name(); }
  int order() const override { return inner_.order(); }
  bool has_embedded_estimate() const override { return inner_.has_embedded_estimate(); }
  void set_state(double t, Vec q, Vec v, Vec a) override { inner_.set_state(t, q, v, a); }
  solvers::StepOutcome attempt(double h, const solvers::ErrorTolerance* tol) override {
    if (h <= longest_) return inner_.attempt(h, tol);
    solvers::StepOutcome failed;
    failed.failure = "a step longer than the test's limit";
    return failed;
  }
  void accept() override { inner_.accept(); }
  void interpolate(double t, Vec q, Vec v) override { inner_.interpolate(t, q, v); }
  double time() const override { return inner_.time(); }
  double previous_time() const override { return inner_.previous_time(); }
  Vec q() const override { return inner_.q(); }
  Vec v() const override { return inner_.v(); }
  Vec a() const override { return inner_.a(); }
  Vec pending_q() const override { return inner_.pending_q(); }
  Vec pending_v() const override { return inner_.pending_v(); }
  const solvers::IntegratorCounters& counters() const override { return inner_.counters(); }

 private:
  solvers::HhtIntegrator inner_;
  double longest_;
};

solvers::TransientReport run_failing_long_steps(double longest) {
  const catena::model::Model m = catena::test::oscillator(kMass, kOmega);
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  catena::test::set_global_value(q.get(), system.dof_map().global_dof(0, 0), kX0);
  FailsLongSteps integrator(system, longest);
  integrator.set_state(0.0, q.get(), v.get(), nullptr);
  solvers::TransientOptions o;
  o.t_end = 1.0;
  o.step.dt = 0.01;
  Recorder recorder(MPI_COMM_WORLD, 0);
  return solvers::run_transient(system, integrator, o, recorder);
}

// A fixed step that fails now and then is halved and the run goes on at dt; one that fails
// at every step, where only steps 128 times shorter converge, stops the run after 50 such
// steps in a row (they covered 0.39 dt) with the cause, instead of crawling on.
TEST(Transient, FixedStepsCutNowAndThenGoOn) {
  catena::test::ensure_petsc();
  const solvers::TransientReport r = run_failing_long_steps(0.006);  // each step cut to 0.005
  EXPECT_NEAR(r.t_reached, 1.0, 1e-12);
  // 200 steps of 0.005 s; the last one, the 0.005 s left to the end, is not a cut.
  EXPECT_EQ(r.fixed_steps_cut, 199);
  EXPECT_NEAR(r.smallest_cut_dt, 0.005, 1e-15);
}

TEST(Transient, FixedStepsThatFailEveryTimeStopTheRun) {
  catena::test::ensure_petsc();
  try {
    run_failing_long_steps(1e-4);
    FAIL() << "expected a NumericalError";
  } catch (const catena::NumericalError& e) {
    const std::string what = e.what();
    std::printf("  message: %s\n", what.c_str());
    EXPECT_NE(what.find("the fixed step dt = 0.01 s failed in each of 50 steps in a row from "
                        "t = 0 s"),
              std::string::npos);
    EXPECT_NE(what.find("covered only 0.00390625 s together (the last 7.8125e-05 s)"),
              std::string::npos);
    EXPECT_NE(what.find("last failure: a step longer than the test's limit"), std::string::npos);
    EXPECT_NE(what.find("use a smaller integrator.dt"), std::string::npos);
  }
}

TEST(Transient, FixedStepsLandOnTheEndTime) {
  catena::test::ensure_petsc();
  solvers::TransientOptions o;
  o.t_end = 0.105;
  o.step.dt = 0.01;
  const OscillatorRun run = run_oscillator<solvers::HhtIntegrator>(solvers::HhtOptions{}, o);
  EXPECT_EQ(run.report.steps_accepted, 11);
  EXPECT_NEAR(run.report.t_reached, 0.105, 1e-15);
  EXPECT_EQ(run.recorder.times.size(), 12u);  // every step, plus the start
}

// Variable-step BDF and Park with adaptive steps from dt = 1 ms: no accepted step is longer
// than the cap (TimeIntegrator::max_step_ratio: 2 for BDF-2, 1.8 for Park, 1.1 for BDF-5)
// times the one before, yet the steps grow by far (for BDF-5 only through the narrowed band
// of kept steps: with RADAU5's band [1, 1.2] a cap of 1.1 would never let h grow), and the
// error follows the tolerance as for the one-step methods above.
TEST(Transient, MultistepStepsGrowWithinTheirCap) {
  catena::test::ensure_petsc();
  struct Case {
    const char* name;
    solvers::MultistepFamily family;
    int order;
    double cap;  // the formula's growth cap (multistep_integrator.cpp)
  };
  for (const Case& c : {Case{"bdf2", solvers::MultistepFamily::bdf, 2, 2.0},
                        Case{"park", solvers::MultistepFamily::park, 2, 1.8},
                        Case{"bdf5", solvers::MultistepFamily::bdf, 5, 1.1}}) {
    solvers::MultistepOptions m;
    m.family = c.family;
    m.order = c.order;
    m.atol = 1e-12;
    const OscillatorRun run = run_oscillator<solvers::MultistepIntegrator>(
        m, adaptive(0.0, 1e-7, solvers::ErrorEstimate::embedded));
    EXPECT_NEAR(run.report.t_reached, 2.0, 1e-12) << c.name;
    const std::vector<solvers::StepRecord>& steps = run.recorder.steps;
    ASSERT_GT(steps.size(), 10u) << c.name;
    double largest_ratio = 0.0;
    for (std::size_t k = 1; k < steps.size(); ++k)
      largest_ratio = std::max(largest_ratio, steps[k].dt / steps[k - 1].dt);
    const double largest_step =
        std::max_element(steps.begin(), steps.end(), [](const auto& a, const auto& b) {
          return a.dt < b.dt;
        })->dt;
    std::printf(
        "  %s: %ld steps (%ld rejected), largest step ratio %.4f (cap %.2f), steps up to "
        "%.2e s, worst sampled error %.2e m\n",
        c.name, run.report.steps_accepted, run.report.steps_rejected, largest_ratio, c.cap,
        largest_step, run.worst_sample_error);
    EXPECT_LE(largest_ratio, c.cap * (1 + 1e-12)) << c.name;
    EXPECT_GT(largest_ratio, 1.0 + 0.5 * (c.cap - 1.0)) << c.name << ": the steps never grew";
    EXPECT_GT(largest_step, 5 * 1e-3) << c.name;
    EXPECT_LT(run.worst_sample_error, 5.0 * static_cast<double>(run.report.steps_accepted) * 1e-7)
        << c.name;
  }
}

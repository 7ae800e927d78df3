#include "catena/solvers/time/transient_solver.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/time/state_guard.hpp"

namespace catena::solvers {
namespace {

// Samples taken during a step-doubling pair, released only when the pair is accepted.
struct PendingSample {
  double t;
  VecHandle q, v;
};

class Driver {
 public:
  Driver(assembly::SecondOrderSystem& system, TimeIntegrator& integrator,
         const TransientOptions& options, TransientObserver& observer)
      : system_(system),
        in_(integrator),
        options_(options),
        observer_(observer),
        guard_(system, options.t_end, options.step.dt) {
    const StepControl& c = options.step;
    doubling_ = c.adaptive &&
                (c.estimate == ErrorEstimate::step_doubling ||
                 (c.estimate == ErrorEstimate::automatic && !integrator.has_embedded_estimate()));
    if (c.adaptive && c.estimate == ErrorEstimate::embedded && !integrator.has_embedded_estimate())
      throw InputError({"", 0, "integrator.error_estimate"},
                       integrator.name() + " has no embedded error estimate; use step_doubling");
    k_ = doubling_ ? integrator.order() + 1 : integrator.estimate_order();
    reference_ = system.create_vector();
    system.reference_state(reference_.get());
    tol_.rtol = c.rtol;
    tol_.atol = c.atol;
    tol_.reference = reference_.get();
    if (system.has_constraints()) {
      algebraic_ = system.create_vector();
      system.algebraic_mask(algebraic_.get());
      tol_.algebraic = algebraic_.get();
    }
    for (VecHandle* v :
         {&q_save_, &v_save_, &a_save_, &q_big_, &v_big_, &diff_, &q_sample_, &v_sample_})
      *v = system.create_vector();
    t_start_ = integrator.time();
    origin_ = t_start_;
  }

  TransientReport run() {
    const StepControl& c = options_.step;
    const double t_end = options_.t_end;
    double h = c.dt;
    next_sample_ = 0;
    if (options_.resume && options_.resume_driver) {
      const DriverState& d = *options_.resume_driver;
      if (c.adaptive) h = d.next_dt;
      report_ = d.report;
      previous_error_ = d.previous_error;
      report_.interrupted = false;
    }
    if (options_.resume) {
      origin_ = options_.sample_origin;
      if (options_.sample_interval > 0.0)
        while (sample_time(next_sample_) <= in_.time() * (1 + 1e-13) + 1e-300) ++next_sample_;
      committed_sample_ = next_sample_;
    } else {
      emit_samples_up_to(in_.time());
    }
    // An explicit method's stability limit (TimeIntegrator::stable_step): a longer fixed
    // step is refused before any is taken, adaptive steps are capped at it.
    const double stable = in_.stable_step();
    if (!c.adaptive && c.dt > stable) {
      std::ostringstream os;
      os << "dt = " << c.dt << " s is too long: " << in_.stable_step_reason()
         << "; use dt <= " << stable << " s, or an implicit method (hht) for longer steps";
      throw InputError({"", 0, "integrator.dt"}, os.str());
    }
    int rejected = 0;
    while (in_.time() < t_end * (1 - 1e-14) - 1e-300) {
      if (stop_requested()) {
        report_.interrupted = true;
        break;
      }
      if (options_.boundary) options_.boundary->before_step(in_);
      const double t = in_.time();
      double step = std::min({h, c.dt_max > 0 ? c.dt_max : h, stable});
      // Land on t_end; avoid a sliver of a last step.
      if (t + step >= t_end || t + 1.01 * step >= t_end) step = t_end - t;
      if (step < c.dt_min && t_end - t > c.dt_min) fail_small_step(t, step);

      Attempt a = doubling_ ? attempt_doubled(step) : attempt_single(step);
      if (!a.converged) {
        ++rejected;
        ++report_.steps_rejected;
        last_failure_ = a.outcome;
        h = 0.5 * step;
        if (h < c.dt_min) fail_small_step(t, h);
        if (!c.adaptive) note_fixed_step_cut(t, step, h, rejected == 1);
        continue;
      }
      if (c.adaptive && a.error > 1.0) {
        ++rejected;
        ++report_.steps_rejected;
        last_failure_ = a.outcome;
        if (doubling_) restore_start();
        h = step * std::max(c.shrink, c.safety * std::pow(a.error, -1.0 / k_));
        if (h < c.dt_min) fail_small_step(t, h);
        continue;
      }
      if (!doubling_) {
        in_.accept();
        observer_.accepted(in_.time());
        emit_samples_up_to(in_.time());
      } else {
        observer_.accepted(in_.time());
        release_pending_samples();
      }
      if (c.adaptive) {
        // A multistep method's steps may not grow faster than its formula stays zero-stable.
        const double growth = std::min(c.growth, in_.max_step_ratio());
        // PI control after two accepted steps in a row, else the elementary rule (header).
        const bool pi = a.error > 0.0 && previous_error_ > 0.0 && rejected == 0;
        const double raw =
            a.error <= 0.0 ? growth
            : pi ? c.safety * std::pow(a.error, -0.7 / k_) * std::pow(previous_error_, 0.4 / k_)
                 : c.safety * std::pow(a.error, -1.0 / k_);
        // An estimate of exactly 0 (a step with nothing to err on) counts as a small one.
        if (a.error >= 0.0) previous_error_ = std::max(a.error, 1e-4);
        // The step after a rejected attempt does not grow (RADAU5's rule: Hairer & Wanner
        // II, IV.8): where Newton limits the step, growing at once fails the attempt
        // again (the squeezer at rtol 1e-6: 158 attempts rejected for 105 steps, 17 for
        // 97 with the rule, docs/validation.md).
        const double factor = std::min(rejected > 0 ? 1.0 : growth, std::max(c.shrink, raw));
        // Keep h (and its factorisation) for small changes, unless the growth limit is as
        // small as that (BDF-4 and 5): then every allowed growth is taken.
        const double hold = std::min(1.2, 0.5 * (1.0 + growth));
        h = (factor >= 1.0 && factor <= hold) ? step : step * factor;
      } else {
        h = c.dt;
        watch_for_stalled_fixed_steps(t, step, rejected > 0);
      }
      record(step, a, rejected, h);
      rejected = 0;
    }
    report_.t_reached = in_.time();
    return report_;
  }

 private:
  struct Attempt {
    bool converged = false;
    double error = -1.0;
    int newton_iterations = 0;
    StepOutcome outcome;
  };

  Attempt attempt_single(double h) {
    Attempt a;
    a.outcome = in_.attempt(h, options_.step.adaptive ? &tol_ : nullptr);
    a.converged = a.outcome.converged;
    a.error = a.outcome.error;
    a.newton_iterations = a.outcome.newton_iterations;
    return a;
  }

  // One step of h against two of h/2 (Richardson); the half steps are kept.
  Attempt attempt_doubled(double h) {
    Attempt a;
    a.outcome = in_.attempt(h, nullptr);
    if (!a.outcome.converged) return a;
    a.newton_iterations = a.outcome.newton_iterations;
    CATENA_PETSC(VecCopy(in_.pending_q(), q_big_.get()));
    const bool velocities = in_.velocity_order() < in_.order();
    if (velocities) CATENA_PETSC(VecCopy(in_.pending_v(), v_big_.get()));
    t_save_ = in_.time();
    CATENA_PETSC(VecCopy(in_.q(), q_save_.get()));
    CATENA_PETSC(VecCopy(in_.v(), v_save_.get()));
    CATENA_PETSC(VecCopy(in_.a(), a_save_.get()));
    for (int half = 0; half < 2; ++half) {
      a.outcome = in_.attempt(0.5 * h, nullptr);
      a.newton_iterations += a.outcome.newton_iterations;
      if (!a.outcome.converged) {
        restore_start();
        return a;
      }
      if (half == 1) {
        CATENA_PETSC(VecWAXPY(diff_.get(), -1.0, q_big_.get(), in_.pending_q()));
        CATENA_PETSC(VecScale(diff_.get(), 1.0 / (std::pow(2.0, in_.order()) - 1.0)));
        a.error = weighted_error_norm(tol_, diff_.get(), q_save_.get(), in_.pending_q());
        // Velocities of a lower order (index-3 constraints) are estimated too, as the
        // displacement h·Δv their error makes in a step, weighed as the positions' error:
        // without it the squeezer's angles stayed about 1e-6 off at every rtol from 1e-3
        // to 1e-7 (docs/validation.md). The step's exponent stays the positions' (k = p + 1)
        // where this term decides, larger than the velocities' q + 1: the step grows more
        // cautiously than theirs would ask, and a rejection may take one more attempt.
        if (velocities) {
          CATENA_PETSC(VecWAXPY(diff_.get(), -1.0, v_big_.get(), in_.pending_v()));
          CATENA_PETSC(VecScale(diff_.get(), h / (std::pow(2.0, in_.velocity_order()) - 1.0)));
          a.error = std::max(
              a.error, weighted_error_norm(tol_, diff_.get(), q_save_.get(), in_.pending_q()));
        }
        if (a.error > 1.0) {
          restore_start();
          a.converged = true;
          return a;
        }
      }
      in_.accept();
      buffer_samples_up_to(in_.time());
    }
    a.converged = true;
    return a;
  }

  void restore_start() {
    in_.set_state(t_save_, q_save_.get(), v_save_.get(), a_save_.get());
    pending_.clear();
    next_sample_ = committed_sample_;
  }

  double sample_time(long k) const {
    return origin_ + static_cast<double>(k) * options_.sample_interval;
  }

  // Samples up to t not yet taken (t_start's at the beginning) straight to the observer.
  void emit_samples_up_to(double t) {
    if (options_.sample_interval <= 0.0) {
      take_sample(t, in_.q(), in_.v());
      return;
    }
    while (sample_time(next_sample_) <= t * (1 + 1e-13) + 1e-300) {
      const double ts = std::min(sample_time(next_sample_), t);
      in_.interpolate(ts, q_sample_.get(), v_sample_.get());
      take_sample(ts, q_sample_.get(), v_sample_.get());
      ++next_sample_;
    }
    committed_sample_ = next_sample_;
  }

  // Collective. A state goes to the observer only once the guard has passed it.
  void take_sample(double t, Vec q, Vec v) {
    guard_.check(in_.name(), t, q, v);
    observer_.sample(t, q, v);
    ++report_.samples;
  }

  void buffer_samples_up_to(double t) {
    auto add = [&](double ts) {
      PendingSample p{ts, system_.create_vector(), system_.create_vector()};
      in_.interpolate(ts, p.q.get(), p.v.get());
      pending_.push_back(std::move(p));
    };
    if (options_.sample_interval <= 0.0) {
      add(t);
      return;
    }
    while (sample_time(next_sample_) <= t * (1 + 1e-13) + 1e-300) {
      add(std::min(sample_time(next_sample_), t));
      ++next_sample_;
    }
  }

  void release_pending_samples() {
    for (PendingSample& p : pending_) take_sample(p.t, p.q.get(), p.v.get());
    pending_.clear();
    committed_sample_ = next_sample_;
  }

  // A fixed step failed and is retried at h_next; `first_failure` if the step was tried
  // at dt until now (its later halvings count as the same cut step).
  void note_fixed_step_cut(double t, double failed, double h_next, bool first_failure) {
    if (first_failure) ++report_.fixed_steps_cut;
    observer_.fixed_step_cut({t, failed, h_next, last_failure_.failure, report_.fixed_steps_cut});
  }

  // Fixed steps: a step of dt that fails is retried halved, and dt resumes after it. Where
  // dt fails at every step and only far shorter steps converge, the run crawls on at their
  // length (a million attempts without reaching dt_min, seen with a factorisation that
  // could not pivot): after kStalledSteps cut steps in a row that together covered less
  // than one dt, the run stops with the cause instead.
  static constexpr int kStalledSteps = 50;
  void watch_for_stalled_fixed_steps(double t, double step, bool cut) {
    if (!cut) {
      stalled_steps_ = 0;
      stalled_time_ = 0.0;
      return;
    }
    if (stalled_steps_ == 0) stalled_since_ = t;
    ++stalled_steps_;
    stalled_time_ += step;
    if (stalled_steps_ < kStalledSteps || stalled_time_ >= options_.step.dt) return;
    std::ostringstream os;
    os << in_.name() << ": the fixed step dt = " << options_.step.dt << " s failed in each of "
       << stalled_steps_ << " steps in a row from t = " << stalled_since_
       << " s, and the halved steps that converged covered only " << stalled_time_
       << " s together (the last " << step << " s)";
    const StepOutcome& f = last_failure_;
    if (!f.failure.empty()) os << "; last failure: " << f.failure;
    if (f.worst_dof >= 0) os << "; largest residual at " << system_.describe_dof(f.worst_dof);
    os << "; use a smaller integrator.dt, or adaptive steps (integrator.adaptive: true)";
    throw NumericalError(os.str());
  }

  void record(double step, const Attempt& a, int rejected, double next_h) {
    if (!options_.step.adaptive && rejected > 0)
      report_.smallest_cut_dt =
          report_.smallest_cut_dt > 0.0 ? std::min(report_.smallest_cut_dt, step) : step;
    ++report_.steps_accepted;
    report_.smallest_dt = report_.steps_accepted == 1 ? step : std::min(report_.smallest_dt, step);
    report_.largest_dt = std::max(report_.largest_dt, step);
    report_.t_reached = in_.time();
    // Only with sliders: q() is not free for every method (the modal model rebuilds the
    // whole field from its modes for it, 40 ms on EN 50318 against a 0.07 ms step).
    if (guard_.watches_sliders()) guard_.check_sliders(in_.time(), in_.q());
    observer_.step({in_.time(),
                    step,
                    a.newton_iterations,
                    a.error,
                    rejected,
                    {next_h, report_, previous_error_}});
  }

  bool stop_requested() {
    int local = observer_.stop_requested() ? 1 : 0, any = 0;
    MPI_Allreduce(&local, &any, 1, MPI_INT, MPI_MAX, system_.comm());
    return any != 0;
  }

  [[noreturn]] void fail_small_step(double t, double h) {
    std::ostringstream os;
    os << in_.name() << ": the step size fell below its minimum at t = " << t << " s (h = " << h
       << " s < dt_min = " << options_.step.dt_min << " s)";
    const StepOutcome& f = last_failure_;
    if (!f.failure.empty())
      os << "; last attempt: " << f.failure;
    else if (f.error > 0)
      os << "; last error estimate " << f.error << " (accepted: <= 1)";
    os << "; residual |R| = " << f.residual_norm << " N";
    if (f.worst_dof >= 0) os << "; largest residual at " << system_.describe_dof(f.worst_dof);
    throw NumericalError(os.str());
  }

  assembly::SecondOrderSystem& system_;
  TimeIntegrator& in_;
  const TransientOptions& options_;
  TransientObserver& observer_;
  StateGuard guard_;
  bool doubling_ = false;
  double previous_error_ = -1.0;  // the last accepted step's estimate (PI control)
  int k_ = 1;
  ErrorTolerance tol_;
  double origin_ = 0.0;  // sample grid: origin_ + k·interval
  VecHandle reference_, algebraic_, q_save_, v_save_, a_save_, q_big_, v_big_, diff_, q_sample_,
      v_sample_;
  double t_save_ = 0.0, t_start_ = 0.0;
  long next_sample_ = 0, committed_sample_ = 0;
  std::vector<PendingSample> pending_;
  StepOutcome last_failure_;
  TransientReport report_;
  int stalled_steps_ = 0;  // fixed steps cut in a row (watch_for_stalled_fixed_steps)
  double stalled_time_ = 0.0, stalled_since_ = 0.0;
};

}  // namespace

void save_driver_state(const DriverState& state, ResumeState& out) {
  const TransientReport& r = state.report;
  out.reals["driver.next_dt"] = state.next_dt;
  out.reals["driver.previous_error"] = state.previous_error;
  out.integers["driver.steps_accepted"] = r.steps_accepted;
  out.integers["driver.steps_rejected"] = r.steps_rejected;
  out.integers["driver.samples"] = r.samples;
  out.reals["driver.smallest_dt"] = r.smallest_dt;
  out.reals["driver.largest_dt"] = r.largest_dt;
  out.integers["driver.fixed_steps_cut"] = r.fixed_steps_cut;
  out.reals["driver.smallest_cut_dt"] = r.smallest_cut_dt;
}

std::optional<DriverState> restore_driver_state(const ResumeState& in) {
  if (!in.reals.contains("driver.next_dt")) return std::nullopt;  // saved before a step
  DriverState state;
  TransientReport& r = state.report;
  state.next_dt = in.real("driver.next_dt");
  // Checkpoints before PI control have none: the elementary rule takes the first step.
  if (in.reals.contains("driver.previous_error"))
    state.previous_error = in.real("driver.previous_error");
  r.steps_accepted = in.integer("driver.steps_accepted");
  r.steps_rejected = in.integer("driver.steps_rejected");
  r.samples = in.integer("driver.samples");
  r.smallest_dt = in.real("driver.smallest_dt");
  r.largest_dt = in.real("driver.largest_dt");
  if (in.integers.contains("driver.fixed_steps_cut")) {
    r.fixed_steps_cut = in.integer("driver.fixed_steps_cut");
    r.smallest_cut_dt = in.real("driver.smallest_cut_dt");
  }
  return state;
}

TransientReport run_transient(assembly::SecondOrderSystem& system, TimeIntegrator& integrator,
                              const TransientOptions& options, TransientObserver& observer) {
  if (!(options.t_end > integrator.time()))
    throw InputError({"", 0, "analysis.duration"}, "the end time must lie after the start time");
  Driver driver(system, integrator, options, observer);
  return driver.run();
}

}  // namespace catena::solvers

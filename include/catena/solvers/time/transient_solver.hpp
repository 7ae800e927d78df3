#pragma once
// The step-control driver of every dynamic analysis: advances a TimeIntegrator from t0 to
// t_end with fixed or adaptive steps, samples the state at a fixed output interval by the
// integrator's dense output, and stops cleanly when asked (SIGTERM) or when the step
// falls below its minimum.
//
// Adaptive steps (Hairer, Nørsett & Wanner I, II.4; Hairer & Wanner II, IV.2 and IV.8):
//   err ≤ 1 accepts;  h_new = h · min(growth, max(shrink, 0.9 · err^(−1/k)))
// after a rejection and at the first step, and after an accepted step that followed an
// accepted one the PI controller of Gustafsson (ACM TOMS 17 (1991) 533–554)
//   h_new = h · min(growth, max(shrink, 0.9 · err_n^(−0.7/k) · err_{n−1}^(0.4/k))),
// which damps the step sequence's oscillation: with a pantograph's kinks in the forcing
// the elementary rule alone rejected a third of the attempts (EN 50318, Park at rtol
// 1e-3: 162 rejected for 395 accepted in 0.5 s; with the PI rule 7 for 516).
// with k the order of the local error estimate in h: the integrator's embedded estimate
// (HHT: 3, Radau IIA: s + 1), or step doubling for any method — one step of h against two
// of h/2, err = ‖q_{h/2,h/2} − q_h‖ / (2^p − 1), k = p + 1, and the two half steps are
// kept. A step change within [1, 1.2]·h is not made, so the factorisation is reused
// (RADAU5's rule). Growth is capped at the integrator's max_step_ratio() (a multistep
// formula's zero-stability limit); where that is below 1.2 the kept band shrinks to
// [1, (1 + limit)/2]. A Newton failure halves h, and the step accepted after a rejected
// attempt (Newton failure or error) does not grow (RADAU5's rule). Fixed steps: h = dt (the
// last step is cut to land on t_end); a Newton failure halves h for that step and dt
// resumes afterwards; the observer hears of each such cut and the report counts them,
// since a dt that keeps failing costs a failed solve per step and says the step is too
// long.
// Below dt_min the run stops with a NumericalError naming the time, step, residual and
// the worst DOF (node and component). Every sample passes the state guard before the
// observer sees it (state_guard.hpp): a state that is not finite or has grown beyond any
// motion of the scene stops the run with a NumericalError instead of being written.
#include <petscvec.h>

#include <optional>
#include <string>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/time_integrator.hpp"

namespace catena::solvers {

enum class ErrorEstimate { automatic, embedded, step_doubling };

struct StepControl {
  double dt = 1e-3;  // s: the fixed step, or the first adaptive step
  bool adaptive = false;
  double rtol = 1e-4, atol = 1e-6;  // weighted local error (time_integrator.hpp)
  double dt_min = 1e-10;            // s
  double dt_max = 0.0;              // s, 0: no limit
  ErrorEstimate estimate = ErrorEstimate::automatic;
  double growth = 5.0, shrink = 0.2, safety = 0.9;
};

struct TransientReport {
  double t_reached = 0.0;
  bool interrupted = false;  // stopped by a stop request before t_end
  long steps_accepted = 0, steps_rejected = 0, samples = 0;
  double smallest_dt = 0.0, largest_dt = 0.0;
  // Fixed steps only: steps of dt that failed and were retried halved (each counted once,
  // however often it was halved), and the shortest step taken in their place (0: none).
  long fixed_steps_cut = 0;
  double smallest_cut_dt = 0.0;
};

// The driver's step-to-step state after an accepted step. With the integrator's
// (TimeIntegrator::save_resume_state) it is what a restart needs to continue as the
// uninterrupted run: the step size tried next (adaptive steps) and the counters so far.
struct DriverState {
  double next_dt = 0.0;  // s
  TransientReport report;
  double previous_error = -1.0;  // the last accepted step's estimate (PI control), −1: none
};
// Not collective. As resume-state entries "driver.*", and back (none if not saved).
void save_driver_state(const DriverState& state, ResumeState& out);
std::optional<DriverState> restore_driver_state(const ResumeState& in);

// Collective. Before each step, may put an equivalent state in the integrator's place:
// a moving window moves the line's state back a span when the pantograph has crossed one
// (apps/catena/window_mover.hpp). Called with the integrator's accepted state, after its
// samples and step record are out, so that the state a checkpoint saves is the one a
// restart continues from.
class StepBoundary {
 public:
  virtual ~StepBoundary() = default;
  virtual void before_step(TimeIntegrator& integrator) = 0;
};

struct TransientOptions {
  double t_end = 0.0;            // s
  double sample_interval = 0.0;  // s, 0: sample every accepted step
  StepControl step;
  // A restarted run continues the sampling of the run it resumes: samples on the grid
  // sample_origin + k·sample_interval strictly after the start (those at or before it
  // were written before the checkpoint).
  bool resume = false;
  double sample_origin = 0.0;  // s
  // With resume: the driver's state at the checkpoint (adaptive steps continue with its
  // next step; the counters continue). None (an older checkpoint): the first step is
  // step.dt and the counters start at 0.
  std::optional<DriverState> resume_driver;
  StepBoundary* boundary = nullptr;  // none: the state is the integrator's alone
};

// One accepted step, for statistics output.
struct StepRecord {
  double time = 0.0;  // end of the step
  double dt = 0.0;
  int newton_iterations = 0;  // summed over the step's attempts that were kept
  double error = -1.0;        // weighted local error estimate, −1 if none
  int rejected = 0;           // attempts rejected before this step was accepted
  DriverState driver;         // after this step (for checkpoints)
};

// A fixed step cut after a Newton failure (adaptive runs cut steps as a matter of course).
struct StepCut {
  double time = 0.0;         // start of the step
  double failed_dt = 0.0;    // the step that failed
  double next_dt = 0.0;      // the step tried next (half of it)
  std::string failure;       // why Newton failed
  long fixed_steps_cut = 0;  // steps of the run cut so far, this one included
};

class TransientObserver {
 public:
  virtual ~TransientObserver() = default;
  // Collective. The state at an output time.
  virtual void sample(double t, Vec q, Vec v) = 0;
  // Not collective. A step ending at t was accepted; its samples and its record (step())
  // follow. Separates a step's own wall time from its output's (`catena run --realtime`).
  virtual void accepted(double /*t*/) {}
  // Collective. After every accepted step (identical on every rank).
  virtual void step(const StepRecord&) {}
  // Collective (identical on every rank). A fixed step failed and is retried at half its
  // size: every failure of a step, its first one and the retries of halves alike.
  virtual void fixed_step_cut(const StepCut&) {}
  // Not collective: this rank's request to stop (e.g. a signal arrived). The driver
  // combines the ranks' answers so that all stop at the same step.
  virtual bool stop_requested() { return false; }
};

// Collective. Runs integrator (whose state is set) to options.t_end.
TransientReport run_transient(assembly::SecondOrderSystem& system, TimeIntegrator& integrator,
                              const TransientOptions& options, TransientObserver& observer);

}  // namespace catena::solvers

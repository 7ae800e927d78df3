#pragma once
// Local Newton correction for one-step integrators whose residual in the unknown a is
//
//   R(a) = M a + c_f f(q, v) + (terms that do not depend on a),  q = q̂ + c_q a, v = v̂ + c_v a
//
// (HHT-α: c_f = 1 + α, c_q = βh², c_v = γh). After a global Newton iteration with a stale
// tangent, the residual of a moving-load run is left only near the load: the tangent's
// error is where the load's kink has moved since it was evaluated (docs/integrators.md,
// "Local Newton correction", with the measurement). This finishes the solve there: Newton
// on the windows around the large residual entries (assembly/local_patch.hpp), with a
// fresh tangent of the window and the residual updated from the window's kernels alone,
// at the cost of a few element evaluations instead of a global residual and a pair of
// triangular solves. The window's edge is held fixed (a Dirichlet truncation), so the
// correction is not the global Newton step; it is accepted only if the whole residual,
// re-evaluated exactly where it changed, meets the tolerance. A window that stalls is
// tried once at twice the width, which is kept for later solves (the coupling length of
// the Newton matrix, over which a correction spreads, grows with the step).
#include <petscvec.h>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/resume_state.hpp"

namespace catena::solvers {

struct LocalNewtonSettings {
  int layers = 32;         // kernel layers around the large entries, to start with
  int max_layers = 1024;   // the widest window tried
  int max_iterations = 4;  // local Newton iterations per correction
  // The windows hold the largest entries of R, all but a rest of norm outside_fraction·atol.
  double outside_fraction = 0.5;
  // A correction must cost less than the global iteration it replaces: measured on the
  // moving-load benchmark, a window iteration costs about 1.9 µs per unknown and a global
  // iteration (a residual and a solve pair over n = 240 000 DOFs) 16 ms, the price of
  // 0.035·n window unknowns (docs/performance.md, "Local Newton correction"). Wider
  // windows are not tried.
  double max_window_fraction = 0.03;
  // Windows grow as the tangent ages (a stale tangent's error follows the waves a moving
  // load leaves behind). A refresh (element tangents, Newton matrix, factorisation) costs
  // about as much as local corrections over 0.26·n unknowns (docs/performance.md, "Local
  // Newton correction"); past n/2 of local work since the last tangent, refresh (about
  // twice the break-even: a refresh narrows the windows only partly).
  double worn_fraction = 0.5;
};

struct LocalNewtonCounters {
  long attempts = 0;    // corrections tried
  long successes = 0;   // corrections that met the tolerance
  long iterations = 0;  // local Newton iterations (over every rank's windows at once)
  long unknowns = 0;    // window unknowns, summed over ranks and iterations
};

class LocalNewton {
 public:
  // R's coefficients for the current step.
  struct Coefficients {
    double c_f = 1.0, c_q = 0.0, c_v = 0.0;
    double t = 0.0;  // s: the time f is evaluated at (moving contacts)
  };

  // Collective (assembly::SecondOrderSystem::prepare_local_patches).
  LocalNewton(assembly::SecondOrderSystem& system, const LocalNewtonSettings& settings);

  // Collective. a: the iterate; r = R(a); q, v: the states at a; f = f(q, v) (global
  // vectors). If the windows bring ‖R‖₂ to atol, updates all five in place (r and f
  // exactly where they changed), sets *norm and returns true; otherwise changes nothing
  // and returns false.
  bool correct(Vec a, Vec r, Vec q, Vec v, Vec f, const Coefficients& c, double atol, double* norm);

  const LocalNewtonCounters& counters() const { return counters_; }
  // The window width (kernel layers) the next correction starts from.
  int layers() const { return layers_; }

  // Not collective (same answer on every rank). True once the corrections since the last
  // tangent have together worked on `worn_fraction`·n unknowns (n: the system's size): the
  // owner should then refresh the tangent (see LocalNewtonSettings::worn_fraction).
  bool tangent_worn() const { return worked_since_tangent_ > worn_limit_; }
  // The owner evaluated a new tangent: the windows start again from their first width.
  void tangent_refreshed() {
    worked_since_tangent_ = 0.0;
    layers_ = settings_.layers;
  }

  // Restarts (resume_state.hpp). Not collective. The window width, the skip state, the
  // work since the last tangent and the counters, as entries "local_newton.*".
  void save_resume_state(ResumeState& out) const;
  void restore_resume_state(const ResumeState& in);

 private:
  enum class Outcome { converged, no_window, too_narrow, too_wide, failed };
  struct Vectors {
    Vec a, r, q, v, f;
  };
  // Collective. One correction with windows `layers` wide; undone unless converged.
  Outcome attempt(const Vectors& vecs, const Coefficients& c, double atol, int layers,
                  double* norm);

  assembly::SecondOrderSystem& system_;
  LocalNewtonSettings settings_;
  LocalNewtonCounters counters_;
  int layers_;
  int misses_ = 0, skip_ = 0;          // failures in a row; calls still to skip
  double worked_since_tangent_ = 0.0;  // window unknowns × iterations, all ranks
  double worn_limit_ = 0.0;
};

}  // namespace catena::solvers

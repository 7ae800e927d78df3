#pragma once
// The contract between one-step time integrators and the step-control driver
// (transient_solver.hpp). An integrator advances
//   M a + f(t, q, v) = 0        (assembly/second_order_system.hpp)
// by attempting a step of a given size from its current state; the attempt is held
// pending until the driver accepts it, so a rejected attempt costs nothing but the work
// done, and step doubling can restore the start state. Integrators never see elements and
// never choose step sizes: the driver does (error estimate, Newton failures, output times).
#include <petscvec.h>

#include <limits>
#include <string>
#include <vector>

#include "catena/solvers/resume_state.hpp"

namespace catena::solvers {

// Cumulative work counters (reported per run and in the output's statistics).
struct IntegratorCounters {
  long steps_accepted = 0;
  long steps_rejected = 0;  // error test failed or Newton failed
  long newton_iterations = 0;
  long newton_failures = 0;       // attempts whose Newton iteration did not converge
  long residual_evaluations = 0;  // full-system f evaluations (a stage counts once)
  long jacobian_evaluations = 0;  // element K/C assemblies
  long factorizations = 0;        // numeric LU/LDLᵀ factorisations
  long linear_solves = 0;         // pairs of triangular solves
  long local_corrections = 0;     // Newton solves finished by a local correction (HHT)
  long local_unknowns = 0;        // window unknowns of local Newton iterations, summed
};

// Not collective. The counters an integrator keeps itself (steps, Newton iterations and
// failures, element tangents) as resume-state entries "counters.*", and back (resume_state.hpp;
// the Newton solver's own counters travel with its state).
void save_own_counters(const IntegratorCounters& c, ResumeState& out);
void restore_own_counters(const ResumeState& in, IntegratorCounters& c);

// Weighted RMS norm of a local error in the displacement q − q_ref (q_ref: the reference
// configuration), the usual mixed test of ODE codes (Hairer & Wanner I, II.4):
//   ‖e‖ = sqrt( (1/N) Σ_i ( e_i / (atol + rtol·max(|d0_i|, |d1_i|)) )² ),  d = q − q_ref,
// over all N free DOFs; a step is acceptable when ‖e‖ ≤ 1. Lagrange multipliers are not
// part of the test (their local error is of lower order in index-3 form, and they are
// forces, not lengths): entries where `algebraic` is nonzero are skipped.
struct ErrorTolerance {
  double rtol = 1e-4;
  double atol = 1e-6;
  Vec reference = nullptr;  // q_ref (not owned)
  Vec algebraic = nullptr;  // multiplier mask (not owned; null: no multipliers)
};

// Collective. The weighted RMS norm above of `error` for a step from q0 to q1.
double weighted_error_norm(const ErrorTolerance& tol, Vec error, Vec q0, Vec q1);

struct StepOutcome {
  bool converged = false;  // Newton converged (if not, `failure` says why)
  int newton_iterations = 0;
  // Norm of the last Newton residual, N (the solve's measure: reusable_newton.hpp).
  double residual_norm = 0.0;
  // Weighted local error estimate (≤ 1: acceptable) when the integrator has an embedded
  // estimate and the driver asked for it; < 0 otherwise.
  double error = -1.0;
  PetscInt worst_dof = -1;  // global DOF with the largest residual (failures), or −1
  std::string failure;
};

// Collective. For StepOutcome::worst_dof: the global DOF whose row of a Newton residual is
// largest in magnitude, or −1 for an empty vector; each DOF owns rows_per_dof consecutive
// rows (an IRK stage vector interleaves its s stages per DOF, the first-order form q and v).
PetscInt worst_dof(Vec residual, PetscInt rows_per_dof = 1);

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;

  // "hht(alpha=-0.1)", "radau_iia_3", "petsc(alpha2)".
  virtual std::string name() const = 0;
  // Classical order of the step (exponent of step doubling's Richardson estimate).
  virtual int order() const = 0;
  // True if attempt() fills StepOutcome::error from an embedded estimate.
  virtual bool has_embedded_estimate() const = 0;
  // k in ‖embedded estimate‖ = O(h^k) (HHT: 3; Radau IIA: s + 1); 0 without an estimate.
  virtual int estimate_order() const { return 0; }
  // Order of the velocities' global error. Below order() only where index-3 constraints
  // reduce it: an IRK on nonlinear constraints converges in v at its stage order (Radau
  // IIA: s; Hairer & Wanner II, VII.4, Table 4.1). Step doubling then estimates the
  // velocities' error too (transient_solver.hpp).
  virtual int velocity_order() const { return order(); }

  // Collective. Sets the state at time t (vectors are copied). a may be null: then the
  // consistent acceleration M a = −f(t, q, v) is computed.
  virtual void set_state(double t, Vec q, Vec v, Vec a) = 0;
  // Collective. Attempts a step of size h from the current state. The current state does
  // not change; the result is pending until accept(). tol is used only for the embedded
  // estimate (null: none wanted). Throws only on programming or PETSc errors: Newton
  // failure is reported in the outcome.
  virtual StepOutcome attempt(double h, const ErrorTolerance* tol) = 0;
  // Collective. The pending step (the last converged attempt) becomes the current state.
  virtual void accept() = 0;
  // Collective. After accept(): q and v at t ∈ [t_previous, t_current] by the method's
  // dense output (either vector may be null).
  virtual void interpolate(double t, Vec q, Vec v) = 0;

  virtual double time() const = 0;
  virtual double previous_time() const = 0;  // start of the last accepted step
  // Current state (owned by the integrator; copy to keep).
  virtual Vec q() const = 0;
  virtual Vec v() const = 0;
  virtual Vec a() const = 0;
  // The pending state of the last converged attempt (valid until the next attempt).
  virtual Vec pending_q() const = 0;
  virtual Vec pending_v() const = 0;

  virtual const IntegratorCounters& counters() const = 0;
  // After accept(): the contact forces at t ∈ [previous_time(), time()] (N, one per
  // model::MovingContact) into `out`, when the integrator solves for them itself (the modal
  // model, whose q() leaves out the part they depend on); false: the caller evaluates them
  // from the state.
  virtual bool contact_forces_at(double t, std::vector<double>& out) const {
    (void)t;
    (void)out;
    return false;
  }

  // Not collective. After accept(): the current q's entries at `rows` (local rows of its
  // owned part; a row −1, a fixed DOF, gives 0) into `out`, when the integrator has them
  // cheaper than q() (the modal model rebuilds q from every mode); false: the caller reads
  // q().
  virtual bool current_entries(const std::vector<PetscInt>& rows, std::vector<double>& out) const {
    (void)rows;
    (void)out;
    return false;
  }

  // Not collective. After set_state(): the longest step the method is stable for from the
  // initial state (an explicit method's 2/ω_max), +∞ for the unconditionally stable ones;
  // the driver refuses a longer fixed step and caps adaptive ones there.
  virtual double stable_step() const { return std::numeric_limits<double>::infinity(); }
  // Not collective. Why stable_step() is what it is, for the driver's message.
  virtual std::string stable_step_reason() const { return {}; }
  // Not collective. The largest ratio h_{n+1}/h_n of successive steps the method takes
  // safely: a variable-step multistep formula loses zero-stability when its steps grow
  // faster (BDF-2 beyond 1 + √2); the driver's adaptive growth stays below it. +∞ for
  // one-step methods.
  virtual double max_step_ratio() const { return std::numeric_limits<double>::infinity(); }

  // Restarts (resume_state.hpp). Not collective. After accept(): what this integrator
  // carries to its next step beyond (t, q, v, a), its counters included; the vectors are
  // its own, valid until the next attempt. Default: nothing (a restart then starts afresh).
  virtual void save_resume_state(ResumeState& out) const { (void)out; }
  // Collective. After set_state() with the saved (t, q, v, a): continue as the integrator
  // that saved `in` would have (re-evaluating its reused tangent where it was evaluated).
  // An empty `in` (an older checkpoint) changes nothing. Throws catena::Error if an entry
  // is missing.
  virtual void restore_resume_state(const ResumeState& in) { (void)in; }

  // Not collective. The state set last (set_state) lies elsewhere in the model than the
  // one before it (a moving window's state moved back a span): a Jacobian the method
  // reuses belongs to the old place (a contact's coupling on another element) and is to be
  // evaluated afresh. Methods that discard it in set_state already need nothing.
  virtual void forget_jacobian() {}
  // Whether the two above carry everything, so that a restart on the same ranks continues
  // bit for bit.
  virtual bool resumes_exactly() const { return false; }
};

}  // namespace catena::solvers

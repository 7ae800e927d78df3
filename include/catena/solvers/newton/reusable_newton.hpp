#pragma once
// Newton's method on SNES + MUMPS with the matrix kept across solves: the simplified
// Newton iteration of implicit integrators (Hairer & Wanner II, IV.8), in which the
// factorisation of one step is reused by the next steps while the iteration contracts
// fast, and refreshed only when it does not.
//
// Two levels of freshness, because they cost differently:
//   tangent   — the element Jacobians K, C (one element pass): invalidate_tangent();
//   matrix    — the Newton matrix built from them with the step's coefficients (h):
//               invalidate_matrix(); every rebuild is one numeric factorisation.
// The owner's Jacobian callback is told which one to redo. When the contraction
// ‖F_{k+1}‖/‖F_k‖ of a step taken with a tangent evaluated at an earlier iterate (of this
// solve or an earlier one) exceeds `refresh_contraction`, the tangent is re-evaluated at
// the current iterate; a Newton step from a tangent evaluated at its own starting iterate
// that contracts by more than `divergence_contraction` twice in a row, or the iteration
// limit, fails the solve (the caller cuts the step). Refreshing again within a solve
// matters where the force law has kinks (tension-only droppers, contact): an iterate that
// crosses a kink after the refresh makes that tangent as wrong as a stale one, and iterating
// on with it converged linearly, often beyond the iteration limit (docs/validation.md,
// "Dropper slack and re-tension"). `full_newton` re-evaluates the tangent at every iterate.
//
// Convergence: ‖F‖ ≤ atol (set per solve), or a Newton update below kNewtonStepTolerance
// relative to the iterate (round-off). ‖F‖ is the 2-norm, or the owner's measure of the
// solve (`ResidualMeasure`: e.g. constraint rows weighted down to their own round-off
// floor, so that the force rows still meet atol); the contraction rates use the same
// measure (a local correction tests the plain 2-norm: stricter). Failures are reported,
// not thrown.
#include <petscsnes.h>

#include <functional>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/petsc_handle.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/resume_state.hpp"

namespace catena::solvers {

struct NewtonCounters {
  long iterations = 0;
  long local_corrections = 0;  // solves a local correction finished
  long residual_evaluations = 0;
  long tangent_evaluations = 0;
  long factorizations = 0;
  long linear_solves = 0;
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  double residual_norm = 0.0;
  double max_contraction = 0.0;  // largest ‖F_{k+1}‖/‖F_k‖ seen
  std::string failure;           // empty if converged
};

struct NewtonSettings {
  int max_iterations = 10;
  bool full_newton = false;
  // Refresh a stale tangent above this rate; -<prefix>newton_refresh_contraction overrides it.
  double refresh_contraction = 0.3;
  double divergence_contraction = 0.9;   // fail above this rate with a fresh tangent
  Pivoting pivoting = Pivoting::needed;  // may the factorisation skip pivoting (direct_newton.hpp)
};

class ReusableNewton {
 public:
  // F(x, r): the residual. J(x, refresh_tangent, J): builds the Newton matrix; re-evaluate
  // the element tangent first if refresh_tangent (else rebuild from the stored one).
  using Residual = std::function<void(Vec x, Vec r)>;
  using MatrixBuilder = std::function<void(Vec x, bool refresh_tangent, Mat J)>;

  // Collective. J: the matrix to build into (its pattern fixed); r: a residual-shaped
  // vector (kept). Options prefix `prefix` (e.g. "irk_": -irk_ksp_type, ...).
  ReusableNewton(MPI_Comm comm, Mat J, Vec r, const std::string& prefix, JacobianSymmetry symmetry,
                 const NewtonSettings& settings, Residual residual, MatrixBuilder builder);
  ~ReusableNewton();
  ReusableNewton(const ReusableNewton&) = delete;
  ReusableNewton& operator=(const ReusableNewton&) = delete;

  // The matrix coefficients changed (e.g. a new step size): rebuild before the next solve.
  void invalidate_matrix() { matrix_valid_ = false; }
  // The tangent is out of date: re-evaluate it before the next solve.
  void invalidate_tangent() {
    tangent_valid_ = false;
    matrix_valid_ = false;
  }

  // Collective. The measure ‖F‖ that convergence is tested on; empty: the 2-norm.
  using ResidualMeasure = std::function<double(Vec F)>;
  // Collective. Solves F(x) = 0 from the initial guess in x, to ‖F‖ ≤ atol in `measure`.
  // A solve that started from the tangent of an earlier solve and fails is retried once
  // from the same guess with a fresh tangent; `iterations` counts both attempts.
  NewtonResult solve(Vec x, double atol, ResidualMeasure measure = {});

  // Collective. One Newton step from x with the current matrix, built (and factored) first
  // only if it is out of date: x ← x − J⁻¹ F(x). No convergence test, no line search, no
  // local correction: one residual and one pair of triangular solves (the linearly implicit
  // step of a fixed-cost integrator). `converged` is false only if F(x) is not finite or
  // the linear solve failed (`failure` says why); residual_norm is ‖F(x)‖ before the step.
  NewtonResult linear_step(Vec x);

  const NewtonCounters& counters() const { return counters_; }
  KSP ksp() const;

  // Restarts (resume_state.hpp). Not collective. Whether the tangent is current, and the
  // counters, as entries "newton.*".
  void save_resume_state(ResumeState& out) const;
  // Not collective. Restores them. The owner restores its tangent (the element matrices)
  // itself; the Newton matrix is rebuilt from it and refactored at the next solve (the
  // same matrix as the saved run's, so the same factors; one more factorisation counted).
  void restore_resume_state(const ResumeState& in);

  // For an owner that puts its own linear solver into the KSP (a PCSHELL, e.g. the
  // decoupled IRK stage solve): its callbacks store their exceptions in this guard, which
  // solve() rethrows after SNESSolve returns; `check` (not collective, same answer on every
  // rank) is asked after every solve and returns why the linear solves failed, or nothing
  // (MUMPS's status is read here only when the KSP's own PC is the factorisation).
  using LinearSolveCheck = std::function<std::string()>;
  CallbackGuard& callback_guard() { return guard_; }

  // Collective. Tried after every Newton iteration that leaves ‖F‖ above the tolerance,
  // before the contraction rules: may finish the solve by changing x and F in place
  // (returns true and the new ‖F‖; e.g. LocalNewton), and leaves both unchanged when it
  // returns false.
  using LocalCorrection = std::function<bool(Vec x, Vec F, double atol, double* norm)>;
  void set_local_correction(LocalCorrection correction) { local_ = std::move(correction); }
  void set_linear_solve_check(LinearSolveCheck check) { linear_check_ = std::move(check); }

 private:
  NewtonResult solve_once(Vec x, double atol, bool full_newton);
  // Collective. After SNESSolve: why its linear solves failed (the factorisation's status,
  // the owner's check, a failed PC), or "".
  std::string linear_failure(SNESConvergedReason reason, PetscInt its) const;
  static PetscErrorCode form_function(SNES, Vec x, Vec r, void* ctx);
  static PetscErrorCode form_jacobian(SNES, Vec x, Mat J, Mat P, void* ctx);
  // Collective. Runs the local correction on SNES's iterate and residual: true if it ended
  // the solve (an exception it throws is kept in guard_, and converged() stops SNESSolve).
  bool try_local_correction(SNES snes);
  static PetscErrorCode converged(SNES, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                  PetscReal fnorm, SNESConvergedReason* reason, void* ctx);

  NewtonSettings settings_;
  std::string prefix_;
  JacobianSymmetry symmetry_;
  Residual residual_fn_;
  MatrixBuilder builder_;
  LinearSolveCheck linear_check_;
  LocalCorrection local_;
  Vec residual_;
  VecHandle guess_;  // the initial guess, kept for a retry (created at the first need)
  VecHandle step_;   // linear_step's update (created at the first need)
  SnesHandle snes_;
  CallbackGuard guard_;
  NewtonCounters counters_;
  bool tangent_valid_ = false, matrix_valid_ = false;
  // The iterate (SNES iteration number) of the current solve at which the tangent was last
  // evaluated; −1: in an earlier solve.
  PetscInt tangent_iterate_ = -1;
  bool full_newton_now_ = false;  // this solve re-evaluates the tangent at every iterate
  double local_norm_ = -1.0;  // ‖F‖ after a local correction that ended the solve, else −1
  double atol_ = 0.0, previous_norm_ = 0.0, previous_theta_ = 0.0, max_contraction_ = 0.0;
  ResidualMeasure measure_;  // of the current solve
  std::string failure_;
};

}  // namespace catena::solvers

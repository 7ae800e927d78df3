#include "catena/solvers/newton/reusable_newton.hpp"

#include <cmath>
#include <sstream>

#include "catena/core/error.hpp"
#include "catena/solvers/newton/mumps_status.hpp"

namespace catena::solvers {

ReusableNewton::ReusableNewton(MPI_Comm comm, Mat J, Vec r, const std::string& prefix,
                               JacobianSymmetry symmetry, const NewtonSettings& settings,
                               Residual residual, MatrixBuilder builder)
    : settings_(settings),
      prefix_(prefix),
      symmetry_(symmetry),
      residual_fn_(std::move(residual)),
      builder_(std::move(builder)),
      residual_(r) {
  CATENA_PETSC(SNESCreate(comm, snes_.out()));
  CATENA_PETSC(SNESSetFunction(snes_.get(), r, form_function, this));
  CATENA_PETSC(SNESSetJacobian(snes_.get(), J, J, form_jacobian, this));
  configure_direct_newton(snes_.get(), prefix, symmetry, settings.pivoting);
  CATENA_PETSC(SNESSetConvergenceTest(snes_.get(), converged, this, nullptr));
  // -<prefix>newton_refresh_contraction θ overrides the refresh threshold (measured on the
  // moving-load benchmark: docs/performance.md, "HHT step: where the time goes").
  PetscReal theta = settings_.refresh_contraction;
  PetscBool set = PETSC_FALSE;
  const char* name = "-newton_refresh_contraction";
  CATENA_PETSC(PetscOptionsGetReal(nullptr, prefix.c_str(), name, &theta, &set));
  if (set) {
    if (!(theta > 0.0 && theta < 1.0))
      throw InputError(
          {"", 0, "-" + prefix + (name + 1)},
          "refresh contraction " + std::to_string(theta) + " is outside the accepted range (0, 1)");
    settings_.refresh_contraction = theta;
  }
  // Our convergence test owns the iteration limit.
  CATENA_PETSC(SNESSetTolerances(snes_.get(), PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT,
                                 settings.max_iterations + 1, 1000000));
}

ReusableNewton::~ReusableNewton() = default;

KSP ReusableNewton::ksp() const {
  KSP ksp = nullptr;
  CATENA_PETSC(SNESGetKSP(snes_.get(), &ksp));
  return ksp;
}

PetscErrorCode ReusableNewton::form_function(SNES, Vec x, Vec r, void* ctx) {
  auto* self = static_cast<ReusableNewton*>(ctx);
  return self->guard_.run([&] {
    self->residual_fn_(x, r);
    ++self->counters_.residual_evaluations;
  });
}

PetscErrorCode ReusableNewton::form_jacobian(SNES snes, Vec x, Mat J, Mat, void* ctx) {
  auto* self = static_cast<ReusableNewton*>(ctx);
  return self->guard_.run([&] {
    const bool refresh = !self->tangent_valid_ || self->full_newton_now_;
    self->builder_(x, refresh, J);
    if (refresh) {
      self->tangent_valid_ = true;
      CATENA_PETSC(SNESGetIterationNumber(snes, &self->tangent_iterate_));
      ++self->counters_.tangent_evaluations;
    }
    self->matrix_valid_ = true;
    ++self->counters_.factorizations;  // a changed matrix is refactored by the PC
  });
}

PetscErrorCode ReusableNewton::converged(SNES snes, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                         PetscReal fnorm, SNESConvergedReason* reason, void* ctx) {
  auto* self = static_cast<ReusableNewton*>(ctx);
  const NewtonSettings& s = self->settings_;
  *reason = SNES_CONVERGED_ITERATING;
  std::ostringstream why;
  if (std::isfinite(fnorm) && self->measure_) {
    Vec F = nullptr;
    if (SNESGetFunction(snes, &F, nullptr, nullptr) != 0) return PETSC_ERR_LIB;
    if (self->guard_.run([&] { fnorm = self->measure_(F); }) != 0) return PETSC_ERR_USER;
  }
  if (!std::isfinite(fnorm)) {
    why << "the residual is not finite at iteration " << it;
    *reason = SNES_DIVERGED_FNORM_NAN;
  } else if (fnorm <= self->atol_) {
    *reason = SNES_CONVERGED_FNORM_ABS;
  } else if (it > 0 && self->local_ && self->try_local_correction(snes)) {
    *reason = SNES_CONVERGED_FNORM_ABS;
  } else if (self->guard_.has_exception()) {
    return PETSC_ERR_USER;  // the correction threw: SNESSolve stops, solve() rethrows
  } else if (it > 0 && snorm <= kNewtonStepTolerance * xnorm) {
    *reason = SNES_CONVERGED_SNORM_RELATIVE;
  } else if (it > 0) {
    const double theta = self->previous_norm_ > 0.0 ? fnorm / self->previous_norm_ : 0.0;
    self->max_contraction_ = std::max(self->max_contraction_, theta);
    // Fresh: the step to this iterate was a Newton step, its tangent evaluated at the
    // step's start (iterate it − 1).
    const bool fresh = self->tangent_iterate_ == it - 1 || self->full_newton_now_;
    // At this rate the remaining iterations would end at |F| θ^(max − it): if that misses
    // the tolerance, a new tangent now is cheaper than a failed step (the convergence
    // prediction of Hairer & Wanner II, IV.8).
    const bool too_slow =
        theta < 1.0 && fnorm * std::pow(theta, s.max_iterations - it) > self->atol_;
    if ((theta > s.refresh_contraction || too_slow) && !fresh) {
      // The tangent of an earlier iterate no longer contracts well: re-evaluate it now.
      self->tangent_valid_ = false;
      if (SNESSetLagJacobian(snes, -2) != 0) return PETSC_ERR_LIB;
    } else if (theta > s.divergence_contraction &&
               self->previous_theta_ > s.divergence_contraction) {
      // Two poor iterations in a row with a fresh tangent (one is tolerated: full Newton's
      // residual may grow once before it converges).
      why << "Newton does not contract (|F| ratios " << self->previous_theta_ << ", " << theta
          << " at iterations " << it - 1 << ", " << it << ", fresh Jacobian)";
      *reason = SNES_DIVERGED_DTOL;
    }
    self->previous_theta_ = fresh ? theta : 0.0;
    if (*reason == SNES_CONVERGED_ITERATING && it >= s.max_iterations) {
      why << "no convergence in " << s.max_iterations << " Newton iterations (|F| = " << fnorm
          << " N, tolerance " << self->atol_ << " N)";
      *reason = SNES_DIVERGED_MAX_IT;
    }
  }
  self->previous_norm_ = fnorm;
  if (*reason < 0) self->failure_ = why.str();
  return 0;
}

bool ReusableNewton::try_local_correction(SNES snes) {
  Vec x = nullptr, F = nullptr;
  if (SNESGetSolution(snes, &x) != 0 || SNESGetFunction(snes, &F, nullptr, nullptr) != 0)
    return false;
  bool done = false;
  double norm = 0.0;
  if (guard_.run([&] { done = local_(x, F, atol_, &norm); }) != 0) return false;
  if (!done) return false;
  local_norm_ = norm;
  ++counters_.local_corrections;
  return true;
}

void ReusableNewton::save_resume_state(ResumeState& out) const {
  out.integers["newton.tangent_valid"] = tangent_valid_ ? 1 : 0;
  out.integers["newton.iterations"] = counters_.iterations;
  out.integers["newton.local_corrections"] = counters_.local_corrections;
  out.integers["newton.residual_evaluations"] = counters_.residual_evaluations;
  out.integers["newton.tangent_evaluations"] = counters_.tangent_evaluations;
  out.integers["newton.factorizations"] = counters_.factorizations;
  out.integers["newton.linear_solves"] = counters_.linear_solves;
}

void ReusableNewton::restore_resume_state(const ResumeState& in) {
  tangent_valid_ = in.integer("newton.tangent_valid") != 0;
  matrix_valid_ = false;  // the PC holds no factors yet
  counters_.iterations = in.integer("newton.iterations");
  counters_.local_corrections = in.integer("newton.local_corrections");
  counters_.residual_evaluations = in.integer("newton.residual_evaluations");
  counters_.tangent_evaluations = in.integer("newton.tangent_evaluations");
  counters_.factorizations = in.integer("newton.factorizations");
  counters_.linear_solves = in.integer("newton.linear_solves");
}

NewtonResult ReusableNewton::solve(Vec x, double atol, ResidualMeasure measure) {
  measure_ = std::move(measure);
  // A solve that fails after starting from the tangent of an earlier solve is tried once
  // more from the same guess by full Newton (RADAU5 retries with a fresh Jacobian): the
  // failure may be the old tangent's (a step across many kinks, e.g. droppers changing
  // state), not the step size's, and the caller would otherwise halve the step. Full
  // Newton, because between kinks a tangent kept over iterates can make the iteration
  // cycle between two active sets.
  const bool stale_start = tangent_valid_ && !settings_.full_newton;
  if (stale_start) {
    if (!guess_) CATENA_PETSC(VecDuplicate(x, guess_.out()));
    CATENA_PETSC(VecCopy(x, guess_.get()));
  }
  NewtonResult result = solve_once(x, atol, settings_.full_newton);
  if (result.converged || !stale_start) return result;
  CATENA_PETSC(VecCopy(guess_.get(), x));
  const int first_iterations = result.iterations;
  result = solve_once(x, atol, true);
  result.iterations += first_iterations;
  return result;
}

std::string ReusableNewton::linear_failure(SNESConvergedReason reason, PetscInt its) const {
  // A factorisation that fails at the first solve after a rebuild stops SNES before it
  // counts an iteration; with no iteration and no such stop, nothing was factored.
  if (its == 0 && reason != SNES_DIVERGED_LINEAR_SOLVE) return {};
  std::ostringstream os;
  const MumpsStatus mumps = mumps_status(ksp());
  if (mumps.infog1 < 0 || mumps.null_pivots > 0) {
    os << "the Newton matrix could not be factored (MUMPS INFOG(1) = " << mumps.infog1
       << ", null pivots " << mumps.null_pivots << ")";
    return os.str();
  }
  if (linear_check_) {
    if (std::string why = linear_check_(); !why.empty()) return why;
  }
  if (reason != SNES_DIVERGED_LINEAR_SOLVE) return {};
  // E.g. a zero pivot of PETSc's own LU (direct_newton.hpp, Pivoting::not_needed).
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp(), &pc));
  PCFailedReason pc_reason = PC_NOERROR;
  CATENA_PETSC(PCGetFailedReason(pc, &pc_reason));
  KSPConvergedReason ksp_reason = KSP_CONVERGED_ITERATING;
  CATENA_PETSC(KSPGetConvergedReason(ksp(), &ksp_reason));
  os << "the linear solve of the Newton matrix failed (KSP reason "
     << KSPConvergedReasons[ksp_reason] << ", PC " << PCFailedReasons[pc_reason] << ")";
  return os.str();
}

NewtonResult ReusableNewton::solve_once(Vec x, double atol, bool full_newton) {
  full_newton_now_ = full_newton;
  atol_ = atol;
  local_norm_ = -1.0;
  previous_norm_ = -1.0;
  previous_theta_ = 0.0;
  max_contraction_ = 0.0;
  tangent_iterate_ = -1;
  failure_.clear();
  const bool rebuild = !matrix_valid_ || full_newton;
  CATENA_PETSC(SNESSetLagJacobian(snes_.get(), full_newton ? 1 : (rebuild ? -2 : -1)));
  PetscErrorCode ierr = SNESSolve(snes_.get(), nullptr, x);
  guard_.rethrow_if_any();
  CATENA_PETSC(ierr);
  // MUMPS out of workspace (delayed pivots of a saddle-point matrix): the matrix is factored
  // again with a larger margin; PETSc's LU with the multipliers last at a zero pivot: MUMPS
  // factors it (direct_newton.hpp). Newton goes on from the iterate it stopped at.
  for (;;) {
    SNESConvergedReason stopped;
    CATENA_PETSC(SNESGetConvergedReason(snes_.get(), &stopped));
    if (stopped != SNES_DIVERGED_LINEAR_SOLVE) break;
    if (!enlarge_mumps_workspace(ksp(), direct_solve_status(ksp())) &&
        !(settings_.pivoting == Pivoting::constraints_last &&
          fall_back_to_pivoting(ksp(), prefix_, symmetry_)))
      break;
    ierr = SNESSolve(snes_.get(), nullptr, x);
    guard_.rethrow_if_any();
    CATENA_PETSC(ierr);
  }

  NewtonResult result;
  SNESConvergedReason reason;
  PetscInt its = 0;
  CATENA_PETSC(SNESGetConvergedReason(snes_.get(), &reason));
  CATENA_PETSC(SNESGetIterationNumber(snes_.get(), &its));
  PetscReal norm = 0.0;
  CATENA_PETSC(SNESGetFunctionNorm(snes_.get(), &norm));
  if (measure_ && std::isfinite(norm)) {
    Vec F = nullptr;
    CATENA_PETSC(SNESGetFunction(snes_.get(), &F, nullptr, nullptr));
    norm = measure_(F);
  }
  if (local_norm_ >= 0.0) norm = local_norm_;  // SNES keeps the norm before the correction
  counters_.iterations += its;
  counters_.linear_solves += its;
  result.iterations = static_cast<int>(its);
  result.residual_norm = norm;
  result.max_contraction = max_contraction_;
  result.converged = reason > 0;
  if (const std::string why = linear_failure(reason, its); !why.empty()) {
    result.converged = false;
    failure_ = why;
    invalidate_tangent();
  }
  if (!result.converged) {
    if (failure_.empty()) {
      std::ostringstream os;
      os << "SNES stopped with reason " << static_cast<int>(reason) << " after " << its
         << " iterations (|F| = " << norm << " N)";
      failure_ = os.str();
    }
    result.failure = failure_;
    // A failed solve says the tangent is poor for this step: start the retry afresh.
    invalidate_tangent();
  }
  return result;
}

NewtonResult ReusableNewton::linear_step(Vec x) {
  NewtonResult result;
  residual_fn_(x, residual_);
  ++counters_.residual_evaluations;
  PetscReal norm = 0.0;
  CATENA_PETSC(VecNorm(residual_, NORM_2, &norm));
  result.residual_norm = norm;
  if (!std::isfinite(norm)) {
    result.failure = "the residual is not finite";
    invalidate_tangent();
    return result;
  }
  const KSP solver = ksp();
  if (!matrix_valid_) {
    Mat J = nullptr;
    CATENA_PETSC(SNESGetJacobian(snes_.get(), &J, nullptr, nullptr, nullptr));
    const bool refresh = !tangent_valid_;
    builder_(x, refresh, J);
    if (refresh) {
      tangent_valid_ = true;
      ++counters_.tangent_evaluations;
    }
    matrix_valid_ = true;
    ++counters_.factorizations;  // the changed matrix is refactored at the solve
    CATENA_PETSC(KSPSetOperators(solver, J, J));
  }
  if (!step_) CATENA_PETSC(VecDuplicate(x, step_.out()));
  CATENA_PETSC(KSPSolve(solver, residual_, step_.get()));
  while (enlarge_mumps_workspace(solver, direct_solve_status(solver)))
    CATENA_PETSC(KSPSolve(solver, residual_, step_.get()));
  ++counters_.iterations;
  ++counters_.linear_solves;
  result.iterations = 1;
  const DirectSolveStatus status = direct_solve_status(solver);
  if (status.failed()) {
    result.failure = "the linear solve of the Newton matrix failed (" + status.describe() + ")";
    invalidate_tangent();
    return result;
  }
  // No residual follows at the new iterate: a factorisation without pivoting (PETSc's LU)
  // may return a non-finite update without reporting it, which would be accepted here.
  PetscReal step_norm = 0.0;
  CATENA_PETSC(VecNorm(step_.get(), NORM_INFINITY, &step_norm));
  if (!std::isfinite(step_norm)) {
    result.failure = "the Newton step is not finite";
    invalidate_tangent();
    return result;
  }
  CATENA_PETSC(VecAXPY(x, -1.0, step_.get()));
  result.converged = true;
  return result;
}

}  // namespace catena::solvers

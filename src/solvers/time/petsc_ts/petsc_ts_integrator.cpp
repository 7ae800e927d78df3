#include "catena/solvers/time/petsc_ts/petsc_ts_integrator.hpp"

#include <petscts.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/newton/mumps_status.hpp"
#include "catena/solvers/time/petsc_ts/first_order_form.hpp"
#include "catena/solvers/time/step_state.hpp"
#include "petsc_ts_methods.hpp"

namespace catena::solvers {

using TsHandle = PetscHandle<TS, TSDestroy>;

// Where the TS stands relative to our current state (t0, q0, v0):
//   synced — at it, with its history (the last accepted step, or a fresh restart);
//   ahead  — at the end of a converged attempt the driver has not accepted (yet);
//   stale  — anywhere else (a failed step, a new state): copy ours in and restart.
enum class TsState { synced, ahead, stale };

// PETSc 3.18's alpha2 start-up returns this multiple of the acceleration of its two
// backward-Euler half steps (see Impl::in_alpha2_startup).
constexpr double kStartupGain = 2.0;

struct PetscTsIntegrator::Impl {
  assembly::SecondOrderSystem& system;
  PetscTsOptions options;
  TsHandle ts;
  std::string type;
  detail::TsMethodTraits traits;
  bool second_order = false;  // alpha2: the I2Function form
  bool ts_interpolate_ok = true;

  MatHandle M, K, C, J;                  // n×n; J: alpha2's Newton matrix
  std::unique_ptr<FirstOrderForm> form;  // first-order types
  VecHandle X, V, F;                     // alpha2: TS solution (U, U̇) and residual
  VecHandle U, G, U_work;                // first-order: TS solution, residual, work
  VecHandle qw, vw, qdw, vdw, fw, Mb;    // n-vector work; Mb = M a0/κ for the start-up
  KspHandle mass_ksp;                    // M a = −f for Hermite's accelerations

  // The current state (t0, q0, v0, a0), the one before (dense output) and the pending step.
  // First-order types leave the accelerations unknown until dense output or a() needs them
  // (solve_acceleration).
  StepState& state;

  TsState ts_state = TsState::stale;
  bool restart_scheduled = false;    // TSRestartStep called: the next TSStep restarts
  bool last_step_restarted = false;  // the pending step was a restart step
  int stages_this_step = 0;          // TSPreStage calls in the current TSStep
  int checked_stage = 0;             // the stage check_alpha2_start last looked at

  double scale_ref = 0.0, scale_last = 0.0, scale = 0.0;  // element force norms, N
  std::string newton_failure;
  CallbackGuard guard;
  IntegratorCounters counters;

  Impl(assembly::SecondOrderSystem& s, const PetscTsOptions& o, StepState& st)
      : system(s), options(o), state(st) {
    state.set_lazy_acceleration(
        [this](double t, Vec q, Vec v, Vec a) { solve_acceleration(t, q, v, a); });
  }

  // alpha2 start-up. After TSRestartStep, PETSc's alpha2 (alpha2.c, TSAlpha_Restart)
  // finds A₀ from two backward-Euler half steps of k = h/2 (generalised-α with alpha_m =
  // alpha_f = gamma = 1, beta = ½, each preceded by TSPreStage) as
  //   A₀ = (−3V₀ + 4V₁ − V₂)/k,
  // which is twice the backward-difference derivative (that divides by 2k = h): PETSc
  // 3.18 starts with about 2a, an O(1) error that makes the run first order (measured:
  // docs/integrators.md). During those two stages the bridge solves M A = M a0/κ, κ =
  // kStartupGain = 2, instead of the equation of motion: then V₁ = V₀ + a0 k/κ, V₂ = V₀ +
  // 2a0 k/κ, and PETSc's formula returns A₀ = a0 to round-off (ε|V₀|/h), a0 being the
  // state's consistent (or carried) acceleration. check_alpha2_start() measures the A₀
  // PETSc actually uses at the main stage's first residual, so a change in PETSc's
  // start-up becomes an error, not a silently different method. Stages come in threes
  // (two start-up, one main) while the restart lasts: PETSc's own adaptivity
  // (-ts_adapt_type) may reject the main stage and restart again within one TSStep.
  bool in_alpha2_startup() const {
    if (!second_order || !restart_scheduled || stages_this_step % 3 == 0) return false;
    PetscReal am = 0, af = 0, g = 0, b = 0;
    CATENA_PETSC(TSAlpha2GetParams(ts.get(), &am, &af, &g, &b));
    if (am != 1.0 || af != 1.0 || g != 1.0 || b != 0.5)
      throw std::logic_error(
          "PetscTsIntegrator: PETSc's alpha2 start-up is not the two "
          "backward-Euler half steps this bridge expects");
    return true;
  }

  // At the main stage's first residual after a restart PETSc evaluates at X₁ = X₀, where
  //   A_α = c A₀ − alpha_m V₀/(hβ),  c = (1 − alpha_m) − alpha_m (1 − 2β)/(2β)
  // (alpha2.c, TSAlpha_StageVecs): solve for the A₀ PETSc uses and compare with a0.
  void check_alpha2_start(Vec a_stage) {
    checked_stage = stages_this_step;
    PetscReal am = 0, af = 0, gamma = 0, beta = 0, h = 0;
    CATENA_PETSC(TSAlpha2GetParams(ts.get(), &am, &af, &gamma, &beta));
    CATENA_PETSC(TSGetTimeStep(ts.get(), &h));
    const double c = (1 - am) - am * (1 - 2 * beta) / (2 * beta);
    if (std::abs(c) < 1e-3) return;  // A₀ not observable this way (user parameters)
    // qw = (A_α + alpha_m V₀/(hβ))/c − a0
    CATENA_PETSC(VecWAXPY(qw.get(), am / (h * beta), state.v(), a_stage));
    CATENA_PETSC(VecScale(qw.get(), 1.0 / c));
    CATENA_PETSC(VecAXPY(qw.get(), -1.0, state.a()));
    PetscReal gap = 0, a_norm = 0, v_norm = 0;
    CATENA_PETSC(VecNorm(qw.get(), NORM_INFINITY, &gap));
    CATENA_PETSC(VecNorm(state.a(), NORM_INFINITY, &a_norm));
    CATENA_PETSC(VecNorm(state.v(), NORM_INFINITY, &v_norm));
    if (gap > 1e-8 * (a_norm + v_norm / h) + 1e-300) {
      std::ostringstream os;
      os << "PetscTsIntegrator: PETSc's alpha2 start-up did not return the state's "
            "acceleration (off by "
         << gap << " m/s^2, |a0| = " << a_norm
         << "); its start-up procedure differs from the one this bridge corrects";
      throw std::logic_error(os.str());
    }
  }

  void evaluate_force(double t, Vec q, Vec v, Vec f) {
    double s = 0.0;
    system.force({q, v, {}, t}, f, &s);
    scale = std::max(scale, s);
    scale_last = s;
    ++counters.residual_evaluations;
  }

  // F(t, U, V, A) = M A + f(t, U, V).
  static PetscErrorCode i2_function(TS, PetscReal t, Vec x, Vec v, Vec a, Vec out, void* ctx) {
    auto* s = static_cast<Impl*>(ctx);
    return s->guard.run([&] {
      if (s->in_alpha2_startup()) {
        CATENA_PETSC(MatMult(s->M.get(), a, out));
        CATENA_PETSC(VecAXPY(out, -1.0, s->Mb.get()));
        return;
      }
      if (s->second_order && s->restart_scheduled && s->checked_stage != s->stages_this_step)
        s->check_alpha2_start(a);
      s->evaluate_force(t, x, v, s->fw.get());
      CATENA_PETSC(MatMultAdd(s->M.get(), a, s->fw.get(), out));
    });
  }

  // J = K + shiftV C + shiftA M (PETSc: ∂F/∂U + shiftV ∂F/∂V + shiftA ∂F/∂A).
  static PetscErrorCode i2_jacobian(TS, PetscReal t, Vec x, Vec v, Vec, PetscReal shift_v,
                                    PetscReal shift_a, Mat J, Mat, void* ctx) {
    auto* s = static_cast<Impl*>(ctx);
    return s->guard.run([&] {
      if (s->in_alpha2_startup()) {
        CATENA_PETSC(MatCopy(s->M.get(), J, SAME_NONZERO_PATTERN));
        CATENA_PETSC(MatScale(J, shift_a));
      } else {
        s->system.tangent_parts({x, v, {}, t}, s->K.get(), s->C.get());
        ++s->counters.jacobian_evaluations;
        CATENA_PETSC(MatCopy(s->K.get(), J, SAME_NONZERO_PATTERN));
        CATENA_PETSC(MatAXPY(J, shift_v, s->C.get(), SAME_NONZERO_PATTERN));
        CATENA_PETSC(MatAXPY(J, shift_a, s->M.get(), SAME_NONZERO_PATTERN));
      }
      ++s->counters.factorizations;  // a changed matrix is refactored by the PC
    });
  }

  // G(t, U, U̇) = [q̇ − v; M v̇ + f(t, q, v)].
  static PetscErrorCode i_function(TS, PetscReal t, Vec u, Vec u_dot, Vec out, void* ctx) {
    auto* s = static_cast<Impl*>(ctx);
    return s->guard.run([&] {
      s->form->split(u, s->qw.get(), s->vw.get());
      s->form->split(u_dot, s->qdw.get(), s->vdw.get());
      s->evaluate_force(t, s->qw.get(), s->vw.get(), s->fw.get());
      CATENA_PETSC(MatMultAdd(s->M.get(), s->vdw.get(), s->fw.get(), s->fw.get()));
      CATENA_PETSC(VecAXPY(s->qdw.get(), -1.0, s->vw.get()));
      s->form->join(s->qdw.get(), s->fw.get(), out);
    });
  }

  // ∂G/∂U + σ ∂G/∂U̇ = [σI, −I; K, C + σM].
  static PetscErrorCode i_jacobian(TS, PetscReal t, Vec u, Vec, PetscReal sigma, Mat, Mat,
                                   void* ctx) {
    auto* s = static_cast<Impl*>(ctx);
    return s->guard.run([&] {
      s->form->split(u, s->qw.get(), s->vw.get());
      s->system.tangent_parts({s->qw.get(), s->vw.get(), {}, t}, s->K.get(), s->C.get());
      ++s->counters.jacobian_evaluations;
      s->form->assemble(sigma, s->K.get(), s->C.get(), s->M.get());
      ++s->counters.factorizations;
    });
  }

  static PetscErrorCode pre_stage(TS ts, PetscReal) {
    void* ctx = nullptr;
    PetscCall(TSGetApplicationContext(ts, &ctx));
    ++static_cast<Impl*>(ctx)->stages_this_step;
    return 0;
  }

  // Catena's Newton test (ReusableNewton's, without its matrix reuse).
  static PetscErrorCode converged(SNES, PetscInt it, PetscReal xnorm, PetscReal snorm,
                                  PetscReal fnorm, SNESConvergedReason* reason, void* ctx) {
    auto* s = static_cast<Impl*>(ctx);
    const double tolerance = s->options.atol + s->options.rtol * s->scale;
    *reason = SNES_CONVERGED_ITERATING;
    std::ostringstream why;
    if (!std::isfinite(fnorm)) {
      why << "the residual is not finite at Newton iteration " << it;
      *reason = SNES_DIVERGED_FNORM_NAN;
    } else if (fnorm <= tolerance) {
      *reason = SNES_CONVERGED_FNORM_ABS;
    } else if (it > 0 && snorm <= kNewtonStepTolerance * xnorm) {
      *reason = SNES_CONVERGED_SNORM_RELATIVE;
    } else if (it >= s->options.max_newton_iterations) {
      why << "no convergence in " << it << " Newton iterations (|F| = " << fnorm << ", tolerance "
          << tolerance << " N)";
      *reason = SNES_DIVERGED_MAX_IT;
    }
    if (*reason < 0) s->newton_failure = why.str();
    return 0;
  }

  // The TS's own solution vector(s), set to (q, v).
  void write_ts_state(Vec q, Vec v) {
    if (second_order) {
      Vec x = nullptr, xd = nullptr;
      CATENA_PETSC(TS2GetSolution(ts.get(), &x, &xd));
      CATENA_PETSC(VecCopy(q, x));
      CATENA_PETSC(VecCopy(v, xd));
    } else {
      Vec u = nullptr;
      CATENA_PETSC(TSGetSolution(ts.get(), &u));
      form->join(q, v, u);
    }
  }

  void read_ts_state(Vec q, Vec v) {
    if (second_order) {
      Vec x = nullptr, xd = nullptr;
      CATENA_PETSC(TS2GetSolution(ts.get(), &x, &xd));
      CATENA_PETSC(VecCopy(x, q));
      CATENA_PETSC(VecCopy(xd, v));
    } else {
      Vec u = nullptr;
      CATENA_PETSC(TSGetSolution(ts.get(), &u));
      form->split(u, q, v);
    }
  }

  void restart_from_current() {
    CATENA_PETSC(TSSetTime(ts.get(), state.time()));
    write_ts_state(state.q(), state.v());
    CATENA_PETSC(TSRestartStep(ts.get()));
    if (second_order) {
      CATENA_PETSC(MatMult(M.get(), state.a(), Mb.get()));
      CATENA_PETSC(VecScale(Mb.get(), 1.0 / kStartupGain));
    }
    restart_scheduled = true;
  }

  // Brings the TS back to (t0, q0, v0) before an attempt.
  void prepare_attempt() {
    if (ts_state == TsState::ahead && traits.keeps_history && !last_step_restarted)
      CATENA_PETSC(TSRollBack(ts.get()));  // exact for bdf and alpha2: a copy, history kept
    else if (ts_state != TsState::synced)
      restart_from_current();
    ts_state = TsState::synced;
  }

  // M a = −f(t, q, v) with one factorisation of M kept for the run.
  void solve_acceleration(double t, Vec q, Vec v, Vec a) {
    if (!mass_ksp) {
      mass_ksp = create_direct_ksp(system.comm(), "mass_", JacobianSymmetry::symmetric);
      CATENA_PETSC(KSPSetOperators(mass_ksp.get(), M.get(), M.get()));
    }
    evaluate_force(t, q, v, fw.get());
    CATENA_PETSC(VecScale(fw.get(), -1.0));
    CATENA_PETSC(KSPSolve(mass_ksp.get(), fw.get(), a));
    if (const DirectSolveStatus status = direct_solve_status(mass_ksp.get()); status.failed())
      throw NumericalError("PetscTsIntegrator: the mass matrix could not be factored (" +
                           status.describe() + ")");
  }

  // The global DOF with the largest |entry| of the last Newton residual (−1 if none).
  PetscInt worst_residual_dof(SNES snes) const {
    Vec r = nullptr;
    CATENA_PETSC(SNESGetFunction(snes, &r, nullptr, nullptr));
    if (!r) return -1;
    return worst_dof(r, second_order ? 1 : 2);  // first-order rows 2g, 2g + 1: DOF g
  }
};

PetscTsIntegrator::PetscTsIntegrator(assembly::SecondOrderSystem& system,
                                     const PetscTsOptions& options)
    : StepStateIntegrator(system) {
  if (!(options.alpha >= -1.0 / 3.0 && options.alpha <= 0.0))
    throw InputError({"", 0, "integrator.alpha"}, "HHT alpha = " + std::to_string(options.alpha) +
                                                      " is outside the accepted range [-1/3, 0]");
  // TS sees an ODE: multiplier rows (g = 0, no mass) would be a DAE it cannot integrate.
  if (system.has_constraints())
    throw InputError({"", 0, "integrator.type"},
                     "the PETSc TS bridge takes no Lagrange-multiplier constraints");
  impl_ = std::make_unique<Impl>(system, options, step_state());
  Impl& s = *impl_;
  for (VecHandle* v : {&s.qw, &s.vw, &s.qdw, &s.vdw, &s.fw, &s.Mb}) *v = system.create_vector();
  for (MatHandle* m : {&s.M, &s.K, &s.C}) *m = system.create_matrix();
  // M is constant (ANCF); K and C are evaluated once here for their patterns.
  system.reference_state(s.qw.get());
  system.jacobian({s.qw.get(), nullptr, {}}, {0.0, 0.0, 1.0}, s.M.get());
  system.tangent_parts({s.qw.get(), s.vw.get(), {}}, s.K.get(), s.C.get());

  CATENA_PETSC(TSCreate(system.comm(), s.ts.out()));
  TS ts = s.ts.get();
  CATENA_PETSC(TSSetType(ts, TSALPHA2));
  // HHT-α as generalised-α (header); -ts_alpha_* options override it below.
  const double alpha = options.alpha;
  CATENA_PETSC(
      TSAlpha2SetParams(ts, 1.0, 1.0 + alpha, 0.5 - alpha, 0.25 * (1.0 - alpha) * (1.0 - alpha)));
  // The driver decides where to stop; TSStep only insists that some end is set.
  CATENA_PETSC(TSSetMaxTime(ts, 0.5 * PETSC_MAX_REAL));
  CATENA_PETSC(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_STEPOVER));
  // One nonlinear failure ends the step: the driver, not PETSc, cuts h.
  CATENA_PETSC(TSSetMaxSNESFailures(ts, 1));
  CATENA_PETSC(TSSetErrorIfStepFails(ts, PETSC_FALSE));
  TSAdapt adapt = nullptr;
  CATENA_PETSC(TSGetAdapt(ts, &adapt));
  CATENA_PETSC(TSAdaptSetType(adapt, TSADAPTNONE));
  SNES snes = nullptr;
  CATENA_PETSC(TSGetSNES(ts, &snes));
  SNESLineSearch line_search = nullptr;
  CATENA_PETSC(SNESGetLineSearch(snes, &line_search));
  CATENA_PETSC(SNESLineSearchSetType(line_search, SNESLINESEARCHBASIC));
  CATENA_PETSC(SNESSetDivergenceTolerance(snes, -1.0));
  CATENA_PETSC(SNESSetTolerances(snes, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT,
                                 options.max_newton_iterations + 1, 1000000));
  CATENA_PETSC(SNESSetConvergenceTest(snes, Impl::converged, &s, nullptr));
  KSP ksp = nullptr;
  PC pc = nullptr;
  CATENA_PETSC(SNESGetKSP(snes, &ksp));
  CATENA_PETSC(KSPSetType(ksp, KSPPREONLY));
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  CATENA_PETSC(PCSetType(pc, PCLU));  // damping makes the matrices non-symmetric
  CATENA_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  CATENA_PETSC(TSSetFromOptions(ts));

  TSType type = nullptr;
  CATENA_PETSC(TSGetType(ts, &type));
  s.type = type;
  s.second_order = s.type == TSALPHA2;
  s.traits = detail::ts_method_traits(ts);
  PetscBool snes_type_given = PETSC_FALSE;
  CATENA_PETSC(PetscOptionsHasName(nullptr, nullptr, "-snes_type", &snes_type_given));
  // Rosenbrock stages are linear by construction: one solve each (PETSc's own default,
  // lost once SNESSetFromOptions has chosen newtonls). Newton iterating them to
  // convergence would make a different, fully implicit method.
  if (s.type == TSROSW && !snes_type_given) CATENA_PETSC(SNESSetType(snes, SNESKSPONLY));
  if (!s.traits.supported)
    throw InputError({"", 0, "-ts_type"},
                     "PETSc TS type '" + s.type + "' is not supported by integrator type petsc: " +
                         s.traits.refusal + "; accepted: " + detail::kSupportedTsTypes);
  if (s.second_order) {
    s.X = system.create_vector();
    s.V = system.create_vector();
    s.F = system.create_vector();
    CATENA_PETSC(TS2SetSolution(ts, s.X.get(), s.V.get()));
    CATENA_PETSC(TSSetI2Function(ts, s.F.get(), Impl::i2_function, &s));
    CATENA_PETSC(MatDuplicate(s.M.get(), MAT_COPY_VALUES, s.J.out()));
    CATENA_PETSC(TSSetI2Jacobian(ts, s.J.get(), s.J.get(), Impl::i2_jacobian, &s));
  } else {
    s.form = std::make_unique<FirstOrderForm>(s.K.get(), s.C.get(), s.M.get());
    s.U = s.form->create_vector();
    s.G = s.form->create_vector();
    s.U_work = s.form->create_vector();
    CATENA_PETSC(TSSetSolution(ts, s.U.get()));
    CATENA_PETSC(TSSetIFunction(ts, s.G.get(), Impl::i_function, &s));
    Mat B = s.form->matrix();
    CATENA_PETSC(TSSetIJacobian(ts, B, B, Impl::i_jacobian, &s));
  }
  CATENA_PETSC(TSSetApplicationContext(ts, &s));
  CATENA_PETSC(TSSetPreStage(ts, Impl::pre_stage));
  CATENA_PETSC(TSSetUp(ts));
}

PetscTsIntegrator::~PetscTsIntegrator() = default;

std::string PetscTsIntegrator::name() const { return "petsc(" + impl_->type + ")"; }
std::string PetscTsIntegrator::ts_type() const { return impl_->type; }
int PetscTsIntegrator::order() const { return impl_->traits.order; }

void PetscTsIntegrator::set_state(double t, Vec q, Vec v, Vec a) {
  Impl& s = *impl_;
  // Without a: alpha2 carries it, so the consistent one now; first-order types need it only
  // for dense output (Hermite), so it is solved for when first needed.
  s.state.start(t, q, v, a,
                s.second_order ? consistent_acceleration_of(s.system, s.M.get()) : nullptr);
  s.scale_ref = s.system.element_force_norm({s.state.q(), s.state.v(), {}, t});
  s.ts_state = TsState::stale;
}

StepOutcome PetscTsIntegrator::attempt(double h, const ErrorTolerance*) {
  Impl& s = *impl_;
  TS ts = s.ts.get();
  s.state.discard_pending();
  s.prepare_attempt();
  CATENA_PETSC(TSSetTimeStep(ts, h));
  s.stages_this_step = 0;
  s.checked_stage = 0;
  s.scale = s.scale_ref;
  s.newton_failure.clear();
  PetscInt snes_before = 0, ksp_before = 0, snes_after = 0, ksp_after = 0;
  CATENA_PETSC(TSGetSNESIterations(ts, &snes_before));
  CATENA_PETSC(TSGetKSPIterations(ts, &ksp_before));
  const PetscErrorCode ierr = TSStep(ts);
  s.guard.rethrow_if_any();
  CATENA_PETSC(ierr);
  CATENA_PETSC(TSGetSNESIterations(ts, &snes_after));
  CATENA_PETSC(TSGetKSPIterations(ts, &ksp_after));
  // The counts are cumulative per TSSolve; TSStep alone never resets them.
  const PetscInt newton = snes_after - snes_before, linear = ksp_after - ksp_before;
  s.counters.newton_iterations += newton;
  s.counters.linear_solves += linear;

  SNES snes = nullptr;
  CATENA_PETSC(TSGetSNES(ts, &snes));
  StepOutcome out;
  out.newton_iterations = static_cast<int>(newton);
  PetscReal norm = 0.0;
  CATENA_PETSC(SNESGetFunctionNorm(snes, &norm));
  out.residual_norm = norm;
  TSConvergedReason reason;
  CATENA_PETSC(TSGetConvergedReason(ts, &reason));
  if (reason < 0) {
    ++s.counters.newton_failures;
    SNESConvergedReason snes_reason;
    CATENA_PETSC(SNESGetConvergedReason(snes, &snes_reason));
    std::ostringstream why;
    why << "PETSc TS " << s.type << " step failed (" << TSConvergedReasons[reason] << ", SNES "
        << SNESConvergedReasons[snes_reason] << ")";
    if (!s.newton_failure.empty()) why << ": " << s.newton_failure;
    out.failure = why.str();
    out.worst_dof = s.worst_residual_dof(snes);
    s.ts_state = TsState::stale;  // the TS may have advanced its history: restart next time
    return out;
  }
  const bool restarted = s.restart_scheduled;
  s.restart_scheduled = false;
  s.last_step_restarted = restarted;
  s.ts_state = TsState::ahead;
  PetscReal t1 = 0.0;
  CATENA_PETSC(TSGetTime(ts, &t1));
  s.read_ts_state(s.state.pending_q(), s.state.pending_v());
  if (s.second_order) {
    // alpha2's own new acceleration from its velocity update v1 = v0 + h[(1−γ)a0 + γa1].
    PetscReal am = 0, af = 0, gamma = 0, beta = 0;
    CATENA_PETSC(TSAlpha2GetParams(ts, &am, &af, &gamma, &beta));
    const double h1 = t1 - s.state.time();
    CATENA_PETSC(VecWAXPY(s.state.pending_a(), -1.0, s.state.v(), s.state.pending_v()));
    CATENA_PETSC(
        VecAXPBY(s.state.pending_a(), -(1.0 - gamma) / gamma, 1.0 / (h1 * gamma), s.state.a()));
  }
  // First-order types: the new acceleration is solved for if dense output needs it.
  s.state.set_pending(t1, s.second_order);
  out.converged = true;
  return out;
}

void PetscTsIntegrator::accept() {
  Impl& s = *impl_;
  s.state.accept("PetscTsIntegrator");
  s.scale_ref = s.scale_last;
  s.ts_state = TsState::synced;
  ++s.counters.steps_accepted;
}

void PetscTsIntegrator::interpolate(double t, Vec q, Vec v) {
  Impl& s = *impl_;
  t = std::clamp(t, s.state.previous_time(), s.state.time());
  // TSInterpolate works on the TS's last step, which is ours only while synced.
  if (s.state.time() > s.state.previous_time() &&
      s.traits.dense == detail::TsDenseOutput::ts_interpolate && s.ts_interpolate_ok &&
      s.ts_state == TsState::synced && !s.second_order) {
    // A tableau without an interpolant is an error inside PETSc: ask quietly, fall back.
    CATENA_PETSC(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr));
    const PetscErrorCode ierr = TSInterpolate(s.ts.get(), t, s.U_work.get());
    CATENA_PETSC(PetscPopErrorHandler());
    if (ierr == 0) {
      s.form->split(s.U_work.get(), q, v);
      return;
    }
    s.ts_interpolate_ok = false;
  }
  s.state.interpolate(t, q, v);  // Hermite (the accelerations solved for where unknown)
}

const IntegratorCounters& PetscTsIntegrator::counters() const { return impl_->counters; }

}  // namespace catena::solvers

#include "catena/solvers/statics/static_solver.hpp"

#include <petscsnes.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <sstream>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/newton/mumps_status.hpp"

namespace catena::solvers {

struct StaticSolver::Impl {
  assembly::SecondOrderSystem& system;
  model::StaticOptions options;
  SnesHandle snes;
  VecHandle residual;
  MatHandle jacobian;
  CallbackGuard guard;
  std::function<void(const StaticProgress&)> progress;  // none: no progress calls
  // The load path (elements::LoadPath) parameterised by τ: [0, 1] tensions, [1, 2] loads,
  // [2, 3] releases prestrain to its scene value (only when some cable needs it).
  elements::LoadPath path{0.0, 0.0, 0.0};
  // Tolerances in force after the command line (SNESSetFromOptions): the per-step
  // round-off floor is added to the absolute one, the rest is left as the user set it.
  PetscReal base_atol = 0, base_rtol = 0, base_stol = 0;
  PetscInt base_max_it = 0, base_max_f = 0;
  // An LDLᵀ factorisation of the tangent at each accepted state, independent of the
  // solver the user chose for Newton, for its inertia (stability) and null pivots; its
  // factors are discarded as MUMPS computes them (never solved with). Not Newton's MUMPS
  // instance even when Newton's is MUMPS LDLᵀ: with rigid bodies Newton factors a
  // regularised matrix (below), and the stability check needs the tangent itself.
  KspHandle stability_ksp;
  int n_jacobians = 0;  // in the current SNESSolve: only then has MUMPS factored
  // Rigid bodies: a body's rotations have no stiffness of their own (natural coordinates:
  // constant mass, loads linear in q), only what its frame multipliers give once they carry
  // load, so the first Newton matrix of a load step is singular (a pendulum's swing). Newton
  // then iterates with ∂f/∂q + μ M, a Levenberg–Marquardt term in the kinetic-energy metric
  // (pseudo-transient continuation, Kelley & Keyes 1998) whose μ falls with the residual:
  // μ = μ₀ |f| / |f₀| within each load step. The equilibrium is f = 0 whatever μ was; near it
  // the iteration is Newton's. μ₀ makes every mass a 1 Hz oscillator: for a pendulum of
  // length ℓ the true stiffness is g/ℓ per unit mass, comparable for ℓ of a few decimetres.
  bool regularise = false;
  // Whether Newton factors without pivoting (constructor): no multipliers, no bodies.
  bool unpivoted = false;
  static constexpr double kRegularisation = 4.0 * M_PI * M_PI;  // μ₀, 1/s²
  double first_norm = 0.0, last_norm = 0.0;
  bool first_evaluation = true;  // of the current attempt

  Impl(assembly::SecondOrderSystem& s, const model::StaticOptions& o)
      : system(s), options(o), regularise(!s.model().rigid_bodies.empty()) {}

  // The μ of the next Newton matrix (0 without bodies, and once f vanishes).
  double regularisation() const {
    if (!regularise || !(first_norm > 0.0)) return 0.0;
    return kRegularisation * std::min(1.0, last_norm / first_norm);
  }

  // Collective. Factors the tangent at q (current path point); MUMPS's status gives the
  // number of negative eigenvalues (INFOG(12), exact in parallel with ICNTL(13) = 1) and
  // of null pivots (INFOG(28)).
  MumpsStatus tangent_status(Vec q) {
    system.jacobian({q, nullptr, path}, assembly::kStaticJacobian, jacobian.get());
    CATENA_PETSC(KSPSetOperators(stability_ksp.get(), jacobian.get(), jacobian.get()));
    CATENA_PETSC(KSPSetUp(stability_ksp.get()));
    MumpsStatus status = mumps_status(stability_ksp.get());
    // [K Gᵀ; G 0] has exactly one negative eigenvalue per multiplier when K is positive
    // definite on the constraints' null space: only the excess means instability.
    status.negative_pivots -= model::total_multipliers(system.model());
    return status;
  }

  void set_path(double tau) {
    path = {std::clamp(tau, 0.0, 1.0), std::clamp(tau - 1.0, 0.0, 1.0),
            std::clamp(tau - 2.0, 0.0, 1.0)};
  }

  static PetscErrorCode form_function(SNES, Vec q, Vec f, void* ctx) {
    auto* self = static_cast<Impl*>(ctx);
    return self->guard.run([&] {
      self->system.force({q, nullptr, self->path}, f);
      if (!self->regularise) return;
      PetscReal norm = 0.0;
      CATENA_PETSC(VecNorm(f, NORM_2, &norm));
      self->last_norm = norm;
      if (self->first_evaluation) self->first_norm = norm;
      self->first_evaluation = false;
    });
  }
  static PetscErrorCode form_jacobian(SNES, Vec q, Mat J, Mat, void* ctx) {
    auto* self = static_cast<Impl*>(ctx);
    ++self->n_jacobians;
    return self->guard.run([&] {
      assembly::JacobianCoefficients c = assembly::kStaticJacobian;
      c.c_M = self->regularisation();
      self->system.jacobian({q, nullptr, self->path}, c, J);
    });
  }
};

StaticSolver::StaticSolver(assembly::SecondOrderSystem& system, const model::StaticOptions& options)
    : impl_(std::make_unique<Impl>(system, options)) {
  Impl& s = *impl_;
  s.residual = system.create_vector();
  s.jacobian = system.create_matrix();
  CATENA_PETSC(SNESCreate(system.comm(), s.snes.out()));
  CATENA_PETSC(SNESSetFunction(s.snes.get(), s.residual.get(), Impl::form_function, &s));
  CATENA_PETSC(
      SNESSetJacobian(s.snes.get(), s.jacobian.get(), s.jacobian.get(), Impl::form_jacobian, &s));
  // Scene tolerances first, so that -static_snes_* on the command line wins.
  CATENA_PETSC(SNESSetTolerances(s.snes.get(), options.atol, options.rtol, kNewtonStepTolerance,
                                 options.max_newton_iterations, 100000));
  // Without multipliers (zero diagonal rows) and rigid bodies (regularised, below) the
  // tangent's pivots do not vanish where the structure holds (a stable equilibrium's tangent
  // is positive definite): PETSc's LU on one rank and the interface split on more
  // (interface_schur.hpp) factor it without pivoting: the 10 km line's static solve in 0.57
  // of its time with MUMPS's LDLᵀ on one rank, 0.62 on two (docs/performance.md, "Static
  // line benchmark"). A failed attempt (a zero pivot, or the huge step of a nearly singular
  // tangent: a mechanism, a part without stiffness before its loads are on, whose null
  // pivots MUMPS steps past) or a singular tangent at an accepted state switches this
  // solver to MUMPS's LDLᵀ for the rest of its solves (attempt). Otherwise MUMPS's LDLᵀ
  // from the start (the static tangent is symmetric: LDLᵀ halves the factorisation).
  s.unpivoted = !s.regularise && model::total_multipliers(system.model()) == 0;
  configure_direct_newton(s.snes.get(), "static_",
                          s.unpivoted ? JacobianSymmetry::general : JacobianSymmetry::symmetric,
                          s.unpivoted ? Pivoting::not_needed : Pivoting::needed);
  if (s.regularise) {
    // With rigid bodies the matrices change in kind along the load path (a body's rotations
    // gain stiffness only as loads come on): MUMPS scales each one afresh rather than keep
    // the first one's scaling. Not without bodies, where the default serves and a null
    // pivot's fixed step keeps Newton where it is (a mechanism is then reported).
    KSP ksp = nullptr;
    CATENA_PETSC(SNESGetKSP(s.snes.get(), &ksp));
    CATENA_PETSC(KSPSetOperators(ksp, s.jacobian.get(), s.jacobian.get()));
    scale_mumps_factor_at_each_factorisation(ksp, "static_");
  }
  CATENA_PETSC(SNESGetTolerances(s.snes.get(), &s.base_atol, &s.base_rtol, &s.base_stol,
                                 &s.base_max_it, &s.base_max_f));

  enable_mumps_exact_inertia("static_stability_");
  discard_mumps_factors("static_stability_");
  // Its first tangent is that of the unloaded structure (every accepted state is factored),
  // with or without bodies.
  scale_mumps_at_each_factorisation("static_stability_");
  s.stability_ksp =
      create_direct_ksp(system.comm(), "static_stability_", JacobianSymmetry::symmetric);
}

StaticSolver::~StaticSolver() = default;

void StaticSolver::on_progress(std::function<void(const StaticProgress&)> callback) {
  impl_->progress = std::move(callback);
}

namespace {

// "node 17 (id 4017), component y" for the largest |f| entry.
std::string largest_residual_location(const assembly::SecondOrderSystem& system, Vec f) {
  PetscInt where = -1;
  PetscReal value = 0.0;
  VecHandle abs_f;
  if (VecDuplicate(f, abs_f.out()) || VecCopy(f, abs_f.get()) || VecAbs(abs_f.get()) ||
      VecMax(abs_f.get(), &where, &value) || where < 0)
    return "unknown";
  std::ostringstream os;
  os << system.describe_dof(where) << ", |f| = " << value
     << (system.dof_map().constraint_of_global(where) >= 0 ? " m" : " N");
  return os.str();
}

// Where on the load path τ is, in words.
std::string describe_path(double tau, double tau_end) {
  std::ostringstream os;
  if (tau <= 1.0)
    os << "prestrain " << 100.0 * tau << " % applied, no loads yet";
  else if (tau <= 2.0)
    os << "load factor " << tau - 1.0
       << (tau_end > 2.0 ? " (cables held at their path prestrain)" : "");
  else
    os << "full load, cable prestrain " << 100.0 * (tau - 2.0)
       << " % of the way from the path prestrain to its scene value";
  return os.str();
}

// Fraction of the element-force norm below which the residual is round-off.
constexpr double kRoundoffFraction = 1e-10;

void check_factorisation(const MumpsStatus& mumps, const std::string& where) {
  if (mumps.infog1 < 0)
    throw NumericalError(
        "static solve: MUMPS failed with INFOG(1) = " + std::to_string(mumps.infog1) +
        ", INFOG(2) = " + std::to_string(mumps.infog2) + " at " + where);
}

}  // namespace

// Collective. Newton at path point `target` from `start` into `trial`; whether it
// converged to a stable equilibrium (negative tangent pivots: unstable, rejected), with
// its iteration count added to `report`.
StaticSolver::Attempt StaticSolver::attempt(double target, double tau_end, Vec start, Vec trial,
                                            StaticReport& report) {
  Impl& s = *impl_;
  s.set_path(target);
  // Converged when |f| ≤ atol + kRoundoffFraction·(norm of the unassembled element
  // forces), or |f| fell by rtol within the step, or the Newton update is below
  // kNewtonStepTolerance·|q|. Element forces are large where they cancel at nodes
  // (tension): a scale from external loads alone would ask for more than round-off
  // allows. Where stiffness is large and forces small (a stiff cantilever under a small
  // load) the residual's round-off floor is stiffness × size × ε and only the update
  // criterion can see convergence.
  const double scale = s.system.element_force_norm({start, nullptr, s.path});
  CATENA_PETSC(SNESSetTolerances(s.snes.get(), s.base_atol + kRoundoffFraction * scale, s.base_rtol,
                                 s.base_stol, s.base_max_it, s.base_max_f));
  CATENA_PETSC(VecCopy(start, trial));
  s.n_jacobians = 0;
  s.first_evaluation = true;
  KSP ksp = nullptr;
  CATENA_PETSC(SNESGetKSP(s.snes.get(), &ksp));
  SNESConvergedReason reason;
  PetscInt its = 0, all_its = 0;
  for (;;) {
    const PetscErrorCode ierr = SNESSolve(s.snes.get(), nullptr, trial);
    s.guard.rethrow_if_any();
    CATENA_PETSC(ierr);
    CATENA_PETSC(SNESGetConvergedReason(s.snes.get(), &reason));
    CATENA_PETSC(SNESGetIterationNumber(s.snes.get(), &its));
    all_its += its;
    // Any failure of Newton without pivoting: a zero pivot (PETSc's LU flags only pivots
    // below 100ε), or a nearly singular tangent's huge step (NaN residual, no convergence).
    // MUMPS's LDLᵀ, which detects null pivots relative to the matrix, from here on.
    if (!(reason < 0 && s.unpivoted &&
          switch_to_pivoting(ksp, "static_", JacobianSymmetry::symmetric)))
      break;
    // The attempt again from its start, not from the iterate reached: MUMPS scales the matrix
    // it first factors and keeps that scaling, and from a singular one (a row without
    // stiffness) it took a nearly null pivot for a pivot (a slack bar's end thrown through
    // its pin).
    s.unpivoted = false;
    CATENA_PETSC(VecCopy(start, trial));
    s.n_jacobians = 0;
  }
  report.n_newton_iterations += static_cast<int>(all_its);  // its: the last try's alone
  if (s.n_jacobians > 0) {
    const MumpsStatus newton = mumps_status(ksp);
    if (newton.infog1 < 0 && newton.infog1 != -10)
      throw NumericalError(
          "static solve: MUMPS failed with INFOG(1) = " + std::to_string(newton.infog1) +
          ", INFOG(2) = " + std::to_string(newton.infog2) + " at " +
          describe_path(target, tau_end));
  }

  // Accept only stable equilibria: Newton may converge to an unstable branch (a slack
  // cable's inverted arch, a column beyond buckling), whose tangent has negative
  // eigenvalues. The tangent is factored at the converged state itself.
  Attempt result{reason > 0, false, static_cast<int>(its)};
  if (result.accepted) {
    const MumpsStatus tangent = s.tangent_status(trial);
    check_factorisation(tangent, describe_path(target, tau_end));
    if (tangent.negative_pivots > 0) {
      result.accepted = false;
      result.unstable = true;
      ++report.n_unstable_rejections;
    } else if (tangent.null_pivots > 0 && s.unpivoted &&
               switch_to_pivoting(ksp, "static_", JacobianSymmetry::symmetric)) {
      // A singular tangent at the accepted state (before the loads are on): the next
      // attempt's first matrix, which only MUMPS's null-pivot detection gets past.
      s.unpivoted = false;
    }
    if (tangent.null_pivots > 0 && target >= tau_end && result.accepted) {
      // Neutral directions are normal before the loads are on (an unloaded pendulum);
      // at full load they mean a mechanism.
      throw NumericalError(
          "static solve: the stiffness matrix at the equilibrium is singular (" +
          std::to_string(tangent.null_pivots) +
          " null pivots): the structure is a mechanism. Check the supports (a cable or "
          "bar held at one end only can swing; a beam needs its rotations held "
          "somewhere) and that every node is connected to a supported part.");
    }
  }
  return result;
}

StaticReport StaticSolver::solve(Vec q, Vec guess) {
  Impl& s = *impl_;
  StaticReport report;
  VecHandle q_trial;
  CATENA_PETSC(VecDuplicate(q, q_trial.out()));

  const double tau_end = s.system.has_slack_prestrain() ? 3.0 : 2.0;
  const double initial_step = std::clamp(s.options.initial_load_step, s.options.min_load_step, 1.0);
  double tau = 0.0;  // reached point on the load path
  double step = initial_step;
  double last_attempt = 0.0;
  int attempts = 0;  // steps that needed Newton iterations, or were rejected
  bool last_rejection_unstable = false;
  if (guess != nullptr) {
    // The whole load at once from the guess; if Newton does not reach a stable
    // equilibrium from there, the path from q as if there had been none.
    last_attempt = tau_end;
    const Attempt from_guess = attempt(tau_end, tau_end, guess, q_trial.get(), report);
    report.guess = from_guess.accepted ? GuessOutcome::accepted : GuessOutcome::rejected;
    if (from_guess.accepted) {
      CATENA_PETSC(VecCopy(q_trial.get(), q));
      tau = tau_end;
      ++report.n_load_steps;
    } else {
      ++report.n_rejected_steps;
    }
    ++attempts;
    if (s.progress)
      s.progress({describe_path(tau, tau_end) + (from_guess.accepted ? " from the guess" : ""),
                  report.n_load_steps, report.n_rejected_steps, report.n_newton_iterations});
  }
  while (tau < tau_end) {
    if (attempts >= s.options.max_load_steps) break;
    // Never step across a phase boundary (integer τ), where the path changes what it ramps.
    const double phase_end = std::floor(tau) + 1.0;
    const double target = std::min({phase_end, tau + step, tau_end});
    last_attempt = target;
    const Attempt tried = attempt(target, tau_end, q, q_trial.get(), report);
    const int its = tried.iterations;
    if (tried.accepted) {
      last_rejection_unstable = false;
      CATENA_PETSC(VecCopy(q_trial.get(), q));
      tau = target;
      ++report.n_load_steps;
      if (its > 0) ++attempts;
      if (tau >= phase_end)
        step = initial_step;  // a new phase starts with the user's increment
      else if (its == 0)
        step = phase_end - tau;  // nothing changes in this phase here: finish it
      else if (its <= 4)
        step = std::min(1.0, 2.0 * step);
    } else {
      ++attempts;
      ++report.n_rejected_steps;
      last_rejection_unstable = tried.unstable;
      step *= 0.5;
    }
    if (s.progress)
      s.progress({describe_path(tau, tau_end), report.n_load_steps, report.n_rejected_steps,
                  report.n_newton_iterations});
    if (!tried.accepted && step < s.options.min_load_step) break;
  }

  // Residual at the returned state (the last converged point of the path).
  s.set_path(tau);
  s.system.force({q, nullptr, s.path}, s.residual.get());
  PetscReal norm = 0.0;
  CATENA_PETSC(VecNorm(s.residual.get(), NORM_2, &norm));
  report.load_factor = s.path.loads;
  report.residual_norm = norm;
  if (tau < tau_end) {
    // A mechanism shows as null pivots at the last accepted state.
    const MumpsStatus tangent = s.tangent_status(q);
    const bool singular = tangent.null_pivots > 0;
    // Where the failed attempt left the largest residual (at its own load level).
    s.set_path(last_attempt);
    s.system.force({q_trial.get(), nullptr, s.path}, s.residual.get());
    std::ostringstream os;
    os << "static solve did not converge: reached " << describe_path(tau, tau_end) << " after "
       << report.n_load_steps << " accepted and " << report.n_rejected_steps
       << " rejected load steps (" << report.n_newton_iterations
       << " Newton iterations); at the last attempt (" << describe_path(last_attempt, tau_end)
       << ") the largest residual is at " << largest_residual_location(s.system, s.residual.get())
       << ". " << report.n_unstable_rejections
       << " steps converged to unstable equilibria (negative tangent stiffness) and were "
          "retried. ";
    if (last_rejection_unstable)
      // Newton converges, but every step, however short, ends on an unstable equilibrium:
      // the path from the reference reaches a limit or bifurcation point there.
      os << "Newton converged at the last attempt, to an unstable equilibrium: the path turns "
            "unstable there (a limit or bifurcation point: a column buckling, a body pushed "
            "against a surface or a support so that it would tip or slide, which statics, "
            "with no friction at rest, cannot hold). Shorter load steps cannot pass it; "
            "support the structure where it would move (a dynamic run may instead start "
            "from the reference: analysis.initial.from: reference).";
    else if (singular)
      os << "The stiffness matrix at the last equilibrium is singular (" << tangent.null_pivots
         << " null pivots): the structure is probably a mechanism; check its supports.";
    else
      os << "Try a smaller analysis.load_steps.initial or more analysis.newton.max_iterations.";
    throw NumericalError(os.str());
  }
  return report;
}

}  // namespace catena::solvers

#include "catena/solvers/time/hht_integrator.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/modes/modal_analysis.hpp"
#include "catena/solvers/newton/local_newton.hpp"
#include "catena/solvers/newton/reusable_newton.hpp"
#include "catena/solvers/time/newton_outcome.hpp"
#include "catena/solvers/time/step_matrices.hpp"
#include "catena/solvers/time/step_state.hpp"

namespace catena::solvers {
namespace {

// The local Newton settings with the options database's overrides; false if it is off.
bool local_newton_options(bool on, LocalNewtonSettings& local) {
  PetscInt layers = on ? local.layers : 0;
  PetscReal worn = local.worn_fraction, window = local.max_window_fraction;
  CATENA_PETSC(PetscOptionsGetInt(nullptr, "hht_", "-local_newton_layers", &layers, nullptr));
  CATENA_PETSC(PetscOptionsGetReal(nullptr, "hht_", "-local_newton_worn", &worn, nullptr));
  CATENA_PETSC(PetscOptionsGetReal(nullptr, "hht_", "-local_newton_max_window", &window, nullptr));
  if (layers < 0 || layers > local.max_layers)
    throw InputError({"", 0, "-hht_local_newton_layers"},
                     "local Newton layers " + std::to_string(layers) + "; accepted: 0 (off) to " +
                         std::to_string(local.max_layers));
  if (!(worn > 0.0))
    throw InputError({"", 0, "-hht_local_newton_worn"},
                     "local Newton worn fraction " + std::to_string(worn) + "; accepted: > 0");
  if (!(window > 0.0 && window <= 1.0))
    throw InputError(
        {"", 0, "-hht_local_newton_max_window"},
        "local Newton window fraction " + std::to_string(window) + "; accepted: (0, 1]");
  local.layers = static_cast<int>(layers);
  local.worn_fraction = worn;
  local.max_window_fraction = window;
  return layers > 0;
}

}  // namespace

// M, K, C, the Newton matrix, Gᵀ and the tangent's point: StepMatrices.
struct HhtIntegrator::Impl : StepMatrices {
  HhtOptions options;
  double beta, gamma;
  // The current state (start of the next step), the one before (dense output) and the
  // pending step (q1, v1 built from the unknown a1), in the integrator's StepState.
  StepState& state;
  double scale0 = 0.0;
  VecHandle f0;  // f(t0, q0, v0)
  double h = 0.0, h_matrix = -1.0, scale1 = 0.0;
  VecHandle f1, residual, error, work;
  long steps_since_tangent = 0;  // linearly implicit: steps accepted with the current tangent
  double omega_max = 0.0;        // central differences: rad/s at the state set last
  // The parts of q1, v1 that do not depend on a1, set once per attempt (kinematics).
  VecHandle q_known, v_known;
  std::unique_ptr<ReusableNewton> newton;
  std::unique_ptr<LocalNewton> local;  // null unless options.local_newton
  IntegratorCounters counters;

  Impl(assembly::SecondOrderSystem& s, const HhtOptions& o, StepState& st)
      : StepMatrices(s, st.q()),
        options(o),
        beta(o.central_difference ? 0.0 : 0.25 * (1 - o.alpha) * (1 - o.alpha)),
        gamma(o.central_difference ? 0.5 : 0.5 - o.alpha),
        state(st) {
    if (o.central_difference) options.alpha = 0.0;
  }

  // The a1-independent parts of the Newmark formulas for the step h from (q0, v0, a0):
  // q_known = q0 + h v0 + h²(½ − β) a0,  v_known = v0 + h(1 − γ) a0. Computed once per
  // attempt, so that each residual evaluation makes two vector passes, not seven.
  void start_attempt() {
    CATENA_PETSC(VecWAXPY(q_known.get(), h, state.v(), state.q()));
    CATENA_PETSC(VecAXPY(q_known.get(), h * h * (0.5 - beta), state.a()));
    CATENA_PETSC(VecWAXPY(v_known.get(), h * (1 - gamma), state.a(), state.v()));
  }

  // q1, v1 from a1 (Newmark); the multiplier slots of a1 hold λ1 itself.
  void kinematics(Vec a) {
    CATENA_PETSC(VecWAXPY(state.pending_q(), h * h * beta, a, q_known.get()));
    CATENA_PETSC(VecWAXPY(state.pending_v(), h * gamma, a, v_known.get()));
    algebraic->take_algebraic(state.pending_q(), a);
    algebraic->zero_algebraic(state.pending_v());
  }

  // R(a1) = M a1 + (1 + α)(f + Gᵀλ)(t1, q1, v1) − α (f + Gᵀλ)0 in the nodal rows and
  // (m̄/βh²) g(q1, t1) in the constraint rows (Negrut et al.: the constraint holds at the
  // step end, not α-weighted).
  void residual_at(Vec a, Vec r) {
    kinematics(a);
    system.force({state.pending_q(), state.pending_v(), {}, state.time() + h}, f1.get(), &scale1);
    CATENA_PETSC(MatMult(mass_product.get(), a, r));
    CATENA_PETSC(VecAXPBYPCZ(r, 1.0 + options.alpha, -options.alpha, 1.0, f1.get(), f0.get()));
    if (algebraic->active()) {
      algebraic->take_algebraic(r, f1.get());
      algebraic->scale_rows(r, algebraic->mass_scale() / (beta * h * h));
    }
  }

  // The linearly implicit step (HhtOptions::linearly_implicit) from the predictor a_p = a₀:
  // a₁ = a_p − J⁻¹ R(a_p), and for the next step's α term the step's linear model of
  // f(q₁, v₁): from J (a₁ − a_p) = −R_p, (1 + α)(βh² K + γh C)(a₁ − a_p) = −R_p − M (a₁ − a_p),
  //   f₁ ≈ f_p + (βh² K + γh C)(a₁ − a_p) = f_p − (R_p − M δ)/(1 + α),  δ = a_p − a₁.
  NewtonResult linearly_implicit_step() {
    if (options.tangent_every > 0 && steps_since_tangent >= options.tangent_every)
      newton->invalidate_tangent();
    const long tangents_before = newton->counters().tangent_evaluations;
    const NewtonResult r = newton->linear_step(state.pending_a());  // f1 = f_p, residual = R_p
    if (!r.converged) return r;
    if (newton->counters().tangent_evaluations != tangents_before) steps_since_tangent = 0;
    CATENA_PETSC(VecWAXPY(work.get(), -1.0, state.pending_a(), state.a()));  // δ
    CATENA_PETSC(MatMult(mass_product.get(), work.get(), error.get()));      // M δ
    CATENA_PETSC(VecAXPY(error.get(), -1.0, residual.get()));                // M δ − R_p
    CATENA_PETSC(VecAXPY(f1.get(), 1.0 / (1.0 + options.alpha), error.get()));
    return r;
  }

  // The attempt's outcome from its Newton result: on success the pending state from a1
  // (pending_a) and the local error estimate if asked for.
  StepOutcome finish_attempt(const NewtonResult& result, const ErrorTolerance* tol) {
    StepOutcome out = newton_outcome(result, residual.get(), counters);
    if (!out.converged) {
      state.discard_pending();
      return out;
    }
    // q1, v1 from a1 (a Newton solve's last residual evaluation was at a1 already).
    kinematics(state.pending_a());
    algebraic->zero_algebraic(state.pending_a());  // λ1 now lives in q1
    state.set_pending(state.time() + h);
    if (tol) {
      CATENA_PETSC(VecWAXPY(error.get(), -1.0, state.a(), state.pending_a()));
      CATENA_PETSC(VecScale(error.get(), h * h * (beta - 1.0 / 6.0)));
      out.error = weighted_error_norm(*tol, error.get(), state.q(), state.pending_q());
    }
    return out;
  }

  // J = M + (1 + α)(γ h C + β h² K) with the matrix's step h_matrix (attempt(): a step
  // within 10⁻⁶ of it keeps the matrix, and a restart rebuilds the same matrix from the
  // saved h_matrix), K and C re-evaluated at the iterate if asked.
  void build_matrix(Vec a, bool refresh_tangent, Mat J) {
    if (refresh_tangent) {
      kinematics(a);
      evaluate_tangent(state.pending_q(), state.pending_v(), state.time() + h);
      ++counters.jacobian_evaluations;
      if (local) local->tangent_refreshed();
    }
    const double s = 1.0 + options.alpha, hm = h_matrix;
    CATENA_PETSC(MatCopy(mass.get(), J, SAME_NONZERO_PATTERN));
    if (const Mat damping = damping_matrix())
      CATENA_PETSC(MatAXPY(J, s * gamma * hm, damping, SAME_NONZERO_PATTERN));
    if (beta != 0.0)  // central differences: no stiffness in the matrix
      CATENA_PETSC(MatAXPY(J, s * beta * hm * hm, K.get(), SAME_NONZERO_PATTERN));
    if (algebraic->active()) {
      // Multiplier columns (1 + α)Gᵀ; constraint rows, holding (1 + α)βh² G from K,
      // scaled to m̄ G like the residual's.
      CATENA_PETSC(MatAXPY(J, s, coupling.get(), SAME_NONZERO_PATTERN));
      algebraic->scale_rows(J, algebraic->mass_scale() / (s * beta * hm * hm));
    }
  }
};

HhtIntegrator::HhtIntegrator(assembly::SecondOrderSystem& system, const HhtOptions& options)
    : StepStateIntegrator(system) {
  if (options.central_difference && system.has_constraints())
    throw InputError({"", 0, "integrator.type"},
                     "central_difference takes no Lagrange-multiplier constraints (its positions "
                     "do not depend on the step's unknown); use hht or radau");
  if (options.central_difference && options.linearly_implicit)
    throw InputError({"", 0, "integrator.newton"},
                     "central_difference has no linearly implicit variant (its positions are "
                     "explicit already); use simplified or full");
  if (!options.central_difference && !(options.alpha >= -1.0 / 3.0 && options.alpha <= 0.0))
    throw InputError({"", 0, "integrator.alpha"}, "HHT alpha = " + std::to_string(options.alpha) +
                                                      " is outside the accepted range [-1/3, 0]");
  impl_ = std::make_unique<Impl>(system, options, step_state());
  Impl& s = *impl_;
  CATENA_ASSERT(
      !options.linearly_implicit || !system.has_constraints(),
      "HHT's linearly implicit step takes no constraints (the scene reader refuses them)");
  for (VecHandle* v : {&s.f0, &s.f1, &s.residual, &s.error, &s.work, &s.q_known, &s.v_known})
    *v = system.create_vector();
  s.newton = s.make_newton(
      "hht_", options.max_newton_iterations, options.full_newton, s.residual.get(),
      [&s](Vec a, Vec r) { s.residual_at(a, r); },
      [&s](Vec a, bool refresh, Mat J) { s.build_matrix(a, refresh, J); });
  LocalNewtonSettings local = options.local_newton_settings;
  // Central differences: the stiffness is not in the matrix, so no window of it either.
  const bool use_local =
      !options.central_difference && local_newton_options(options.local_newton, local);
  if (use_local) {
    s.local = std::make_unique<LocalNewton>(system, local);
    // R(a1) = M a1 + (1 + α) f(q1, v1) − α f0, q1 = q̂ + βh² a1, v1 = v̂ + γh a1; q1, v1
    // and f1 hold the last residual evaluation's (the iterate's) values.
    s.newton->set_local_correction([&s](Vec a, Vec r, double atol, double* norm) {
      const LocalNewton::Coefficients c{1.0 + s.options.alpha, s.beta * s.h * s.h, s.gamma * s.h,
                                        s.state.time() + s.h};
      return s.local->correct(a, r, s.state.pending_q(), s.state.pending_v(), s.f1.get(), c, atol,
                              norm);
    });
  }
}

HhtIntegrator::~HhtIntegrator() = default;

std::string HhtIntegrator::name() const {
  if (impl_->options.central_difference) return "central_difference";
  char text[64];
  // The linearly implicit step is another method: a checkpoint of one does not continue
  // as the other (checkpoints name their integrator).
  std::snprintf(
      text, sizeof text,
      impl_->options.linearly_implicit ? "hht(alpha=%g, linearly implicit)" : "hht(alpha=%g)",
      impl_->options.alpha);
  return text;
}

void HhtIntegrator::set_state(double t, Vec q, Vec v, Vec a) {
  Impl& s = *impl_;
  // Without a, the consistent one (also λ0 with constraints).
  s.state.start(t, q, v, a, consistent_acceleration_of(s.system, s.mass.get()));
  s.system.force({s.state.q(), s.state.v(), {}, t}, s.f0.get(), &s.scale0);
  s.newton->invalidate_tangent();
  if (s.options.central_difference && !(s.omega_max > 0.0)) {
    // The stability limit at the initial state, once: the tangent there (kept: the first
    // Newton matrix is built from it) against the mass. Not again when the driver returns
    // to a step's start (step doubling): that would repeat the eigen-solve every step.
    s.evaluate_tangent(s.state.q(), s.state.v(), t);
    s.omega_max = highest_frequency(s.K.get(), s.mass.get());
  }
}

StepOutcome HhtIntegrator::attempt(double h, const ErrorTolerance* tol) {
  Impl& s = *impl_;
  s.h = h;
  // A step within 10⁻⁶ of the matrix's keeps it: the driver's last step, t_end − t, is dt
  // but for the round-off t gathered over the run (3·10⁻¹⁰ of dt after 4000 steps of
  // 0.5 ms), and refactoring for it made the last step of every fixed-step run a
  // factorisation (docs/performance.md, "The linearly implicit step"). The matrix is
  // Newton's, or the linearly implicit step's linearisation, to that relative accuracy.
  if (std::abs(h - s.h_matrix) > 1e-6 * h) {
    s.newton->invalidate_matrix();
    s.h_matrix = h;
  }
  s.start_attempt();
  if (s.options.linearly_implicit) {
    CATENA_PETSC(VecCopy(s.state.a(), s.state.pending_a()));  // predictor: a₀
    const NewtonResult result = s.linearly_implicit_step();
    return s.finish_attempt(result, tol);
  }
  // The local corrections have grown costlier than a new tangent (local_newton.hpp).
  if (s.local && s.local->tangent_worn()) s.newton->invalidate_tangent();
  CATENA_PETSC(VecCopy(s.state.a(), s.state.pending_a()));  // predictor: constant acceleration
  s.algebraic->take_algebraic(s.state.pending_a(), s.state.q());  // and constant λ
  if (!s.round_off.known())  // first attempt: the floor from a tangent at the start
    s.evaluate_tangent(s.state.q(), s.state.v(), s.state.time());
  const double atol = s.options.atol + s.options.rtol * s.scale0 +
                      (1.0 + s.options.alpha) * s.round_off.at(s.state.q());
  const double floor = s.algebraic->residual_floor(s.beta * h * h, s.state.q());
  const NewtonResult result =
      s.newton->solve(s.state.pending_a(), atol, s.algebraic->residual_measure(atol, floor));
  return s.finish_attempt(result, tol);
}

void HhtIntegrator::accept() {
  Impl& s = *impl_;
  s.state.accept("HhtIntegrator");
  if (s.options.linearly_implicit) ++s.steps_since_tangent;
  std::swap(s.f0, s.f1);
  s.scale0 = s.scale1;
  ++s.counters.steps_accepted;
}

void HhtIntegrator::interpolate(double t, Vec q, Vec v) { impl_->state.interpolate(t, q, v); }

// The step-to-step state: f0 and its scale (the last residual's, which a local correction
// updated in part: recomputing f0 would differ in round-off), the tangent's point, the
// matrix's h, Newton's and the local correction's state, the counters.
void HhtIntegrator::save_resume_state(ResumeState& out) const {
  const Impl& s = *impl_;
  out.vectors["hht.f0"] = s.f0.get();
  s.save_tangent(out, "hht");
  out.reals["hht.scale0"] = s.scale0;
  out.reals["hht.h_matrix"] = s.h_matrix;
  out.integers["hht.steps_since_tangent"] = s.steps_since_tangent;
  // Central differences: ω_max of the run's start (the restart's set_state measured it at
  // its own state; the saved value keeps the uninterrupted run's limit).
  if (s.options.central_difference) out.reals["hht.omega_max"] = s.omega_max;
  save_own_counters(s.counters, out);
  s.newton->save_resume_state(out);
  if (s.local) s.local->save_resume_state(out);
}

void HhtIntegrator::restore_resume_state(const ResumeState& in) {
  if (in.empty()) return;
  Impl& s = *impl_;
  CATENA_PETSC(VecCopy(in.vector("hht.f0"), s.f0.get()));
  s.scale0 = in.real("hht.scale0");
  s.h_matrix = in.real("hht.h_matrix");
  restore_own_counters(in, s.counters);
  s.newton->restore_resume_state(in);
  if (s.local) s.local->restore_resume_state(in);
  // Checkpoints before the linearly implicit step carry neither: their runs did not use it.
  if (in.integers.contains("hht.steps_since_tangent"))
    s.steps_since_tangent = in.integer("hht.steps_since_tangent");
  if (s.options.central_difference && in.reals.contains("hht.omega_max"))
    s.omega_max = in.real("hht.omega_max");
  // K, C and the floor as they were: evaluated again at their point (the Newton matrix is
  // rebuilt from them at the next attempt).
  if (s.restore_tangent(in, "hht")) ++s.counters.jacobian_evaluations;
}

double HhtIntegrator::stable_step() const {
  const Impl& s = *impl_;
  if (!s.options.central_difference || !(s.omega_max > 0.0))
    return std::numeric_limits<double>::infinity();
  return 2.0 / s.omega_max;
}

std::string HhtIntegrator::stable_step_reason() const {
  const Impl& s = *impl_;
  if (!s.options.central_difference) return {};
  std::ostringstream os;
  os << "central differences are stable for steps up to 2/omega_max = " << stable_step()
     << " s, omega_max = " << s.omega_max
     << " rad/s, the structure's highest frequency at the initial state (docs/integrators.md, "
        "\"Central differences\")";
  return os.str();
}

const IntegratorCounters& HhtIntegrator::counters() const {
  Impl& s = *impl_;
  const NewtonCounters& n = s.newton->counters();
  s.counters.residual_evaluations = n.residual_evaluations;
  s.counters.factorizations = n.factorizations;
  s.counters.linear_solves = n.linear_solves;
  s.counters.local_corrections = n.local_corrections;
  if (s.local) s.counters.local_unknowns = s.local->counters().unknowns;
  return s.counters;
}

}  // namespace catena::solvers

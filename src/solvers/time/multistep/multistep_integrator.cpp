#include "catena/solvers/time/multistep/multistep_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/newton/reusable_newton.hpp"
#include "catena/solvers/time/multistep/multistep_formulas.hpp"
#include "catena/solvers/time/newton_outcome.hpp"
#include "catena/solvers/time/step_matrices.hpp"

namespace catena::solvers {
namespace {

// The Newton matrix w₀²M + w₀C + K is kept while w₀ stays within this fraction of the
// value it was built with (after a step change the formula's w₀ settles over a few steps):
// the simplified iteration then contracts at about this rate in the mass-dominated modes,
// which costs less than a factorisation per step.
constexpr double kMatrixTolerance = 0.05;

// Below this ratio of successive steps each variable-step formula is zero-stable, with a
// margin: the limits for steps that keep growing by the same ratio are 1 + √2 (BDF-2),
// 1.618 (BDF-3), 1.281 (BDF-4), 1.127 (BDF-5) and 1.909 (Park), the ratios where a root
// of the recurrence's characteristic polynomial reaches the unit circle (docs/integrators.md).
double step_ratio_limit(MultistepFamily family, int order) {
  if (family == MultistepFamily::park) return 1.8;
  switch (order) {
    case 1:
      return std::numeric_limits<double>::infinity();
    case 2:
      return 2.0;
    case 3:
      return 1.5;
    case 4:
      return 1.2;
    default:
      return 1.1;
  }
}

// The formula of one attempt: D's weights over (t₁, t₀, t₋₁, ...), the predictor's over
// (v₀; q₀, q₋₁, ...) and the estimate's constant.
struct Formula {
  std::vector<double> w;          // w[0]: the new point's
  std::vector<double> predictor;  // {s, c₁ (q₀), c₂, ...}
  double error_constant = 1.0;
  int order = 1;
};

}  // namespace

// M, K, C, the Newton matrix, Gᵀ and the tangent's point: StepMatrices.
struct MultistepIntegrator::Impl : StepMatrices {
  MultistepOptions options;
  StepState& state;
  // The history: q, v at t₀ (the current point), t₋₁, ...; `known` of them valid.
  std::vector<VecHandle> q_back, v_back;
  std::vector<double> t_back;
  int known = 0;
  // This attempt: step, formula, predictor and the parts of v₁, a₁ that do not depend on δ.
  double h = 0.0, t1 = 0.0;
  Formula formula;
  VecHandle q_pred, v_pred, a_pred, delta, difference, f1, residual, error;
  double scale0 = 0.0, scale1 = 0.0;
  double w0_matrix = -1.0;  // w₀ the Newton matrix was built with
  // w₀ of the Newton matrix for this attempt: the kept one within kMatrixTolerance of the
  // formula's, else the formula's. The constraint rows are scaled with it in the residual
  // too, so that the kept matrix solves them exactly.
  double w0_newton = 1.0;
  double matrix_tolerance = kMatrixTolerance;  // -multistep_matrix_tolerance overrides it
  std::unique_ptr<ReusableNewton> newton;
  IntegratorCounters counters;

  Impl(assembly::SecondOrderSystem& s, const MultistepOptions& o, StepState& st)
      : StepMatrices(s, st.q()), options(o), state(st) {}

  int history_needed() const { return options.family == MultistepFamily::park ? 3 : options.order; }

  // BDF of the method's order, or Park's formula, as far as the history allows; lower
  // BDF orders while it is short.
  Formula choose_formula() const {
    std::vector<double> times{t1};
    for (int j = 0; j < known; ++j) times.push_back(t_back[static_cast<std::size_t>(j)]);
    Formula f;
    if (options.family == MultistepFamily::park && known >= 3) {
      f.w = park_weights(times);
      f.order = 2;
      f.error_constant = 0.5;
    } else {
      f.order = std::min(options.family == MultistepFamily::park ? 2 : options.order, known);
      f.w = bdf_weights(times, f.order);
    }
    f.predictor = hermite_predictor_weights(times, f.order);
    return f;
  }

  // q̂ = q₀ + s v₀ + Σ_{j≥2} c_j (q_{1−j} − q₀) and the δ-free parts of v₁ and a₁:
  //   v̂ = w₀ (q̂ − q₀) + Σ_{j≥2} w_j (q_{1−j} − q₀),  â = w₀ (v̂ − v₀) + Σ_{j≥2} w_j (v_{1−j} − v₀),
  // written with differences from the current point, since Σ w_j = 0: the positions are
  // absolute coordinates (hundreds of metres) and summing them with weights of order 1/h
  // would lose what the step moves in round-off.
  void predict() {
    const std::vector<double>& w = formula.w;
    const std::vector<double>& c = formula.predictor;
    const double w0 = w[0];
    Vec q0 = q_back[0].get(), v0 = v_back[0].get();
    CATENA_PETSC(VecSet(q_pred.get(), 0.0));  // q̂ − q₀ first
    CATENA_PETSC(VecSet(v_pred.get(), 0.0));
    const std::size_t past = std::max(w.size() - 1, c.size() - 1);
    for (std::size_t j = 2; j <= past; ++j) {
      const double cj = j < c.size() ? c[j] : 0.0;
      const double wj = j < w.size() ? w[j] : 0.0;
      CATENA_PETSC(VecWAXPY(difference.get(), -1.0, q0, q_back[j - 1].get()));
      CATENA_PETSC(VecAXPY(q_pred.get(), cj, difference.get()));
      CATENA_PETSC(VecAXPY(v_pred.get(), w0 * cj + wj, difference.get()));
    }
    CATENA_PETSC(VecAXPY(q_pred.get(), c[0], v0));
    CATENA_PETSC(VecAXPY(v_pred.get(), w0 * c[0], v0));
    CATENA_PETSC(VecAXPY(q_pred.get(), 1.0, q0));
    algebraic->zero_algebraic(v_pred.get());
    CATENA_PETSC(VecWAXPY(a_pred.get(), -1.0, v0, v_pred.get()));
    CATENA_PETSC(VecScale(a_pred.get(), w0));
    for (std::size_t j = 2; j < w.size(); ++j) {
      CATENA_PETSC(VecWAXPY(difference.get(), -1.0, v0, v_back[j - 1].get()));
      CATENA_PETSC(VecAXPY(a_pred.get(), w[j], difference.get()));
    }
    algebraic->zero_algebraic(a_pred.get());
  }

  // q₁, v₁, a₁ from the correction δ; the multiplier slots of δ correct λ₁ (in q₁).
  void kinematics(Vec d) {
    const double w0 = formula.w[0];
    CATENA_PETSC(VecWAXPY(state.pending_q(), 1.0, d, q_pred.get()));
    CATENA_PETSC(VecWAXPY(state.pending_v(), w0, d, v_pred.get()));
    CATENA_PETSC(VecWAXPY(state.pending_a(), w0 * w0, d, a_pred.get()));
    algebraic->zero_algebraic(state.pending_v());
    algebraic->zero_algebraic(state.pending_a());
  }

  // R(δ) = M a₁ + f(t₁, q₁, v₁) in the nodal rows, (m̄ w₀²) g(q₁) in the constraint rows.
  void residual_at(Vec d, Vec r) {
    kinematics(d);
    system.force({state.pending_q(), state.pending_v(), {}, t1}, f1.get(), &scale1);
    CATENA_PETSC(MatMult(mass_product.get(), state.pending_a(), r));
    CATENA_PETSC(VecAXPY(r, 1.0, f1.get()));
    if (algebraic->active()) {
      algebraic->take_algebraic(r, f1.get());
      algebraic->scale_rows(r, algebraic->mass_scale() * w0_newton * w0_newton);
    }
  }

  // J = w₀² M + w₀ C + K (+ Gᵀ; constraint rows scaled to m̄ G).
  void build_matrix(Vec d, bool refresh_tangent, Mat J) {
    if (refresh_tangent) {
      kinematics(d);
      evaluate_tangent(state.pending_q(), state.pending_v(), t1);
      ++counters.jacobian_evaluations;
    }
    const double w0 = w0_newton;
    w0_matrix = w0;
    CATENA_PETSC(MatCopy(mass.get(), J, SAME_NONZERO_PATTERN));
    CATENA_PETSC(MatScale(J, w0 * w0));
    if (const Mat damping = damping_matrix())
      CATENA_PETSC(MatAXPY(J, w0, damping, SAME_NONZERO_PATTERN));
    CATENA_PETSC(MatAXPY(J, 1.0, K.get(), SAME_NONZERO_PATTERN));
    if (algebraic->active()) {
      CATENA_PETSC(MatAXPY(J, 1.0, coupling.get(), SAME_NONZERO_PATTERN));
      algebraic->scale_rows(J, algebraic->mass_scale() * w0 * w0);
    }
  }

  StepOutcome finish_attempt(const NewtonResult& result, const ErrorTolerance* tol) {
    StepOutcome out = newton_outcome(result, residual.get(), counters);
    if (!out.converged) {
      state.discard_pending();
      return out;
    }
    kinematics(delta.get());
    state.set_pending(t1);
    if (tol) {
      CATENA_PETSC(VecCopy(delta.get(), error.get()));
      // δ = q₁ − q̂ = (1 + ρ)(q(t₁) − q̂) and the local error is ρ(q(t₁) − q̂) (header).
      const double rho = formula.error_constant / (formula.w[0] * h);
      CATENA_PETSC(VecScale(error.get(), rho / (1.0 + rho)));
      out.error = weighted_error_norm(*tol, error.get(), state.q(), state.pending_q());
    }
    return out;
  }

  // The history holds the current state only (a start or a restart).
  void restart_history() {
    CATENA_PETSC(VecCopy(state.q(), q_back[0].get()));
    CATENA_PETSC(VecCopy(state.v(), v_back[0].get()));
    t_back[0] = state.time();
    known = 1;
  }
};

MultistepIntegrator::MultistepIntegrator(assembly::SecondOrderSystem& system,
                                         const MultistepOptions& options)
    : StepStateIntegrator(system) {
  if (options.family == MultistepFamily::bdf && (options.order < 1 || options.order > 5))
    throw InputError({"", 0, "integrator.order"},
                     "BDF order " + std::to_string(options.order) + "; accepted: 1 to 5");
  impl_ = std::make_unique<Impl>(system, options, step_state());
  Impl& s = *impl_;
  if (options.family == MultistepFamily::park) s.options.order = 2;
  const std::size_t points = static_cast<std::size_t>(s.history_needed());
  s.q_back.resize(points);
  s.v_back.resize(points);
  s.t_back.assign(points, 0.0);
  for (std::size_t j = 0; j < points; ++j) {
    s.q_back[j] = system.create_vector();
    s.v_back[j] = system.create_vector();
  }
  for (VecHandle* v :
       {&s.q_pred, &s.v_pred, &s.a_pred, &s.delta, &s.difference, &s.f1, &s.residual, &s.error})
    *v = system.create_vector();
  PetscReal tolerance = kMatrixTolerance;
  CATENA_PETSC(
      PetscOptionsGetReal(nullptr, "multistep_", "-matrix_tolerance", &tolerance, nullptr));
  if (!(tolerance >= 0.0))
    throw InputError({"", 0, "-multistep_matrix_tolerance"},
                     "multistep matrix tolerance " + std::to_string(tolerance) +
                         "; accepted: >= 0 (the relative change of w0 that rebuilds the Newton "
                         "matrix)");
  s.matrix_tolerance = tolerance;
  s.newton = s.make_newton(
      "multistep_", options.max_newton_iterations, options.full_newton, s.residual.get(),
      [&s](Vec d, Vec r) { s.residual_at(d, r); },
      [&s](Vec d, bool refresh, Mat J) { s.build_matrix(d, refresh, J); });
}

MultistepIntegrator::~MultistepIntegrator() = default;

std::string MultistepIntegrator::name() const {
  if (impl_->options.family == MultistepFamily::park) return "park";
  return "bdf(order=" + std::to_string(impl_->options.order) + ")";
}

int MultistepIntegrator::order() const { return impl_->options.order; }

double MultistepIntegrator::max_step_ratio() const {
  return step_ratio_limit(impl_->options.family, impl_->options.order);
}

void MultistepIntegrator::set_state(double t, Vec q, Vec v, Vec a) {
  Impl& s = *impl_;
  s.state.start(t, q, v, a, consistent_acceleration_of(s.system, s.mass.get()));
  s.system.force({s.state.q(), s.state.v(), {}, t}, s.f1.get(), &s.scale0);
  s.restart_history();
  s.newton->invalidate_tangent();
}

StepOutcome MultistepIntegrator::attempt(double h, const ErrorTolerance* tol) {
  Impl& s = *impl_;
  s.h = h;
  s.t1 = s.state.time() + h;
  s.formula = s.choose_formula();
  // Kept within the tolerance (also after a restart, which rebuilds the matrix it saved);
  // full Newton rebuilds the matrix at every iterate, so with the formula's own w₀.
  s.w0_newton = s.w0_matrix;
  if (s.options.full_newton || std::abs(s.formula.w[0] / s.w0_matrix - 1.0) > s.matrix_tolerance) {
    s.w0_newton = s.formula.w[0];
    s.newton->invalidate_matrix();
  }
  s.predict();
  CATENA_PETSC(VecSet(s.delta.get(), 0.0));
  if (!s.round_off.known()) s.evaluate_tangent(s.state.q(), s.state.v(), s.state.time());
  // The unknown is a position correction, so the inertia rows M (Σ α_j q_j)/h² carry the
  // round-off of positions over h², as the scaled constraint rows do: the floor is added to
  // the whole residual's tolerance here (HHT and IRK solve for accelerations, and weight
  // only the constraint rows). Weighting them alone made an adaptive BDF-5 run of the
  // squeezer (rtol 1e-7), cut to small steps at its start-up, stop at dt_min.
  const double floor = s.algebraic->residual_floor(1.0 / (s.w0_newton * s.w0_newton), s.state.q());
  const NewtonResult result =
      s.newton->solve(s.delta.get(), s.options.atol + s.options.rtol * s.scale0 +
                                         s.round_off.at(s.state.q()) + floor);
  return s.finish_attempt(result, tol);
}

void MultistepIntegrator::accept() {
  Impl& s = *impl_;
  s.state.accept("MultistepIntegrator");
  // The oldest point's vectors take the new current point.
  std::rotate(s.q_back.rbegin(), s.q_back.rbegin() + 1, s.q_back.rend());
  std::rotate(s.v_back.rbegin(), s.v_back.rbegin() + 1, s.v_back.rend());
  std::rotate(s.t_back.rbegin(), s.t_back.rbegin() + 1, s.t_back.rend());
  CATENA_PETSC(VecCopy(s.state.q(), s.q_back[0].get()));
  CATENA_PETSC(VecCopy(s.state.v(), s.v_back[0].get()));
  s.t_back[0] = s.state.time();
  s.known = std::min(s.known + 1, s.history_needed());
  s.scale0 = s.scale1;
  ++s.counters.steps_accepted;
}

void MultistepIntegrator::interpolate(double t, Vec q, Vec v) { impl_->state.interpolate(t, q, v); }

const IntegratorCounters& MultistepIntegrator::counters() const {
  Impl& s = *impl_;
  const NewtonCounters& n = s.newton->counters();
  s.counters.residual_evaluations = n.residual_evaluations;
  s.counters.factorizations = n.factorizations;
  s.counters.linear_solves = n.linear_solves;
  return s.counters;
}

// The history (the current point's entries duplicate the state's, kept so that a restart
// needs nothing else), the force scale, the matrix's w₀, the tangent's point, Newton's
// state and the counters.
void MultistepIntegrator::save_resume_state(ResumeState& out) const {
  const Impl& s = *impl_;
  out.integers["multistep.known"] = s.known;
  for (int j = 0; j < s.known; ++j) {
    const std::string i = std::to_string(j);
    out.vectors["multistep.q" + i] = s.q_back[static_cast<std::size_t>(j)].get();
    out.vectors["multistep.v" + i] = s.v_back[static_cast<std::size_t>(j)].get();
    out.reals["multistep.t" + i] = s.t_back[static_cast<std::size_t>(j)];
  }
  s.save_tangent(out, "multistep");
  out.reals["multistep.scale0"] = s.scale0;
  out.reals["multistep.w0_matrix"] = s.w0_matrix;
  save_own_counters(s.counters, out);
  s.newton->save_resume_state(out);
}

void MultistepIntegrator::restore_resume_state(const ResumeState& in) {
  if (in.empty()) return;
  Impl& s = *impl_;
  const std::int64_t known = in.integer("multistep.known");
  if (known < 1 || known > s.history_needed())
    throw Error("checkpoint: multistep history of " + std::to_string(known) + " points for " +
                name() + ", which keeps 1 to " + std::to_string(s.history_needed()));
  s.known = static_cast<int>(known);
  for (int j = 0; j < s.known; ++j) {
    const std::string i = std::to_string(j);
    CATENA_PETSC(
        VecCopy(in.vector("multistep.q" + i), s.q_back[static_cast<std::size_t>(j)].get()));
    CATENA_PETSC(
        VecCopy(in.vector("multistep.v" + i), s.v_back[static_cast<std::size_t>(j)].get()));
    s.t_back[static_cast<std::size_t>(j)] = in.real("multistep.t" + i);
  }
  s.scale0 = in.real("multistep.scale0");
  s.w0_matrix = in.real("multistep.w0_matrix");
  restore_own_counters(in, s.counters);
  s.newton->restore_resume_state(in);
  if (s.restore_tangent(in, "multistep")) ++s.counters.jacobian_evaluations;
}

}  // namespace catena::solvers

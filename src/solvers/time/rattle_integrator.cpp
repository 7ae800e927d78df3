#include "catena/solvers/time/rattle_integrator.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/solvers/modes/modal_analysis.hpp"
#include "catena/solvers/newton/reusable_newton.hpp"
#include "catena/solvers/time/newton_outcome.hpp"
#include "catena/solvers/time/step_matrices.hpp"

namespace catena::solvers {

// M, the Newton matrix, the multiplier layout and the matrix's point: StepMatrices (its K
// only for the round-off floor of f: the Newton matrix holds no stiffness).
struct RattleIntegrator::Impl : StepMatrices {
  RattleOptions options;
  StepState& state;
  double h = 0.0, h_matrix = -1.0;
  int phase = 1;
  double scale0 = 0.0, scale1 = 0.0;
  // v½, the step's end positions q₁ (nodal slots), and work vectors.
  VecHandle v_half, q_end, q_start_lambda, f_start, f_end, residual, g_velocity, beta;
  // The Newton matrix's point (StepMatrices' tangent point stays the round-off floor's).
  VecHandle matrix_q, matrix_v;
  double matrix_t = 0.0;
  MatHandle G;  // the constraint rows G(q₁) alone (phase 2's velocity constraint)
  std::unique_ptr<ReusableNewton> newton;
  IntegratorCounters counters;
  long constraint_passes = 0;  // phase 1's constraint-only pass per residual (g at q₁)
  double omega_max = 0.0;      // rad/s at the first state set (the stability limit)
  bool omega_known = false;    // 0 is a value too: nothing stiff, no limit

  Impl(assembly::SecondOrderSystem& s, const RattleOptions& o, StepState& st)
      : StepMatrices(s, st.q()), options(o), state(st) {}

  double t0() const { return state.time(); }
  double t1() const { return state.time() + h; }

  // v½ = v₀ + ½h K₁ and q₁ = q₀ + h v½ from phase 1's unknown.
  void half_step(Vec x) {
    CATENA_PETSC(VecWAXPY(v_half.get(), 0.5 * h, x, state.v()));
    algebraic->zero_algebraic(v_half.get());
    CATENA_PETSC(VecWAXPY(q_end.get(), h, v_half.get(), state.q()));
  }

  // v₁ = v½ + ½h K₂ and q₁ with Λ₂ in its multiplier slots, from phase 2's unknown.
  void end_state(Vec x) {
    CATENA_PETSC(VecWAXPY(state.pending_v(), 0.5 * h, x, v_half.get()));
    algebraic->zero_algebraic(state.pending_v());
    CATENA_PETSC(VecCopy(q_end.get(), state.pending_q()));
    algebraic->take_algebraic(state.pending_q(), x);
  }

  // Phase 1: M K₁ + f(t₀, q₀, v½) + G(q₀)ᵀΛ₁ in the force rows, (m̄/(½h²)) g(q₁, t₁) in the
  // constraint rows.
  void phase_one(Vec x, Vec r) {
    half_step(x);
    CATENA_PETSC(VecCopy(state.q(), q_start_lambda.get()));
    algebraic->take_algebraic(q_start_lambda.get(), x);
    system.force({q_start_lambda.get(), v_half.get(), {}, t0()}, f_start.get());
    CATENA_PETSC(MatMult(mass_product.get(), x, r));
    CATENA_PETSC(VecAXPY(r, 1.0, f_start.get()));
    if (!algebraic->active()) return;
    // g(q₁) from the constraint couplings alone at q₁ (no pass over the elements).
    system.constraint_residual({q_end.get(), v_half.get(), {}, t1()}, f_end.get());
    ++constraint_passes;
    algebraic->take_algebraic(r, f_end.get());
    algebraic->scale_rows(r, algebraic->mass_scale() / (0.5 * h * h));
  }

  // Phase 2: M K₂ + f(t₁, q₁, v½) + G(q₁)ᵀΛ₂ in the force rows (Lobatto IIIB's second stage
  // velocity is v½: taking v₁ there, implicitly, made a damped run first order), and
  // (m̄/(½h)) (G(q₁) v₁ − β(t₁)) in the constraint rows.
  void phase_two(Vec x, Vec r) {
    end_state(x);
    system.force({state.pending_q(), v_half.get(), {}, t1()}, f_end.get(), &scale1);
    CATENA_PETSC(MatMult(mass_product.get(), x, r));
    CATENA_PETSC(VecAXPY(r, 1.0, f_end.get()));
    if (!algebraic->active()) return;
    CATENA_PETSC(MatMult(G.get(), state.pending_v(), g_velocity.get()));
    CATENA_PETSC(VecAXPY(g_velocity.get(), -1.0, beta.get()));
    algebraic->take_algebraic(r, g_velocity.get());
    algebraic->scale_rows(r, algebraic->mass_scale() / (0.5 * h));
  }

  void residual_at(Vec x, Vec r) { phase == 1 ? phase_one(x, r) : phase_two(x, r); }

  // J = M + ½h C + Gᵀ + m̄ G at the matrix's point (phase 2's force rows do not depend on
  // its unknown: no C there); a refresh moves the point to the iterate's q₁ and v½, with
  // its multipliers.
  void build_matrix(Vec x, bool refresh, Mat J) {
    if (refresh) {
      if (phase == 1) {
        half_step(x);
        CATENA_PETSC(VecCopy(q_end.get(), matrix_q.get()));
      } else {
        end_state(x);
        CATENA_PETSC(VecCopy(state.pending_q(), matrix_q.get()));
      }
      CATENA_PETSC(VecCopy(v_half.get(), matrix_v.get()));
      algebraic->take_algebraic(matrix_q.get(), x);
      matrix_t = t1();
      ++counters.jacobian_evaluations;
    }
    const double c_C = phase == 1 && system.has_damping() ? 0.5 * h : 0.0;
    system.jacobian({matrix_q.get(), matrix_v.get(), {}, matrix_t},
                    {0.0, c_C, 1.0, 1.0, algebraic->mass_scale()}, J);
  }

  // ω_max of K φ = ω² M φ over the nodal DOFs at (q, v, t), the multipliers left out (their
  // rows and columns of K zeroed, of M made identity): the unconstrained structure's, an
  // upper bound of the constrained one's, so 2/ω_max is a safe step. K holds the
  // constraints' curvature Σλ H, the stiffness their forces give (a spinning body's frame).
  double highest_nodal_frequency(Vec q, Vec v, double t) {
    evaluate_tangent(q, v, t);
    ++counters.jacobian_evaluations;
    if (!algebraic->active()) return highest_frequency(K.get(), mass.get());
    MatHandle k, m;
    CATENA_PETSC(MatDuplicate(K.get(), MAT_COPY_VALUES, k.out()));
    CATENA_PETSC(MatDuplicate(mass.get(), MAT_COPY_VALUES, m.out()));
    std::vector<PetscInt> rows;
    PetscInt lo = 0, hi = 0;
    CATENA_PETSC(VecGetOwnershipRange(algebraic->mask(), &lo, &hi));
    const PetscScalar* mask = nullptr;
    CATENA_PETSC(VecGetArrayRead(algebraic->mask(), &mask));
    for (PetscInt i = lo; i < hi; ++i)
      if (mask[i - lo] != 0.0) rows.push_back(i);
    CATENA_PETSC(VecRestoreArrayRead(algebraic->mask(), &mask));
    const auto n = static_cast<PetscInt>(rows.size());
    CATENA_PETSC(MatZeroRowsColumns(k.get(), n, rows.data(), 0.0, nullptr, nullptr));
    CATENA_PETSC(MatZeroRowsColumns(m.get(), n, rows.data(), 1.0, nullptr, nullptr));
    return highest_frequency(k.get(), m.get());
  }

  // The largest nodal |x| (at least 1), for the velocity rows' round-off floor.
  static double nodal_max(Vec x) {
    PetscReal norm = 0.0;
    CATENA_PETSC(VecNorm(x, NORM_INFINITY, &norm));
    return std::max(1.0, static_cast<double>(norm));
  }
};

RattleIntegrator::RattleIntegrator(assembly::SecondOrderSystem& system,
                                   const RattleOptions& options)
    : StepStateIntegrator(system), impl_(std::make_unique<Impl>(system, options, step_state())) {
  Impl& s = *impl_;
  for (VecHandle* v : {&s.v_half, &s.q_end, &s.q_start_lambda, &s.f_start, &s.f_end, &s.residual,
                       &s.g_velocity, &s.beta, &s.matrix_q, &s.matrix_v})
    *v = system.create_vector();
  if (s.algebraic->active()) s.G = system.create_matrix();
  s.newton = s.make_newton(
      "rattle_", options.max_newton_iterations, options.full_newton, s.residual.get(),
      [&s](Vec x, Vec r) { s.residual_at(x, r); },
      [&s](Vec x, bool refresh, Mat J) { s.build_matrix(x, refresh, J); });
}

RattleIntegrator::~RattleIntegrator() = default;

void RattleIntegrator::set_state(double t, Vec q, Vec v, Vec a) {
  Impl& s = *impl_;
  // Without a, the consistent one (also λ0 with constraints).
  s.state.start(t, q, v, a, consistent_acceleration_of(s.system, s.mass.get()));
  s.scale0 = s.system.element_force_norm({s.state.q(), s.state.v(), {}, t});
  s.newton->invalidate_tangent();
  // The stability limit at the initial state, once (not again when step doubling returns
  // to a step's start).
  if (!s.omega_known) {
    s.omega_max = s.highest_nodal_frequency(s.state.q(), s.state.v(), t);
    s.omega_known = true;
  }
}

double RattleIntegrator::stable_step() const {
  const Impl& s = *impl_;
  return s.omega_max > 0.0 ? 2.0 / s.omega_max : std::numeric_limits<double>::infinity();
}

std::string RattleIntegrator::stable_step_reason() const {
  std::ostringstream os;
  os << "RATTLE is explicit in the stiffness, stable for steps up to 2/omega_max = "
     << stable_step() << " s, omega_max = " << impl_->omega_max
     << " rad/s, the highest frequency at the initial state without the constraints "
        "(docs/integrators.md, \"RATTLE\")";
  return os.str();
}

StepOutcome RattleIntegrator::attempt(double h, const ErrorTolerance* tol) {
  (void)tol;  // no embedded estimate: the driver uses step doubling
  Impl& s = *impl_;
  s.h = h;
  if (h != s.h_matrix) {
    s.newton->invalidate_matrix();
    s.h_matrix = h;
  }
  const double atol = s.options.atol + s.options.rtol * s.scale0 + s.round_off.at(s.state.q());
  Vec x = s.state.pending_a();

  // Phase 1 from K₁ = a₀ with Λ₁ = λ₀.
  s.phase = 1;
  CATENA_PETSC(VecCopy(s.state.a(), x));
  s.algebraic->take_algebraic(x, s.state.q());
  const double floor1 = s.algebraic->residual_floor(0.5 * h * h, s.state.q());
  const NewtonResult one = s.newton->solve(x, atol, s.algebraic->residual_measure(atol, floor1));
  StepOutcome out = newton_outcome(one, s.residual.get(), s.counters);
  if (!out.converged) {
    s.state.discard_pending();
    return out;
  }
  s.half_step(x);
  if (s.algebraic->active()) {
    const assembly::EvalPoint end{s.q_end.get(), s.v_half.get(), {}, s.t1()};
    s.system.constraint_jacobian(end, {0.0, 0.0, 0.0, 0.0, 1.0}, s.G.get());
    s.system.constraint_velocity(end, s.beta.get());
  }

  // Phase 2 from K₂ = K₁ with Λ₂ = Λ₁, on the matrix at q₁: exact for it (its force and
  // G(q₁) are fixed, so the phase is linear: one iteration) and the next step's phase 1
  // matrix (its columns at that step's q₀ = q₁). Phase 2 on the matrix phase 1 left had its
  // first iterate's residual grow (the top: 3.0 to 4.7).
  s.phase = 2;
  s.newton->invalidate_tangent();
  const double floor2 =
      s.algebraic->residual_floor(0.5 * h, s.state.q()) * Impl::nodal_max(s.v_half.get());
  const NewtonResult two = s.newton->solve(x, atol, s.algebraic->residual_measure(atol, floor2));
  const StepOutcome second = newton_outcome(two, s.residual.get(), s.counters);
  out.newton_iterations += second.newton_iterations;
  out.residual_norm = second.residual_norm;
  if (!second.converged) {
    out.converged = false;
    out.failure = "velocity phase: " + second.failure;
    out.worst_dof = second.worst_dof;
    s.state.discard_pending();
    return out;
  }
  s.end_state(x);                  // the solve's last residual need not have been at x
  s.algebraic->zero_algebraic(x);  // Λ₂ now lives in q₁
  s.state.set_pending(s.t1());
  return out;
}

void RattleIntegrator::accept() {
  Impl& s = *impl_;
  s.state.accept("RattleIntegrator");
  s.scale0 = s.scale1;
  ++s.counters.steps_accepted;
}

void RattleIntegrator::interpolate(double t, Vec q, Vec v) { impl_->state.interpolate(t, q, v); }

// The step-to-step state beyond (t, q, v, a): the force scale, the matrix's point and h,
// Newton's state, the counters.
void RattleIntegrator::save_resume_state(ResumeState& out) const {
  const Impl& s = *impl_;
  s.save_tangent(out, "rattle");
  out.reals["rattle.scale0"] = s.scale0;
  out.reals["rattle.h_matrix"] = s.h_matrix;
  out.integers["rattle.constraint_passes"] = s.constraint_passes;
  out.reals["rattle.omega_max"] = s.omega_max;  // the run's start's, not the restart's
  out.vectors["rattle.matrix_q"] = s.matrix_q.get();
  out.vectors["rattle.matrix_v"] = s.matrix_v.get();
  out.reals["rattle.matrix_t"] = s.matrix_t;
  save_own_counters(s.counters, out);
  s.newton->save_resume_state(out);
}

void RattleIntegrator::restore_resume_state(const ResumeState& in) {
  if (in.empty()) return;
  Impl& s = *impl_;
  s.scale0 = in.real("rattle.scale0");
  s.h_matrix = in.real("rattle.h_matrix");
  s.constraint_passes = in.integer("rattle.constraint_passes");
  s.omega_max = in.real("rattle.omega_max");
  s.omega_known = true;
  CATENA_PETSC(VecCopy(in.vector("rattle.matrix_q"), s.matrix_q.get()));
  CATENA_PETSC(VecCopy(in.vector("rattle.matrix_v"), s.matrix_v.get()));
  s.matrix_t = in.real("rattle.matrix_t");
  restore_own_counters(in, s.counters);
  s.newton->restore_resume_state(in);
  // The floor's tangent as it was (the matrix is rebuilt from its point at the next solve).
  if (s.restore_tangent(in, "rattle")) ++s.counters.jacobian_evaluations;
}

const IntegratorCounters& RattleIntegrator::counters() const {
  Impl& s = *impl_;
  const NewtonCounters& n = s.newton->counters();
  s.counters.residual_evaluations = n.residual_evaluations;  // g at q₁ costs no element pass
  s.counters.factorizations = n.factorizations;
  s.counters.linear_solves = n.linear_solves;
  return s.counters;
}

}  // namespace catena::solvers

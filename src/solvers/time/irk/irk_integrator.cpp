#include "catena/solvers/time/irk/irk_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/model/integrator_catalogue.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/newton/mumps_status.hpp"
#include "catena/solvers/newton/reusable_newton.hpp"
#include "catena/solvers/newton/round_off_floor.hpp"
#include "catena/solvers/time/algebraic_part.hpp"
#include "catena/solvers/time/consistent_acceleration.hpp"
#include "catena/solvers/time/irk/block_matrix.hpp"
#include "catena/solvers/time/irk/decoupled_stage_solver.hpp"
#include "catena/solvers/time/irk/interleaved_vectors.hpp"
#include "catena/solvers/time/newton_outcome.hpp"
#include "catena/solvers/time/step_state.hpp"

namespace catena::solvers {
namespace {

// y = x0 + Σ_j w_j parts_j (y may not alias the parts).
void combine(Vec y, Vec x0, const std::vector<double>& w, const std::vector<VecHandle>& parts) {
  CATENA_PETSC(VecCopy(x0, y));
  std::vector<Vec> raw;
  for (const VecHandle& p : parts) raw.push_back(p.get());
  CATENA_PETSC(VecMAXPY(y, static_cast<PetscInt>(raw.size()), w.data(), raw.data()));
}

std::vector<VecHandle> vectors(assembly::SecondOrderSystem& system, int count) {
  std::vector<VecHandle> v;
  for (int i = 0; i < count; ++i) v.push_back(system.create_vector());
  return v;
}

}  // namespace

struct IrkIntegrator::Impl {
  assembly::SecondOrderSystem& system;
  IrkOptions options;
  ButcherTableau T;
  int s;
  Eigen::MatrixXd A2;     // A²
  Eigen::VectorXd bA;     // bᵀA
  Eigen::MatrixXd L;      // Lagrange basis on c: ℓ_j(σ) = Σ_k L(j, k) σ^k (s ≥ 2)
  bool polynomial_dense;  // dense output by the collocation polynomial
  bool stiffly_accurate;

  // The current state, the one before (dense output) and the pending step.
  StepState& state;
  // h_last: the last accepted step's size (the predictor's and the dense output's).
  double h = 0.0, h_last = 0.0, h_matrix = -1.0;
  double scale0 = 0.0, stage_scale = 0.0;
  RoundOffFloor round_off;  // of f (round_off_floor.hpp)
  double klast_end = -1.0;  // end time of the step whose stages Klast holds
  VecHandle scratch;
  std::vector<VecHandle> Kst, Klast, U, V, F;
  MatHandle mass, K, C;
  // Where K and C were last evaluated (kept for a restart, which evaluates them there again).
  VecHandle tangent_q, tangent_v;
  double tangent_t = 0.0;
  std::vector<MatHandle> Ks, Cs;  // full Newton: per-stage tangents
  // Constraints: the multiplier slots of stage i's unknown hold Λ_i; `mass_coupling` is
  // M + Gᵀ, the block-diagonal part of the stage matrix (coefficient δ_ij).
  std::unique_ptr<AlgebraicPart> algebraic;
  MatHandle mass_coupling;
  // Tableaus other than Radau IIA: the step-end multipliers from the acceleration-level
  // equations at (q1, v1), as their stage multipliers converge at low order or not at all
  // (Gauss: the error grows like 1/h; docs/integrators.md).
  std::unique_ptr<AccelerationSolver> end_multipliers;
  // Exactly one of the two stage solvers: the coupled s·n matrix, or the decoupled blocks
  // (with `row_scale`, the constraint rows' scaling d as a vector, when constrained).
  std::unique_ptr<BlockMatrix> block;
  std::unique_ptr<DecoupledStageSolver> decoupled;
  VecHandle row_scale;
  double row_scale_factor = 0.0;
  // The h and tangent the decoupled blocks were last assembled with (their real block is
  // the Radau IIA estimate's filter matrix when these match the estimate's).
  double blocks_h = -1.0;
  long blocks_tangent = -1;
  VecHandle x, r;
  std::unique_ptr<ReusableNewton> newton;
  long tangent_serial = 0;  // bumped whenever K, C change

  // Embedded estimate (Radau IIA, odd s).
  MatHandle E;
  KspHandle estimate_ksp;
  double estimate_h = -1.0;
  long estimate_tangent = -1;
  VecHandle ru, rv, rhs, xu, xv;
  long estimate_factorizations = 0, estimate_solves = 0;

  IntegratorCounters counters;

  Impl(assembly::SecondOrderSystem& sys, const IrkOptions& o, StepState& st)
      : system(sys), options(o), T(make_tableau(o.family, o.stages)), s(T.stages), state(st) {
    A2 = a_squared(T);
    bA = T.A.transpose() * T.b;
    stiffly_accurate = T.stiffly_accurate && T.c(s - 1) == 1.0;
    const bool collocation = T.family == TableauFamily::gauss ||
                             T.family == TableauFamily::radau_iia ||
                             T.family == TableauFamily::lobatto_iiia;
    polynomial_dense = collocation && s >= 2;
    if (s >= 2) {
      Eigen::MatrixXd vandermonde(s, s);  // row i: c_i^k
      for (int i = 0; i < s; ++i)
        for (int k = 0; k < s; ++k) vandermonde(i, k) = std::pow(T.c(i), k);
      // ℓ_j(c_i) = δ_ij  ⇒  vandermonde · Lᵀ = I.
      L = vandermonde.inverse().transpose();
    }
  }

  // Lagrange weights ℓ_j(σ), and their integrals w_j = ∫0^σ ℓ_j, W_j = ∫0^σ (σ − τ) ℓ_j dτ.
  void basis(double sigma, std::vector<double>& l, std::vector<double>* w,
             std::vector<double>* W) const {
    l.assign(s, 0.0);
    if (w) w->assign(s, 0.0);
    if (W) W->assign(s, 0.0);
    for (int j = 0; j < s; ++j)
      for (int k = 0; k < s; ++k) {
        const double p = std::pow(sigma, k);
        l[j] += L(j, k) * p;
        if (w) (*w)[j] += L(j, k) * p * sigma / (k + 1);
        if (W) (*W)[j] += L(j, k) * p * sigma * sigma / ((k + 1) * (k + 2));
      }
  }

  // U_i, V_i from the stage accelerations in Kst.
  void stage_states() {
    std::vector<double> w(s);
    for (int i = 0; i < s; ++i) {
      for (int j = 0; j < s; ++j) w[j] = h * h * A2(i, j);
      combine(U[i].get(), state.q(), w, Kst);
      CATENA_PETSC(VecAXPY(U[i].get(), T.c(i) * h, state.v()));
      for (int j = 0; j < s; ++j) w[j] = h * T.A(i, j);
      combine(V[i].get(), state.v(), w, Kst);
      algebraic->take_algebraic(U[i].get(), Kst[i].get());
      algebraic->zero_algebraic(V[i].get());
    }
  }

  // Constraint rows g(U_i) are scaled by m̄/h² (the stage matrix then holds m̄ Ā_ij G).
  double constraint_row_scale() const { return algebraic->mass_scale() / (h * h); }
  Mat block_diagonal_part() const { return algebraic->active() ? mass_coupling.get() : mass.get(); }

  std::vector<Vec> raw(const std::vector<VecHandle>& v) const {
    std::vector<Vec> out;
    for (const VecHandle& e : v) out.push_back(e.get());
    return out;
  }

  void residual(Vec xk, Vec rk) {
    split_interleaved(xk, raw(Kst));
    stage_states();
    stage_scale = 0.0;
    for (int i = 0; i < s; ++i) {
      double norm = 0.0;
      system.force({U[i].get(), V[i].get(), {}, state.time() + T.c(i) * h}, F[i].get(), &norm);
      stage_scale = std::max(stage_scale, norm);
      CATENA_PETSC(MatMultAdd(mass.get(), Kst[i].get(), F[i].get(), F[i].get()));
      algebraic->scale_rows(F[i].get(), constraint_row_scale());
    }
    counters.residual_evaluations += s;
    join_interleaved(raw(F), rk);
  }

  BlockCoefficients coefficients() const {
    BlockCoefficients c(s);
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) {
        c.M(i, j) = i == j ? 1.0 : 0.0;
        c.C(i, j) = h * T.A(i, j);
        c.K(i, j) = h * h * A2(i, j);
      }
    return c;
  }

  // M + Gᵀ with G at p, where the constraints are not linear: the constraints' columns
  // assembled alone, the constant M added.
  void refresh_mass_coupling(const assembly::EvalPoint& p) {
    system.constraint_jacobian(p, {0.0, 0.0, 0.0, 1.0, 0.0}, mass_coupling.get());
    CATENA_PETSC(MatAXPY(mass_coupling.get(), 1.0, mass.get(), SAME_NONZERO_PATTERN));
  }

  // The one K, C of the simplified Newton (and the round-off floor's tangent) at p.
  void evaluate_tangent(const assembly::EvalPoint& p) {
    if (p.q != tangent_q.get()) {
      CATENA_PETSC(VecCopy(p.q, tangent_q.get()));
      CATENA_PETSC(VecCopy(p.v, tangent_v.get()));
    }
    tangent_t = p.t;
    system.tangent_parts({tangent_q.get(), tangent_v.get(), {}, p.t}, K.get(), C.get());
    // M + Gᵀ with G where K is, and at its velocity: a slider's Coulomb friction puts
    // μ φ(ṡ) ∂n/∂λ into its multiplier columns.
    if (algebraic->active() && !system.constraints_linear())
      refresh_mass_coupling({tangent_q.get(), tangent_v.get(), {}, p.t});
    ++counters.jacobian_evaluations;
    ++tangent_serial;
    round_off.set_tangent(K.get());
  }

  void evaluate_start_tangent() { evaluate_tangent({state.q(), state.v(), {}, state.time()}); }

  // A refreshed tangent of the simplified Newton: at the current iterate's last stage
  // (Radau IIA, Lobatto: the step's end), not at (q0, v0) as RADAU5 does. Where a force law
  // has a kink that the step crosses (a dropper going slack), the start's tangent is wrong
  // for the whole step however often it is re-evaluated: with cable droppers the iteration
  // then contracted by only 0.3–0.4 per iterate and the step was halved instead
  // (docs/catenary.md, "Droppers as cables"). Away from kinks either point gives the
  // simplified Newton's linear contraction, O(h) per iterate.
  void evaluate_iterate_tangent(Vec xk) {
    split_interleaved(xk, raw(Kst));
    stage_states();
    const int last = s - 1;
    evaluate_tangent({U[last].get(), V[last].get(), {}, state.time() + T.c(last) * h});
  }

  void build(Vec xk, bool refresh, Mat) {
    if (options.full_newton) {
      split_interleaved(xk, raw(Kst));
      stage_states();
      std::vector<Mat> k_rows, c_rows;
      for (int i = 0; i < s; ++i) {
        system.tangent_parts({U[i].get(), V[i].get(), {}, state.time() + T.c(i) * h}, Ks[i].get(),
                             Cs[i].get());
        k_rows.push_back(Ks[i].get());
        c_rows.push_back(Cs[i].get());
      }
      counters.jacobian_evaluations += s;
      // Where G depends on q, the multiplier columns of every stage take G at the last
      // stage's state (a simplified part of the full Newton: it converges linearly there).
      if (algebraic->active() && !system.constraints_linear())
        refresh_mass_coupling({U[s - 1].get(), V[s - 1].get(), {}, state.time() + T.c(s - 1) * h});
      block->assemble_rows(k_rows, c_rows, block_diagonal_part(), coefficients());
    } else if (decoupled) {
      if (refresh) evaluate_iterate_tangent(xk);
      decoupled->assemble({K.get(), C.get(), block_diagonal_part(), constraint_row_vector(), h});
      blocks_h = h;
      blocks_tangent = tangent_serial;
      return;
    } else {
      if (refresh) evaluate_iterate_tangent(xk);
      block->assemble(K.get(), C.get(), block_diagonal_part(), coefficients());
    }
    algebraic->scale_rows(block->matrix(), constraint_row_scale(), s);
  }

  // The constraint rows' scaling as a vector d (1 on nodal rows), or null unconstrained.
  Vec constraint_row_vector() {
    if (!algebraic->active()) return nullptr;
    const double factor = constraint_row_scale();
    if (!row_scale) row_scale = system.create_vector();
    if (factor != row_scale_factor) {
      CATENA_PETSC(VecSet(row_scale.get(), 1.0));
      algebraic->scale_rows(row_scale.get(), factor);
      row_scale_factor = factor;
    }
    return row_scale.get();
  }

  void predict() {
    if (s >= 2 && klast_end == state.time() && h_last > 0.0) {
      std::vector<double> l;
      for (int i = 0; i < s; ++i) {
        basis(1.0 + T.c(i) * h / h_last, l, nullptr, nullptr);
        CATENA_PETSC(VecSet(Kst[i].get(), 0.0));
        std::vector<Vec> parts = raw(Klast);
        CATENA_PETSC(VecMAXPY(Kst[i].get(), s, l.data(), parts.data()));
      }
    } else {
      for (int i = 0; i < s; ++i) {
        CATENA_PETSC(VecCopy(state.a(), Kst[i].get()));
        algebraic->take_algebraic(Kst[i].get(), state.q());  // constant λ
      }
    }
    join_interleaved(raw(Kst), x.get());
  }

  // The Radau IIA estimate x_u (docs/tableaus.md), in the weighted norm.
  double embedded_error(const ErrorTolerance& tol) {
    const Eigen::VectorXd d = *T.b_embedded - T.b;
    const Eigen::VectorXd Atd = T.A.transpose() * d;
    std::vector<double> w(s);
    for (int j = 0; j < s; ++j) w[j] = h * h * Atd(j);
    CATENA_PETSC(VecSet(scratch.get(), 0.0));
    combine(ru.get(), scratch.get(), w, Kst);
    for (int j = 0; j < s; ++j) w[j] = h * d(j);
    combine(rv.get(), scratch.get(), w, Kst);
    const double g = h * T.gamma0;
    CATENA_PETSC(VecAXPY(rv.get(), g, state.a()));
    if (options.full_newton || tangent_serial == 0) {
      // Full Newton keeps no tangent at the step start: take one for the filter.
      evaluate_start_tangent();
    }
    // Decoupled: the filter M + hγ0 C + (hγ0)² K is the real block of the stage solve (γ0
    // is A's real eigenvalue), factored already when it was built for this h and tangent.
    KSP filter = nullptr;
    if (decoupled && blocks_h == h && blocks_tangent == tangent_serial)
      filter = decoupled->real_block(T.gamma0);
    if (!filter && (estimate_h != h || estimate_tangent != tangent_serial)) {
      CATENA_PETSC(MatCopy(mass.get(), E.get(), SAME_NONZERO_PATTERN));
      CATENA_PETSC(MatAXPY(E.get(), g, C.get(), SAME_NONZERO_PATTERN));
      CATENA_PETSC(MatAXPY(E.get(), g * g, K.get(), SAME_NONZERO_PATTERN));
      CATENA_PETSC(KSPSetOperators(estimate_ksp.get(), E.get(), E.get()));
      estimate_h = h;
      estimate_tangent = tangent_serial;
      ++estimate_factorizations;
    }
    if (!filter) filter = estimate_ksp.get();
    // rhs = M r_v − g K r_u
    CATENA_PETSC(MatMult(mass.get(), rv.get(), rhs.get()));
    CATENA_PETSC(MatMult(K.get(), ru.get(), scratch.get()));
    CATENA_PETSC(VecAXPY(rhs.get(), -g, scratch.get()));
    CATENA_PETSC(KSPSolve(filter, rhs.get(), xv.get()));
    ++estimate_solves;
    if (direct_solve_status(filter).failed()) return 1e10;  // reject: h will shrink
    CATENA_PETSC(VecWAXPY(xu.get(), g, xv.get(), ru.get()));
    return weighted_error_norm(tol, xu.get(), state.q(), state.pending_q());
  }
};

IrkIntegrator::IrkIntegrator(assembly::SecondOrderSystem& system, const IrkOptions& options)
    : StepStateIntegrator(system), impl_(std::make_unique<Impl>(system, options, step_state())) {
  Impl& m = *impl_;
  for (VecHandle* v : {&m.scratch, &m.ru, &m.rv, &m.rhs, &m.xu, &m.xv, &m.tangent_q, &m.tangent_v})
    *v = system.create_vector();
  m.Kst = vectors(system, m.s);
  m.Klast = vectors(system, m.s);
  m.U = vectors(system, m.s);
  m.V = vectors(system, m.s);
  m.F = vectors(system, m.s);
  m.mass = system.create_matrix();
  system.jacobian({m.state.q(), nullptr, {}}, {0.0, 0.0, 1.0}, m.mass.get());
  // K, C and E take the mass matrix's full pattern (so MatAXPY can keep it).
  for (MatHandle* A : {&m.K, &m.C, &m.E})
    CATENA_PETSC(MatDuplicate(m.mass.get(), MAT_DO_NOT_COPY_VALUES, A->out()));
  if (options.full_newton)
    for (int i = 0; i < m.s; ++i) {
      m.Ks.push_back(system.create_matrix());
      m.Cs.push_back(system.create_matrix());
    }
  m.algebraic = std::make_unique<AlgebraicPart>(system, m.mass.get());
  if (m.algebraic->active()) {
    // Lobatto IIIA: A's zero first row (explicit first stage) makes the stage matrix
    // singular in the multiplier rows (the catalogue's refusal, also the scene reader's).
    if (const std::optional<model::IntegratorRefusal> refusal = model::refuse_integrator(
            {.type = std::string(tableau_family_name(m.T.family)), .stages = m.s},
            system.model().constraints.size(), !system.constraints_linear()))
      throw InputError({"", 0, "integrator." + refusal->key}, refusal->why);
    if (m.T.family != TableauFamily::radau_iia)
      m.end_multipliers = std::make_unique<AccelerationSolver>(system, m.mass.get());
    m.mass_coupling = system.create_matrix();
    system.jacobian({m.state.q(), nullptr, {}}, {0.0, 0.0, 1.0, 1.0, 0.0}, m.mass_coupling.get());
  }
  // Decoupled where the transformation is exact: simplified Newton (one K, C for every
  // stage) and an A with distinct nonzero eigenvalues.
  std::string why_not;
  std::optional<TableauDecomposition> form;
  if (options.full_newton)
    why_not = "full Newton linearises every stage at its own state (no Kronecker form)";
  else
    form = decompose_butcher_matrix(m.T.A, &why_not);
  if (options.linear_algebra == StageLinearAlgebra::decoupled && !form)
    throw InputError({"", 0, "integrator.linear_algebra"},
                     "linear_algebra: decoupled is not exact for " + m.T.name + ": " + why_not +
                         "; use coupled (or auto)");
  const Mat pattern = m.algebraic->active() ? m.mass_coupling.get() : m.mass.get();
  if (form && options.linear_algebra != StageLinearAlgebra::coupled)
    m.decoupled = std::make_unique<DecoupledStageSolver>(
        pattern, m.T.A, m.A2, *form, "irk_",
        m.algebraic->active() ? Pivoting::required : Pivoting::needed);
  else
    m.block = std::make_unique<BlockMatrix>(m.mass.get(), m.s);
  m.x = create_interleaved_vector(m.state.q(), m.s);
  m.r = create_interleaved_vector(m.state.q(), m.s);
  NewtonSettings settings;
  settings.max_iterations = options.max_newton_iterations;
  settings.full_newton = options.full_newton;
  settings.pivoting = m.algebraic->active() ? Pivoting::required : Pivoting::needed;
  m.newton = std::make_unique<ReusableNewton>(
      system.comm(), m.decoupled ? m.decoupled->operator_matrix() : m.block->matrix(), m.r.get(),
      "irk_", JacobianSymmetry::general, settings, [&m](Vec xk, Vec rk) { m.residual(xk, rk); },
      [&m](Vec xk, bool refresh, Mat J) { m.build(xk, refresh, J); });
  if (m.decoupled) {
    m.decoupled->install(m.newton->ksp(), m.newton->callback_guard());
    DecoupledStageSolver* solver = m.decoupled.get();
    m.newton->set_linear_solve_check([solver] { return solver->failure(); });
  }
  if (has_embedded_estimate())
    m.estimate_ksp = create_direct_ksp(system.comm(), "irk_estimate_", JacobianSymmetry::general);
}

IrkIntegrator::~IrkIntegrator() = default;

std::string IrkIntegrator::name() const { return impl_->T.name; }
int IrkIntegrator::order() const { return impl_->T.order; }
// With constraints the Radau IIA estimate's filter (M − γhC − γ²h²K)⁻¹ would need the
// index-3 treatment of RADAU5; step doubling serves there instead (docs/integrators.md).
bool IrkIntegrator::has_embedded_estimate() const {
  return model::has_embedded_estimate(integrator_type(impl_->T.family), impl_->s,
                                      impl_->algebraic->active());
}
int IrkIntegrator::estimate_order() const {
  return has_embedded_estimate() ? impl_->T.embedded_order + 1 : 0;
}
// On nonlinear index-3 constraints the velocities converge at the stage order (Radau IIA:
// s, against 2s − 1 for the positions; Hairer & Wanner II, VII.4, Table 4.1); linear
// constraints leave the classical order (docs/integrators.md, "Orders measured").
int IrkIntegrator::velocity_order() const {
  const Impl& m = *impl_;
  if (!m.algebraic->active() || m.system.constraints_linear()) return m.T.order;
  return std::min(m.T.order, m.T.stage_order);
}
const ButcherTableau& IrkIntegrator::tableau() const { return impl_->T; }
bool IrkIntegrator::decoupled() const { return static_cast<bool>(impl_->decoupled); }

void IrkIntegrator::set_state(double t, Vec q, Vec v, Vec a) {
  Impl& m = *impl_;
  m.state.start(t, q, v, a, consistent_acceleration_of(m.system, m.mass.get()));
  m.system.force({m.state.q(), m.state.v(), {}, t}, m.scratch.get(), &m.scale0);
  m.h_last = 0.0;  // no step behind this state: dense output is the state itself
}

void IrkIntegrator::forget_jacobian() { impl_->newton->invalidate_tangent(); }

StepOutcome IrkIntegrator::attempt(double h, const ErrorTolerance* tol) {
  Impl& m = *impl_;
  m.h = h;
  if (h != m.h_matrix) {
    m.newton->invalidate_matrix();
    m.h_matrix = h;
  }
  m.predict();
  if (!m.round_off.known()) m.evaluate_start_tangent();  // the floor needs a tangent
  const double root_s = std::sqrt(static_cast<double>(m.s));
  const double atol =
      m.options.atol + m.options.rtol * m.scale0 * root_s + m.round_off.at(m.state.q()) * root_s;
  const double floor = m.algebraic->residual_floor(h * h, m.state.q()) * root_s;
  const NewtonResult result =
      m.newton->solve(m.x.get(), atol, m.algebraic->residual_measure(atol, floor, m.s));
  // The stage vector interleaves s rows per DOF (worst_dof).
  StepOutcome out = newton_outcome(result, m.r.get(), m.counters, m.s);
  if (!out.converged) {
    m.state.discard_pending();
    return out;
  }
  // The last residual was evaluated at the converged stages: Kst, U, V belong to them.
  std::vector<double> w(m.s);
  for (int j = 0; j < m.s; ++j) w[j] = h * h * m.bA(j);
  combine(m.state.pending_q(), m.state.q(), w, m.Kst);
  CATENA_PETSC(VecAXPY(m.state.pending_q(), h, m.state.v()));
  for (int j = 0; j < m.s; ++j) w[j] = h * m.T.b(j);
  combine(m.state.pending_v(), m.state.v(), w, m.Kst);
  if (m.stiffly_accurate) {
    CATENA_PETSC(VecCopy(m.Kst[m.s - 1].get(), m.state.pending_a()));
  } else if (m.s >= 2) {
    std::vector<double> l;
    m.basis(1.0, l, nullptr, nullptr);
    CATENA_PETSC(VecSet(m.scratch.get(), 0.0));
    combine(m.state.pending_a(), m.scratch.get(), l, m.Kst);
  } else {
    CATENA_PETSC(VecCopy(m.Kst[0].get(), m.state.pending_a()));
  }
  // a1's multiplier slots hold λ1 (the last stage's, or the stage polynomial's value).
  m.algebraic->take_algebraic(m.state.pending_q(), m.state.pending_a());
  m.algebraic->zero_algebraic(m.state.pending_v());
  m.algebraic->zero_algebraic(m.state.pending_a());
  if (m.end_multipliers) {
    m.end_multipliers->solve(m.state.time() + h, m.state.pending_q(), m.state.pending_v(),
                             m.state.pending_a());
    m.counters.residual_evaluations += 1;
  }
  m.state.set_pending(m.state.time() + h);
  if (tol && has_embedded_estimate()) out.error = m.embedded_error(*tol);
  return out;
}

void IrkIntegrator::accept() {
  Impl& m = *impl_;
  m.state.accept("IrkIntegrator");
  std::swap(m.Klast, m.Kst);
  m.h_last = m.h;
  m.klast_end = m.state.time();
  m.scale0 = m.stage_scale;
  ++m.counters.steps_accepted;
}

void IrkIntegrator::interpolate(double t, Vec q, Vec v) {
  Impl& m = *impl_;
  const double h = m.h_last;
  if (h <= 0.0) {  // no step taken since set_state
    m.state.copy_current(q, v);
    return;
  }
  // Over the step of size h_last, as the predictor (not previous_time() to time(), which
  // differs from it in round-off).
  const double theta = (t - m.state.previous_time()) / h;
  if (!m.polynomial_dense) {
    m.state.interpolate_hermite(theta, h, q, v);
    return;
  }
  std::vector<double> l, w, W;
  m.basis(theta, l, &w, &W);
  if (v) {
    for (double& x : w) x *= h;
    combine(v, m.state.previous_v(), w, m.Klast);
  }
  if (q) {
    for (double& x : W) x *= h * h;
    combine(q, m.state.previous_q(), W, m.Klast);
    CATENA_PETSC(VecAXPY(q, theta * h, m.state.previous_v()));
    if (m.algebraic->active()) {  // λ by the stage polynomial through Λ_1 … Λ_s
      CATENA_PETSC(VecSet(m.scratch.get(), 0.0));
      combine(m.xu.get(), m.scratch.get(), l, m.Klast);
      m.algebraic->take_algebraic(q, m.xu.get());
    }
  }
  if (v) m.algebraic->zero_algebraic(v);
}

// The step-to-step state: the last step's stages and size (the predictor), the scale of the
// Newton tolerance, the tangent's point and serial, the matrix's h, Newton's state, the
// counters. The blocks and the estimate's filter are refactored at the next attempt.
void IrkIntegrator::save_resume_state(ResumeState& out) const {
  const Impl& m = *impl_;
  for (int j = 0; j < m.s; ++j) out.vectors["irk.stage" + std::to_string(j)] = m.Klast[j].get();
  out.vectors["irk.tangent_q"] = m.tangent_q.get();
  out.vectors["irk.tangent_v"] = m.tangent_v.get();
  out.reals["irk.scale0"] = m.scale0;
  out.reals["irk.h_last"] = m.h_last;
  out.reals["irk.klast_end"] = m.klast_end;
  out.reals["irk.h_matrix"] = m.h_matrix;
  out.reals["irk.tangent_t"] = m.tangent_t;
  out.integers["irk.tangent_serial"] = m.tangent_serial;
  out.integers["irk.estimate_factorizations"] = m.estimate_factorizations;
  out.integers["irk.estimate_solves"] = m.estimate_solves;
  out.integers["irk.residual_evaluations"] = m.counters.residual_evaluations;
  save_own_counters(m.counters, out);
  m.newton->save_resume_state(out);
}

void IrkIntegrator::restore_resume_state(const ResumeState& in) {
  if (in.empty()) return;
  Impl& m = *impl_;
  for (int j = 0; j < m.s; ++j)
    CATENA_PETSC(VecCopy(in.vector("irk.stage" + std::to_string(j)), m.Klast[j].get()));
  m.scale0 = in.real("irk.scale0");
  m.h_last = in.real("irk.h_last");
  m.klast_end = in.real("irk.klast_end");
  m.h_matrix = in.real("irk.h_matrix");
  m.estimate_factorizations = in.integer("irk.estimate_factorizations");
  m.estimate_solves = in.integer("irk.estimate_solves");
  restore_own_counters(in, m.counters);
  m.counters.residual_evaluations = in.integer("irk.residual_evaluations");
  m.newton->restore_resume_state(in);
  // K, C and the floor as they were, evaluated again at their point; the stage blocks and
  // the estimate's filter are assembled and factored again from them when next needed.
  const long serial = static_cast<long>(in.integer("irk.tangent_serial"));
  if (serial > 0)
    m.evaluate_tangent(
        {in.vector("irk.tangent_q"), in.vector("irk.tangent_v"), {}, in.real("irk.tangent_t")});
  m.tangent_serial = serial;
  m.blocks_h = m.estimate_h = -1.0;
  m.blocks_tangent = m.estimate_tangent = -1;
}

const IntegratorCounters& IrkIntegrator::counters() const {
  Impl& m = *impl_;
  const NewtonCounters& n = m.newton->counters();
  // The stage Newton's work plus the estimate's filter solves.
  IntegratorCounters& c = m.counters;
  c.factorizations = n.factorizations + m.estimate_factorizations;
  c.linear_solves = n.linear_solves + m.estimate_solves;
  return c;
}

}  // namespace catena::solvers

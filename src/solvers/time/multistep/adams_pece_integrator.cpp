#include "catena/solvers/time/multistep/adams_pece_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/modes/modal_analysis.hpp"
#include "catena/solvers/time/algebraic_part.hpp"
#include "catena/solvers/time/consistent_acceleration.hpp"
#include "catena/solvers/time/multistep/multistep_formulas.hpp"

namespace catena::solvers {
namespace {

// The radius of the left half-disc inside the PECE region of absolute stability, order 1
// and 2 (docs/integrators.md, "Adams–Bashforth–Moulton").
double stable_radius(int order) { return order == 1 ? 1.0 : 1.28; }

// Milne's factor C_M/(C_B − C_M) of the constant-step error constants: AB-1 ½, AM-1 −½;
// AB-2 5/12, AM-2 −1/12.
double milne_factor(int order) { return order == 1 ? 0.5 : 1.0 / 6.0; }

}  // namespace

struct AdamsPeceIntegrator::Impl {
  assembly::SecondOrderSystem& system;
  AdamsPeceOptions options;
  StepState& state;
  MatHandle mass;
  std::unique_ptr<AccelerationSolver> acceleration;
  std::unique_ptr<AlgebraicPart> algebraic;  // the multiplier slots
  // v and a at t₀ (the current point), t₋₁, ...; `known` of them valid.
  std::vector<VecHandle> v_back, a_back;
  std::vector<double> t_back;
  int known = 0;
  VecHandle q_pred, v_pred, a_pred, error;
  double omega_max = 0.0, nu_max = 0.0;  // rad/s and 1/s at the first state set
  IntegratorCounters counters;

  Impl(assembly::SecondOrderSystem& s, const AdamsPeceOptions& o, StepState& st)
      : system(s), options(o), state(st) {}

  // a(t, q, v): one force evaluation and one solve with the factored mass matrix (with
  // constraints the saddle-point matrix, which also gives λ into q's multiplier slots).
  void evaluate(double t, Vec q, Vec v, Vec a) {
    acceleration->solve(t, q, v, a);
    ++counters.residual_evaluations;
    ++counters.linear_solves;
    counters.factorizations = acceleration->factorizations();
  }

  // The seed paper's stabilisation (Pogorelov 1998, §3: its ABM3, which solves the
  // equations of index 3, 2 and 1 at the corrected state): the corrected positions are
  // moved onto g(q, t₁) = 0 and the velocities onto G v = β(t₁), each the nearest in the
  // kinetic-energy norm, before the final evaluation gives a₁ and λ₁. Without it the
  // acceleration-level constraints alone let the positions drift from g = 0 like t².
  // False (q₁ not reached) if the position's Newton steps did not converge.
  bool stabilise(double t1, Vec q1, Vec v1) {
    algebraic->zero_algebraic(q1);  // λ₀ (forces) out of the coordinates' size
    PetscReal size = 0.0;
    CATENA_PETSC(VecNorm(q1, NORM_INFINITY, &size));
    const int steps =
        acceleration->project_position(t1, q1, kProjectionTolerance * std::max(1.0, size), 8);
    if (steps < 0) return false;
    counters.linear_solves += steps + 1;
    acceleration->project_velocity(t1, q1, v1);
    counters.factorizations = acceleration->factorizations();
    return true;
  }
  // Relative to the largest coordinate: a hundred round-offs of it.
  static constexpr double kProjectionTolerance = 100.0 * std::numeric_limits<double>::epsilon();

  // y₁ = y₀ + Σ_j weights_j·derivative_j over the derivative's nodes (new first if `with_new`).
  static void add_integral(Vec out, Vec y0, const std::vector<double>& w, Vec fresh,
                           const std::vector<VecHandle>& past, bool with_new) {
    CATENA_PETSC(VecCopy(y0, out));
    std::size_t j = 0;
    if (with_new) CATENA_PETSC(VecAXPY(out, w[j++], fresh));
    for (std::size_t i = 0; j < w.size(); ++i, ++j) CATENA_PETSC(VecAXPY(out, w[j], past[i].get()));
  }

  // The highest undamped frequency and damping rate at (t, q, v): the stability limit.
  // With constraints, over the nodal unknowns alone (K's nodal block holds the constraints'
  // Σ λ H): the motions the constraints allow are a subspace of those, and a pencil's largest
  // eigenvalue on a subspace is at most its largest on the whole (Courant–Fischer), so the
  // limit is safe, if sometimes short.
  void measure_spectrum(double t) {
    MatHandle K = system.create_matrix(), C;
    if (system.has_damping()) C = system.create_matrix();
    system.tangent_parts({state.q(), state.v(), {}, t}, K.get(), C.get());
    ++counters.jacobian_evaluations;
    MatHandle K_nodal, M_nodal, C_nodal;
    Mat k = K.get(), m = mass.get(), c = C.get();
    if (algebraic->active()) {
      IsHandle nodal = nodal_rows();
      CATENA_PETSC(
          MatCreateSubMatrix(k, nodal.get(), nodal.get(), MAT_INITIAL_MATRIX, K_nodal.out()));
      CATENA_PETSC(
          MatCreateSubMatrix(m, nodal.get(), nodal.get(), MAT_INITIAL_MATRIX, M_nodal.out()));
      k = K_nodal.get();
      m = M_nodal.get();
      refuse_massless(m);
      if (c) {
        CATENA_PETSC(
            MatCreateSubMatrix(c, nodal.get(), nodal.get(), MAT_INITIAL_MATRIX, C_nodal.out()));
        c = C_nodal.get();
      }
    }
    omega_max = highest_frequency(k, m);
    if (c) {
      const double root = highest_frequency(c, m);  // sqrt of C's eigenvalue
      nu_max = root * root;
    }
  }

  // Collective. Throws NumericalError if a nodal unknown has no mass (a zero diagonal of M):
  // its frequency, and with it the step limit, is undefined. (The constraints' saddle-point
  // matrix may still be regular, so the acceleration solve does not catch it.)
  static void refuse_massless(Mat m) {
    VecHandle diagonal;
    CATENA_PETSC(MatCreateVecs(m, diagonal.out(), nullptr));
    CATENA_PETSC(MatGetDiagonal(m, diagonal.get()));
    CATENA_PETSC(VecAbs(diagonal.get()));
    PetscReal smallest = 0.0;
    CATENA_PETSC(VecMin(diagonal.get(), nullptr, &smallest));
    if (!(smallest > 0.0))
      throw NumericalError(
          "abm: an unknown without mass (its diagonal of M is zero) has no highest frequency, "
          "so the explicit method's step limit is undefined; use hht, radau, bdf or park");
  }

  // Collective. The global indices of this rank's nodal (not multiplier) unknowns.
  IsHandle nodal_rows() const {
    const PetscScalar* mask = nullptr;
    PetscInt n = 0, first = 0;
    CATENA_PETSC(VecGetLocalSize(algebraic->mask(), &n));
    CATENA_PETSC(VecGetOwnershipRange(algebraic->mask(), &first, nullptr));
    std::vector<PetscInt> rows;
    CATENA_PETSC(VecGetArrayRead(algebraic->mask(), &mask));
    for (PetscInt i = 0; i < n; ++i)
      if (PetscRealPart(mask[i]) == 0.0) rows.push_back(first + i);
    CATENA_PETSC(VecRestoreArrayRead(algebraic->mask(), &mask));
    IsHandle is;
    CATENA_PETSC(ISCreateGeneral(system.comm(), static_cast<PetscInt>(rows.size()), rows.data(),
                                 PETSC_COPY_VALUES, is.out()));
    return is;
  }
};

AdamsPeceIntegrator::AdamsPeceIntegrator(assembly::SecondOrderSystem& system,
                                         const AdamsPeceOptions& options)
    : StepStateIntegrator(system) {
  if (options.order < 1 || options.order > 2)
    throw InputError({"", 0, "integrator.order"},
                     "Adams-Bashforth-Moulton order " + std::to_string(options.order) +
                         "; accepted: 1 or 2 (ABM-3 and 4 in PECE form are unstable for "
                         "undamped modes at any step)");
  impl_ = std::make_unique<Impl>(system, options, step_state());
  Impl& s = *impl_;
  const std::size_t points = static_cast<std::size_t>(options.order);
  s.t_back.assign(points, 0.0);
  for (std::size_t j = 0; j < points; ++j) {
    s.v_back.push_back(system.create_vector());
    s.a_back.push_back(system.create_vector());
  }
  for (VecHandle* v : {&s.q_pred, &s.v_pred, &s.a_pred, &s.error}) *v = system.create_vector();
  s.mass = system.create_matrix();
  system.jacobian({s.state.q(), nullptr, {}}, {0.0, 0.0, 1.0}, s.mass.get());
  s.acceleration = std::make_unique<AccelerationSolver>(system, s.mass.get());
  s.algebraic = std::make_unique<AlgebraicPart>(system, s.mass.get());
  s.counters.factorizations = s.acceleration->factorizations();
}

AdamsPeceIntegrator::~AdamsPeceIntegrator() = default;

std::string AdamsPeceIntegrator::name() const {
  return "abm(order=" + std::to_string(impl_->options.order) + ")";
}

int AdamsPeceIntegrator::order() const { return impl_->options.order; }

void AdamsPeceIntegrator::set_state(double t, Vec q, Vec v, Vec a) {
  Impl& s = *impl_;
  s.state.start(t, q, v, a,
                [&s](double ts, Vec qs, Vec vs, Vec as) { s.evaluate(ts, qs, vs, as); });
  CATENA_PETSC(VecCopy(s.state.v(), s.v_back[0].get()));
  CATENA_PETSC(VecCopy(s.state.a(), s.a_back[0].get()));
  s.t_back[0] = t;
  s.known = 1;
  if (!(s.omega_max > 0.0)) s.measure_spectrum(t);
}

StepOutcome AdamsPeceIntegrator::attempt(double h, const ErrorTolerance* tol) {
  Impl& s = *impl_;
  const double t1 = s.state.time() + h;
  const int k = std::min(s.options.order, s.known);
  // Adams–Bashforth over the k past derivatives, Adams–Moulton over the new one and k − 1.
  std::vector<double> past(s.t_back.begin(), s.t_back.begin() + k);
  const std::vector<double> bashforth = integration_weights(past, s.state.time(), t1);
  std::vector<double> moulton_nodes{t1};
  moulton_nodes.insert(moulton_nodes.end(), s.t_back.begin(), s.t_back.begin() + (k - 1));
  const std::vector<double> moulton = integration_weights(moulton_nodes, s.state.time(), t1);
  // P, E
  Impl::add_integral(s.q_pred.get(), s.state.q(), bashforth, nullptr, s.v_back, false);
  Impl::add_integral(s.v_pred.get(), s.state.v(), bashforth, nullptr, s.a_back, false);
  s.evaluate(t1, s.q_pred.get(), s.v_pred.get(), s.a_pred.get());
  // C, (project), E
  Impl::add_integral(s.state.pending_q(), s.state.q(), moulton, s.v_pred.get(), s.v_back, true);
  Impl::add_integral(s.state.pending_v(), s.state.v(), moulton, s.a_pred.get(), s.a_back, true);
  StepOutcome out;
  if (s.system.has_constraints() && !s.stabilise(t1, s.state.pending_q(), s.state.pending_v())) {
    out.failure = "the positions' projection onto the constraints did not converge";
    s.state.discard_pending();
    return out;
  }
  s.evaluate(t1, s.state.pending_q(), s.state.pending_v(), s.state.pending_a());
  PetscReal norm = 0.0;
  CATENA_PETSC(VecNorm(s.state.pending_a(), NORM_INFINITY, &norm));
  if (!std::isfinite(norm)) {  // the state guard names growth; this is an overflow
    out.failure = "the acceleration is not finite";
    s.state.discard_pending();
    return out;
  }
  out.converged = true;
  s.state.set_pending(t1);
  if (tol) {
    CATENA_PETSC(VecWAXPY(s.error.get(), -1.0, s.q_pred.get(), s.state.pending_q()));
    CATENA_PETSC(VecScale(s.error.get(), milne_factor(k)));
    out.error = weighted_error_norm(*tol, s.error.get(), s.state.q(), s.state.pending_q());
  }
  return out;
}

void AdamsPeceIntegrator::accept() {
  Impl& s = *impl_;
  s.state.accept("AdamsPeceIntegrator");
  std::rotate(s.v_back.rbegin(), s.v_back.rbegin() + 1, s.v_back.rend());
  std::rotate(s.a_back.rbegin(), s.a_back.rbegin() + 1, s.a_back.rend());
  std::rotate(s.t_back.rbegin(), s.t_back.rbegin() + 1, s.t_back.rend());
  CATENA_PETSC(VecCopy(s.state.v(), s.v_back[0].get()));
  CATENA_PETSC(VecCopy(s.state.a(), s.a_back[0].get()));
  s.t_back[0] = s.state.time();
  s.known = std::min(s.known + 1, s.options.order);
  ++s.counters.steps_accepted;
}

void AdamsPeceIntegrator::interpolate(double t, Vec q, Vec v) { impl_->state.interpolate(t, q, v); }

const IntegratorCounters& AdamsPeceIntegrator::counters() const { return impl_->counters; }

double AdamsPeceIntegrator::stable_step() const {
  const Impl& s = *impl_;
  const double rate = std::max(s.omega_max, s.nu_max);
  return rate > 0.0 ? stable_radius(s.options.order) / rate
                    : std::numeric_limits<double>::infinity();
}

std::string AdamsPeceIntegrator::stable_step_reason() const {
  const Impl& s = *impl_;
  std::ostringstream os;
  os << "Adams-Bashforth-Moulton of order " << s.options.order
     << " (PECE) is stable for steps up to " << stable_radius(s.options.order)
     << "/max(omega_max, nu_max) = " << stable_step() << " s, omega_max = " << s.omega_max
     << " rad/s (the highest undamped frequency), nu_max = " << s.nu_max
     << " 1/s (the highest damping rate of C against M), at the initial state "
        "(docs/integrators.md, \"Adams-Bashforth-Moulton\")";
  return os.str();
}

// The history, the spectrum behind the stability limit (measured at the run's start: the
// restart's set_state measures it again at its own state, which the saved values replace,
// so that the limit and with it every step is the uninterrupted run's) and the counters.
void AdamsPeceIntegrator::save_resume_state(ResumeState& out) const {
  const Impl& s = *impl_;
  out.integers["abm.known"] = s.known;
  out.reals["abm.omega_max"] = s.omega_max;
  out.reals["abm.nu_max"] = s.nu_max;
  for (int j = 0; j < s.known; ++j) {
    const std::string i = std::to_string(j);
    out.vectors["abm.v" + i] = s.v_back[static_cast<std::size_t>(j)].get();
    out.vectors["abm.a" + i] = s.a_back[static_cast<std::size_t>(j)].get();
    out.reals["abm.t" + i] = s.t_back[static_cast<std::size_t>(j)];
  }
  save_own_counters(s.counters, out);
}

void AdamsPeceIntegrator::restore_resume_state(const ResumeState& in) {
  if (in.empty()) return;
  Impl& s = *impl_;
  const std::int64_t known = in.integer("abm.known");
  if (known < 1 || known > s.options.order)
    throw Error("checkpoint: Adams history of " + std::to_string(known) + " points for " + name() +
                ", which keeps 1 to " + std::to_string(s.options.order));
  s.known = static_cast<int>(known);
  s.omega_max = in.real("abm.omega_max");
  s.nu_max = in.real("abm.nu_max");
  for (int j = 0; j < s.known; ++j) {
    const std::string i = std::to_string(j);
    CATENA_PETSC(VecCopy(in.vector("abm.v" + i), s.v_back[static_cast<std::size_t>(j)].get()));
    CATENA_PETSC(VecCopy(in.vector("abm.a" + i), s.a_back[static_cast<std::size_t>(j)].get()));
    s.t_back[static_cast<std::size_t>(j)] = in.real("abm.t" + i);
  }
  restore_own_counters(in, s.counters);
}

}  // namespace catena::solvers

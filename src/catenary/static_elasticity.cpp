#include "catena/catenary/static_elasticity.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <variant>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/assembly/state_view.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/newton/mumps_status.hpp"
#include "catena/solvers/newton/reusable_newton.hpp"
#include "catena/solvers/newton/round_off_floor.hpp"

namespace catena::catenary {
namespace {

// The probe walks the path at 1 m/s in a fictitious time from t = kProbeEntry on: at
// t = kProbeEntry + x it stands at arc length x, and before kProbeEntry — at t = 0, where
// the base equilibrium is solved — it is off the structure. Nothing else in the model
// depends on t (moving loads and contacts are left out; the motion of prescribed
// constraints is kept out of the probe's force by the nodal mask below).
constexpr double kProbeEntry = 1.0;  // s
// The probe force is applied in halving increments when Newton fails, down to 1/64 of it.
constexpr int kMaxHalvings = 6;

double element_length(const model::Model& m, int e) {
  const auto& nodes = m.elements[static_cast<std::size_t>(e)].nodes;
  return (m.nodes[static_cast<std::size_t>(nodes.back())].position -
          m.nodes[static_cast<std::size_t>(nodes.front())].position)
      .norm();
}

double path_length(const model::Model& m, const std::vector<int>& path) {
  double length = 0.0;
  for (const int e : path) length += element_length(m, e);
  return length;
}

// The model without its moving loads and contacts, with the probe as its one moving load.
model::Model with_probe(const model::Model& m, const ElasticityProbe& probe) {
  model::Model out = m;
  out.moving_loads.clear();
  out.contacts.clear();
  model::MovingLoad load;
  load.name = "elasticity probe";
  load.elements = probe.path;
  load.force = probe.force;
  load.speed = 1.0;
  load.start = 0.0;
  load.start_time = kProbeEntry;
  out.moving_loads.push_back(std::move(load));
  return out;
}

// The time at which the probe stands at x: kProbeEntry + x, lowered by an ulp where
// rounding would put it beyond the path's end (where a moving load does nothing).
double probe_time(double x, double length) {
  double t = kProbeEntry + x;
  while (t - kProbeEntry > length) t = std::nextafter(t, 0.0);
  return t;
}

// Counts the tension-only elements (droppers) of this rank that go slack — axial strain
// below zero, shorter than unstretched — at a state where they were taut at the base
// equilibrium. Each model element is evaluated on one rank, so the counts add up.
class SlackCounter {
 public:
  // Collective. Records which of this rank's tension-only elements are taut at q0.
  SlackCounter(const assembly::SecondOrderSystem& system, Vec q0) : view_(system) {
    const model::Model& m = system.model();
    view_.section_results(at(q0), elements_, results_);
    for (std::size_t i = 0; i < elements_.size(); ++i) {
      const bool tension_only = std::visit(
          [](const auto& p) {
            if constexpr (requires { p.tension_only; })
              return p.tension_only;
            else
              return false;
          },
          *m.elements[static_cast<std::size_t>(elements_[i])].props);
      if (tension_only && results_[i].axial_strain >= 0.0) taut_.push_back(i);
    }
  }

  // Collective. How many of the elements taut at q0 are slack at q (on every rank).
  int slackened(MPI_Comm comm, Vec q) {
    view_.section_results(at(q), elements_, results_);
    int local = 0, total = 0;
    for (const std::size_t i : taut_) local += results_[i].axial_strain < 0.0 ? 1 : 0;
    MPI_Allreduce(&local, &total, 1, MPI_INT, MPI_SUM, comm);
    return total;
  }

 private:
  static assembly::EvalPoint at(Vec q) { return {q, nullptr, elements::LoadPath{}, 0.0}; }

  assembly::StateView view_;
  std::vector<int> elements_;
  std::vector<elements::SectionResult> results_;
  std::vector<std::size_t> taut_;  // positions in results_ (ascending element index)
};

// The linear elasticity's solver: the static tangent at the base equilibrium, factored
// once (LDLᵀ; the tangent with constraints is a symmetric saddle-point matrix).
class TangentSolve {
 public:
  // Collective. `tangent` is copied: the Newton iterations refill theirs.
  TangentSolve(MPI_Comm comm, Mat tangent)
      : ksp_(solvers::create_direct_ksp(comm, "elasticity_linear_",
                                        solvers::JacobianSymmetry::symmetric)) {
    CATENA_PETSC(MatDuplicate(tangent, MAT_COPY_VALUES, matrix_.out()));
    CATENA_PETSC(KSPSetOperators(ksp_.get(), matrix_.get(), matrix_.get()));
    CATENA_PETSC(KSPSetUp(ksp_.get()));
    if (const solvers::DirectSolveStatus status = solvers::direct_solve_status(ksp_.get());
        status.failed())
      throw NumericalError(
          "static elasticity: the tangent at the static equilibrium cannot be factored (" +
          status.describe() + "): the structure is not held statically");
  }

  // Collective. Pᵀ K₀⁻¹ P.
  double energy_norm(Vec P, Vec work) {
    CATENA_PETSC(KSPSolve(ksp_.get(), P, work));
    if (const solvers::DirectSolveStatus status = solvers::direct_solve_status(ksp_.get());
        status.failed())
      throw NumericalError("static elasticity: the tangent solve failed (" + status.describe() +
                           ")");
    PetscScalar value = 0.0;
    CATENA_PETSC(VecDot(P, work, &value));
    return value;
  }

 private:
  KspHandle ksp_;
  MatHandle matrix_;
};

}  // namespace

double path_arc_length_at(const model::Model& model, const std::vector<int>& path, int node) {
  double arc = 0.0;
  for (const int e : path) {
    const auto& nodes = model.elements[static_cast<std::size_t>(e)].nodes;
    const double length = element_length(model, e);
    if (nodes.front() == node) return arc;
    if (nodes.back() == node) return arc + length;
    arc += length;
  }
  return -1.0;
}

ElasticityReport static_elasticity(MPI_Comm comm, const model::Model& model,
                                   const ElasticityProbe& probe) {
  const double magnitude = probe.force.norm();
  CATENA_ASSERT(magnitude > 0.0 && std::isfinite(magnitude), "the probe force must be nonzero");
  CATENA_ASSERT(!probe.path.empty(), "the probe needs a path");
  for ([[maybe_unused]] const int e : probe.path)
    CATENA_ASSERT(!std::holds_alternative<model::BarProps>(*model.elements[e].props) &&
                      !std::holds_alternative<model::SpringProps>(*model.elements[e].props),
                  "the probe's path is made of cable or beam elements (shape functions)");
  const model::Model probed = with_probe(model, probe);
  const double length = path_length(probed, probe.path);

  assembly::SecondOrderSystem system(comm, probed);
  ElasticityReport report;
  VecHandle q0 = system.create_vector();
  system.reference_state(q0.get());
  {
    solvers::StaticSolver statics(system, probed.static_options);
    report.base = statics.solve(q0.get());
  }

  VecHandle q = system.create_vector(), q_trial = system.create_vector();
  VecHandle residual = system.create_vector(), f_base = system.create_vector();
  VecHandle P = system.create_vector(), nodal;
  MatHandle J = system.create_matrix();
  const elements::LoadPath full_load;  // the end of the load path, where solve() stops
  system.force({q0.get(), nullptr, full_load, 0.0}, f_base.get());
  if (system.has_constraints()) {  // 1 on the nodal rows, 0 on the multiplier rows
    nodal = system.create_vector();
    system.algebraic_mask(nodal.get());
    CATENA_PETSC(VecShift(nodal.get(), -1.0));
    CATENA_PETSC(VecScale(nodal.get(), -1.0));
  }
  // Newton tolerance: the scene's absolute one raised by the residual's round-off floor
  // (round_off_floor.hpp), from the tangent at the base state.
  solvers::RoundOffFloor round_off;
  system.jacobian({q0.get(), nullptr, full_load, 0.0}, assembly::kStaticJacobian, J.get());
  round_off.set_tangent(J.get());
  const double atol = probed.static_options.atol + round_off.at(q0.get());
  TangentSolve tangent(comm, J.get());
  SlackCounter slack(system, q0.get());

  // R(q) = f(q) − λ P: the structure at the end of the load path with λ of the probe.
  double lambda = 1.0;
  solvers::NewtonSettings settings;
  settings.max_iterations = probed.static_options.max_newton_iterations;
  solvers::ReusableNewton newton(
      comm, J.get(), residual.get(), "elasticity_", solvers::JacobianSymmetry::symmetric, settings,
      [&](Vec x, Vec r) {
        system.force({x, nullptr, full_load, 0.0}, r);
        CATENA_PETSC(VecAXPY(r, -lambda, P.get()));
      },
      [&](Vec x, bool, Mat matrix) {
        system.jacobian({x, nullptr, full_load, 0.0}, assembly::kStaticJacobian, matrix);
      });

  for (const double x : probe.positions) {
    CATENA_ASSERT(x >= 0.0 && x <= length, "probe position off the path");
    // P = f(q0, no probe) − f(q0, probe at x): the probe's generalised force (f carries
    // −f_ext), on the nodal rows only.
    system.force({q0.get(), nullptr, full_load, probe_time(x, length)}, P.get());
    CATENA_PETSC(VecAYPX(P.get(), -1.0, f_base.get()));
    if (nodal) CATENA_PETSC(VecPointwiseMult(P.get(), P.get(), nodal.get()));

    ElasticityPoint point;
    point.position = x;
    point.linear_elasticity = tangent.energy_norm(P.get(), q.get()) / (magnitude * magnitude);
    CATENA_PETSC(VecCopy(q0.get(), q.get()));
    double reached = 0.0, increment = 1.0;
    int halvings = 0;
    while (reached < 1.0) {
      lambda = std::min(1.0, reached + increment);
      CATENA_PETSC(VecCopy(q.get(), q_trial.get()));
      const solvers::NewtonResult result = newton.solve(q_trial.get(), atol);
      point.newton_iterations += result.iterations;
      if (result.converged) {
        CATENA_PETSC(VecCopy(q_trial.get(), q.get()));
        reached = lambda;
        ++point.increments;
      } else if (++halvings > kMaxHalvings) {
        std::ostringstream os;
        os << "static elasticity: the probe force of " << magnitude << " N at " << x
           << " m along the path could not be applied (Newton failed at " << lambda
           << " of it with increments down to 1/" << (1 << kMaxHalvings) << "): " << result.failure;
        throw NumericalError(os.str());
      } else {
        increment *= 0.5;
      }
    }
    point.slackened = slack.slackened(comm, q.get());
    // u = Pᵀ(q − q0)/|F|: the displacement at x along F, interpolated as P was spread.
    CATENA_PETSC(VecAXPY(q.get(), -1.0, q0.get()));
    PetscScalar work = 0.0;
    CATENA_PETSC(VecDot(P.get(), q.get(), &work));
    point.uplift = work / magnitude;
    point.elasticity = point.uplift / magnitude;
    report.newton_iterations += point.newton_iterations;
    report.points.push_back(point);
  }
  report.factorizations = newton.counters().factorizations;
  return report;
}

}  // namespace catena::catenary

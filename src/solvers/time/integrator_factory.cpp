#include "catena/solvers/time/integrator_factory.hpp"

#include <vector>

#include "catena/core/error.hpp"
#include "catena/model/integrator_catalogue.hpp"
#include "catena/model/unknown_kinds.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "catena/solvers/time/multistep/adams_pece_integrator.hpp"
#include "catena/solvers/time/multistep/multistep_integrator.hpp"
#include "catena/solvers/time/petsc_ts/petsc_ts_integrator.hpp"
#include "catena/solvers/time/rattle_integrator.hpp"

namespace catena::solvers {
namespace {

// Every integrator here moves the unknowns additively (q ← q + Δ on whole vectors), which
// is right for every kind whose update rule is `additive` (model/unknown_kinds.hpp). This
// switch has no default: a new rule does not compile until it is handled here — by the
// integrators implementing it, or by refusing the model with the kind's name.
void check_update_rules(const assembly::DofMap& dofs) {
  std::vector<model::UnknownKind> present{model::UnknownKind::multiplier};
  for (int n = 0; n < dofs.n_nodes(); ++n) present.push_back(dofs.node_kind(n));
  for (const model::UnknownKind kind : present) switch (model::kind_info(kind).update) {
      case model::UpdateRule::additive:
        break;
    }
}

}  // namespace

std::unique_ptr<TimeIntegrator> make_integrator(assembly::SecondOrderSystem& system,
                                                const model::IntegratorOptions& o) {
  check_update_rules(system.dof_map());
  // What the scene reader refuses with the scene's line; here for models built otherwise.
  if (const std::optional<model::IntegratorRefusal> refusal = model::refuse_integrator(
          o, system.model().constraints.size(), !system.constraints_linear()))
    throw InputError({"", 0, "integrator." + refusal->key}, refusal->why);
  if (o.type == "hht" || o.type == "central_difference") {
    HhtOptions h;
    h.central_difference = o.type == "central_difference";  // α then 0 (HhtIntegrator)
    h.alpha = o.alpha;
    h.rtol = o.newton_rtol;
    h.atol = o.newton_atol;
    h.max_newton_iterations = o.max_newton_iterations;
    h.full_newton = o.newton == "full";
    h.local_newton = o.local_newton && o.newton != "linearly_implicit";
    h.linearly_implicit = o.newton == "linearly_implicit";
    h.tangent_every = o.tangent_every;
    return std::make_unique<HhtIntegrator>(system, h);
  }
  if (o.type == "rattle") {
    RattleOptions r;
    r.rtol = o.newton_rtol;
    r.atol = o.newton_atol;
    r.max_newton_iterations = o.max_newton_iterations;
    r.full_newton = o.newton == "full";
    return std::make_unique<RattleIntegrator>(system, r);
  }
  if (o.type == "bdf" || o.type == "park") {
    MultistepOptions m;
    m.family = o.type == "park" ? MultistepFamily::park : MultistepFamily::bdf;
    m.order = o.order;
    m.rtol = o.newton_rtol;
    m.atol = o.newton_atol;
    m.max_newton_iterations = o.max_newton_iterations;
    m.full_newton = o.newton == "full";
    return std::make_unique<MultistepIntegrator>(system, m);
  }
  if (o.type == "abm") {
    AdamsPeceOptions a;
    a.order = o.order;
    return std::make_unique<AdamsPeceIntegrator>(system, a);
  }
  if (o.type == "petsc") {
    // The TS method itself comes from the options database (-ts_type, ...).
    PetscTsOptions p;
    p.alpha = o.alpha;
    p.rtol = o.newton_rtol;
    p.atol = o.newton_atol;
    p.max_newton_iterations = o.max_newton_iterations;
    return std::make_unique<PetscTsIntegrator>(system, p);
  }
  IrkOptions i;
  i.family = parse_tableau_family(o.type);
  i.stages = o.stages;
  i.rtol = o.newton_rtol;
  i.atol = o.newton_atol;
  i.max_newton_iterations = o.max_newton_iterations;
  i.full_newton = o.newton == "full";
  if (o.linear_algebra == "decoupled")
    i.linear_algebra = StageLinearAlgebra::decoupled;
  else if (o.linear_algebra == "coupled")
    i.linear_algebra = StageLinearAlgebra::coupled;
  else
    i.linear_algebra = StageLinearAlgebra::automatic;
  return std::make_unique<IrkIntegrator>(system, i);
}

StepControl make_step_control(const model::IntegratorOptions& o) {
  StepControl c;
  c.dt = o.dt;
  c.adaptive = o.adaptive;
  c.rtol = o.rtol;
  c.atol = o.atol;
  c.dt_min = o.dt_min;
  c.dt_max = o.dt_max;
  if (o.error_estimate == "embedded")
    c.estimate = ErrorEstimate::embedded;
  else if (o.error_estimate == "step_doubling")
    c.estimate = ErrorEstimate::step_doubling;
  else
    c.estimate = ErrorEstimate::automatic;
  return c;
}

}  // namespace catena::solvers

// SecondOrderSystem, part: what solvers ask of the system besides residuals and matrices —
// the multiplier slots, the prescribed motions' acceleration, whether the load path needs
// its release phase, and DOF names for messages (the class:
// include/catena/assembly/second_order_system.hpp).
#include <array>
#include <memory>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/couplings/constraint_coupling.hpp"
#include "catena/elements/ancf_cable.hpp"
#include "local_array.hpp"

namespace catena::assembly {

bool SecondOrderSystem::has_slack_prestrain() const {
  for (const auto& e : model_->elements)
    if (const auto* c = std::get_if<model::CableProps>(&*e.props);
        c && !c->prestrain_with_loads && c->prestrain < elements::AncfCable::kPathPrestrain)
      return true;
  return false;
}

std::string SecondOrderSystem::describe_dof(PetscInt global) const {
  if (global < 0 || global >= dofs_.n_global()) return "unknown DOF";
  const int node = dofs_.node_of_global(global);
  const int comp = dofs_.component_of_global(global);
  const std::string id = std::to_string(model_->nodes[static_cast<size_t>(node)].id);
  const int c = dofs_.constraint_of_global(global);
  const model::UnknownKindInfo& kind =
      model::kind_info(c >= 0 ? model::UnknownKind::multiplier : dofs_.node_kind(node));
  const std::string name = comp >= 0 ? std::string(kind.components[comp]) : "?";
  if (c >= 0)
    return "constraint " + std::to_string(c + 1) + " (multiplier " + name + ", node " + id + ")";
  if (comp >= 0 && dofs_.linked(node, comp))
    return "node " + id + " (stretch of the clamped slope)";
  return "node " + id + " (" + name + ")";
}

void SecondOrderSystem::algebraic_mask(Vec mask) const {
  CATENA_PETSC(VecSet(mask, 0.0));
  for (int c = 0; c < dofs_.n_constraints(); ++c)
    if (dofs_.multiplier_local(c, 0) >= 0)
      for (int k = 0; k < dofs_.n_multipliers(c); ++k)
        CATENA_PETSC(VecSetValue(mask, dofs_.multiplier_dof(c, k), 1.0, INSERT_VALUES));
  CATENA_PETSC(VecAssemblyBegin(mask));
  CATENA_PETSC(VecAssemblyEnd(mask));
}

void SecondOrderSystem::constraint_acceleration(const EvalPoint& p, Vec out) const {
  constraint_targets(p, out, false);
}

void SecondOrderSystem::constraint_velocity(const EvalPoint& p, Vec out) const {
  constraint_targets(p, out, true);
}

void SecondOrderSystem::constraint_targets(const EvalPoint& p, Vec out, bool velocity) const {
  CATENA_PETSC(VecSet(out, 0.0));
  scatter_to_local(p.q, q_work_.get());
  if (p.v) scatter_to_local(p.v, v_work_.get());
  {
    const detail::LocalArrayRead q(q_work_.get());
    std::unique_ptr<detail::LocalArrayRead> v;
    if (p.v) v = std::make_unique<detail::LocalArrayRead>(v_work_.get());
    for (size_t i = 0; i < couplings_.size(); ++i) {
      const auto* c = dynamic_cast<const couplings::ConstraintCoupling*>(couplings_[i].get());
      if (!c) continue;
      const ActiveDofs dofs = active(i, p.t, q.data(), work_);
      const int n = dofs_.n_multipliers(c->index());
      std::array<double, model::kMaxMultipliersPerConstraint> target{};
      const couplings::CouplingState state =
          gather(dofs, q.data(), v ? v->data() : nullptr, p.path, p.t, work_);
      const std::span<double> into{target.data(), static_cast<size_t>(n)};
      if (velocity)
        c->velocity_target(state, into);
      else
        c->acceleration_target(state, into);
      for (int k = 0; k < n; ++k)
        if (target[static_cast<size_t>(k)] != 0.0)
          CATENA_PETSC(VecSetValue(out, dofs_.multiplier_dof(c->index(), k),
                                   target[static_cast<size_t>(k)], INSERT_VALUES));
    }
  }
  CATENA_PETSC(VecAssemblyBegin(out));
  CATENA_PETSC(VecAssemblyEnd(out));
}

}  // namespace catena::assembly

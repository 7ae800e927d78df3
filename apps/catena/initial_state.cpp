#include "initial_state.hpp"

#include "catena/assembly/petsc_call.hpp"

namespace catena::app {

void apply_initial_conditions(const assembly::SecondOrderSystem& system, Vec q, Vec v) {
  const model::InitialConditions& ic = system.model().dynamic_options.initial;
  const assembly::DofMap& dofs = system.dof_map();
  PetscInt lo = 0, hi = 0;
  CATENA_PETSC(VecGetOwnershipRange(q, &lo, &hi));
  auto add = [&](Vec x, PetscInt g, double value) {
    if (g >= lo && g < hi && value != 0.0) CATENA_PETSC(VecSetValue(x, g, value, ADD_VALUES));
  };
  for (const model::InitialNodeOffset& o : ic.offsets) {
    const model::UnknownKindInfo& kind = model::kind_info(dofs.node_kind(o.node));
    // A linked slope (a clamp holding its direction) takes the offset's projection on its
    // tangent: the sum of coefficient × offset over its slots.
    for (int d = 0; d < 3; ++d) {
      add(q, dofs.global_dof(o.node, kind.position + d), o.displacement[d]);
      if (kind.gradients >= 0)
        add(q, dofs.global_dof(o.node, kind.gradients + d),
            dofs.coefficient(o.node, kind.gradients + d) * o.slope[d]);
    }
  }
  CATENA_PETSC(VecAssemblyBegin(q));
  CATENA_PETSC(VecAssemblyEnd(q));
  CATENA_PETSC(VecSet(v, 0.0));
  if (ic.velocity != Vec3::Zero()) {
    for (int node : dofs.owned_nodes())
      for (int d = 0; d < 3; ++d) add(v, dofs.global_dof(node, d), ic.velocity[d]);
  }
  // A rigid body's own velocity: ṙ += its velocity, ė_k = ω × e_k at the axes it starts
  // with (the reference's, or the static equilibrium's).
  for (const model::RigidBody& body : system.model().rigid_bodies) {
    if (dofs.global_dof(body.node, 3) < lo || dofs.global_dof(body.node, 3) >= hi) continue;
    for (int d = 0; d < 3; ++d) add(v, dofs.global_dof(body.node, d), body.velocity[d]);
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 e;
      for (int d = 0; d < 3; ++d) {
        const PetscInt g = dofs.global_dof(body.node, 3 + 3 * axis + d);
        CATENA_PETSC(VecGetValues(q, 1, &g, &e[d]));
      }
      const Vec3 rate = body.angular_velocity.cross(e);
      for (int d = 0; d < 3; ++d) add(v, dofs.global_dof(body.node, 3 + 3 * axis + d), rate[d]);
    }
  }
  CATENA_PETSC(VecAssemblyBegin(v));
  CATENA_PETSC(VecAssemblyEnd(v));
}

}  // namespace catena::app

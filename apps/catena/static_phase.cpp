#include "static_phase.hpp"

#include <algorithm>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/solvers/statics/hanging_cable_guess.hpp"
#include "log_stage.hpp"
#include "progress_lines.hpp"

namespace catena::app {

solvers::StaticReport solve_statics(assembly::SecondOrderSystem& system, Vec q,
                                    const CommandLine& cl) {
  solvers::StaticSolver solver(system, system.model().static_options);
  solver.on_progress(static_progress_lines(mpi_rank(system.comm()), cl.progress_seconds));
  const LogStage stage("Statics");
  const VecHandle guess = solvers::hanging_cable_start(system);
  return solver.solve(q, guess.get());
}

solvers::StaticReport solve_statics_holding(assembly::SecondOrderSystem& system, Vec q,
                                            const CommandLine& cl, const StaticHolds& holds) {
  model::Model held = system.model();
  const auto hold = [&](int node, unsigned mask) {
    const auto it = std::find_if(held.supports.begin(), held.supports.end(),
                                 [&](const model::Support& s) { return s.node == node; });
    if (it != held.supports.end())
      it->fixed_mask |= mask;
    else
      held.supports.push_back({node, mask, false, 0u});
  };
  for (const model::Slider& slider : held.sliders)
    hold(slider.node, 1u << 3u);  // the slider node's s (model::UnknownKind::slider)
  for (const model::AbsorbingEnd& end : held.absorbing_ends) {
    const int position = model::kind_info(system.dof_map().node_kind(end.node)).position;
    hold(end.node, 7u << static_cast<unsigned>(position));
  }
  held.absorbing_ends.clear();
  for (const StaticHolds::End& end : holds.ends_at) {
    const int slope = model::kind_info(system.dof_map().node_kind(end.node)).gradients;
    hold(end.node, 7u << static_cast<unsigned>(slope));
    held.held_places.push_back({end.node, end.position, end.slope});
  }
  if (holds.catenary_alone) {
    // As shape finding does (catenary/shape_finding.hpp): lumped stages stand on their
    // springs; a mechanism's arm, which the wire held, by the height of its last body.
    for (const model::MovingContact& c : system.model().contacts)
      if (c.mechanism) hold(c.mechanism_nodes.back(), 0b100u);
    held.contacts.clear();
    std::erase_if(held.constraints, [](const model::Constraint& c) {
      return c.type == model::ConstraintType::contact;
    });
  }
  assembly::SecondOrderSystem statics(system.comm(), held);
  const VecHandle q_held = statics.create_vector();
  statics.reference_state(q_held.get());
  const solvers::StaticReport report = solve_statics(statics, q_held.get(), cl);

  // Both systems partition the same elements and nodes alike (supports do not enter the
  // partition), so each rank owns the same nodes and constraints in both: a local copy.
  const assembly::DofMap& to = system.dof_map();
  const assembly::DofMap& from = statics.dof_map();
  const PetscScalar* x = nullptr;
  PetscScalar* y = nullptr;
  CATENA_PETSC(VecGetArrayRead(q_held.get(), &x));
  CATENA_PETSC(VecGetArray(q, &y));
  const auto copy = [&](PetscInt g_to, PetscInt g_from) {
    if (g_to < 0 || g_from < 0) return;  // fixed in `system` or held here (s: its start)
    CATENA_ASSERT(g_from >= from.first_owned() && g_from < from.first_owned() + from.n_owned(),
                  "the held model's unknowns lie on the same ranks");
    y[g_to - to.first_owned()] = x[g_from - from.first_owned()];
  };
  for (const int n : to.owned_nodes()) {
    CATENA_ASSERT(from.node_owner(n) == to.node_owner(n), "the same partition");
    for (int k = 0; k < to.node_dofs(n); ++k) copy(to.global_dof(n, k), from.global_dof(n, k));
  }
  const int rank = mpi_rank(system.comm());
  // The multipliers (the same constraints unless a contact's went with the pantographs).
  for (int c = 0; c < to.n_constraints() && !holds.catenary_alone; ++c)
    if (to.constraint_owner(c) == rank)
      for (int k = 0; k < to.n_multipliers(c); ++k)
        copy(to.multiplier_dof(c, k), from.multiplier_dof(c, k));
  // Where they are held, in q too (free there).
  for (const StaticHolds::End& end : holds.ends_at) {
    if (to.node_owner(end.node) != rank) continue;
    const model::UnknownKindInfo& kind = model::kind_info(to.node_kind(end.node));
    for (int d = 0; d < 3; ++d) {
      if (const PetscInt g = to.global_dof(end.node, kind.position + d); g >= 0)
        y[g - to.first_owned()] = end.position[d];
      if (const PetscInt g = to.global_dof(end.node, kind.gradients + d); g >= 0)
        y[g - to.first_owned()] = end.slope[d];
    }
  }
  CATENA_PETSC(VecRestoreArray(q, &y));
  CATENA_PETSC(VecRestoreArrayRead(q_held.get(), &x));
  return report;
}

}  // namespace catena::app

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
                                            const CommandLine& cl) {
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
  for (int c = 0; c < to.n_constraints(); ++c)
    if (to.constraint_owner(c) == rank)
      for (int k = 0; k < to.n_multipliers(c); ++k)
        copy(to.multiplier_dof(c, k), from.multiplier_dof(c, k));
  CATENA_PETSC(VecRestoreArray(q, &y));
  CATENA_PETSC(VecRestoreArrayRead(q_held.get(), &x));
  return report;
}

}  // namespace catena::app

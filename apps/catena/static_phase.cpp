#include "static_phase.hpp"

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

}  // namespace catena::app

// catena — parallel static and dynamic analysis of cable and beam structures.
//
//   catena check meshes/default.yaml
//   mpirun -n 2 catena run meshes/default.yaml -o default.h5
//   mpirun -n 3 catena run meshes/default.yaml --set lines[0].elements=600 -log_view
//   catena stats run.h5 --section 240 360 --json
//   mpirun -n 2 catena elasticity meshes/simple_catenary.yaml --step 0.5
//   mpirun -n 2 catena study meshes/taut_string.yaml --vary integrator.dt=4e-4,2e-4,1e-4
//
// Exit codes: 0 success, 2 bad input (scene, command line, unwritable output path, a run
// estimated too large for the memory, another run writing the same output), 3 numerical
// failure (no equilibrium found, singular structure, step size below its minimum), 4 output
// could not be written (disk full, quota, I/O error: the same on every rank; the last
// checkpoint is kept), 128 + signal after SIGTERM/SIGINT (checkpoint and output written),
// 1 anything else.
#include <cstdio>
#include <exception>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/hdf5_library.hpp"
#include "catena/io/output_error.hpp"
#include "cli.hpp"
#include "commands.hpp"
#include "launcher_watch.hpp"
#include "run_environment.hpp"
#include "scene_loading.hpp"

int main(int argc, char** argv) {
  int status = 0;
  catena::io::start_hdf5_before_mpi();
  try {
    catena::PetscSession petsc(&argc, &argv, nullptr);
    const int rank = catena::mpi_rank(PETSC_COMM_WORLD);
    const catena::app::LauncherWatch launcher_watch;  // ranks never outlive mpirun
    catena::app::record_job_layout(PETSC_COMM_WORLD);
    try {
      const catena::app::CommandLine cl = catena::app::parse_command_line(argc, argv);
      if (cl.command == "help") {
        if (rank == 0) std::fputs(catena::app::usage(cl.help_topic).c_str(), stdout);
      } else if (cl.command == "version") {
        if (rank == 0) std::fputs(catena::app::version_text().c_str(), stdout);
      } else if (cl.command == "check") {
        catena::app::command_check(PETSC_COMM_WORLD, cl);
      } else if (cl.command == "stats") {
        catena::app::command_stats(PETSC_COMM_WORLD, cl);
      } else if (cl.command == "export") {
        catena::app::command_export(PETSC_COMM_WORLD, cl);
      } else if (cl.command == "plot") {
        catena::app::command_plot(PETSC_COMM_WORLD, cl);
      } else if (cl.command == "elasticity") {
        catena::app::command_elasticity(PETSC_COMM_WORLD, cl);
      } else if (cl.command == "modes") {
        catena::app::command_modes(PETSC_COMM_WORLD, cl);
      } else if (cl.command == "study") {
        catena::app::command_study(PETSC_COMM_WORLD, cl);
      } else if (cl.command == "sweep") {
        catena::app::command_sweep(PETSC_COMM_WORLD, cl);
      } else {
        catena::app::command_run(PETSC_COMM_WORLD, cl);
      }
      catena::app::warn_unused_petsc_options(rank, cl.petsc_options);
    } catch (const catena::InputError& e) {
      if (rank == 0) std::fprintf(stderr, "catena: error: %s\n", e.what());
      status = 2;
    } catch (const catena::NumericalError& e) {
      if (rank == 0) std::fprintf(stderr, "catena: numerical failure: %s\n", e.what());
      status = 3;
    } catch (const catena::OutputError& e) {
      if (rank == 0) std::fprintf(stderr, "catena: output could not be written: %s\n", e.what());
      status = 4;
    } catch (const catena::app::RunInterrupted& e) {
      if (rank == 0)
        std::fprintf(stderr,
                     "catena: interrupted by signal %d at t = %g s; output and "
                     "checkpoint written\n",
                     e.signal, e.time);
      status = 128 + e.signal;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "catena: internal error: %s\n", e.what());
    status = 1;
  }
  return status;
}

#pragma once
#include <mpi.h>

#include "catena/model/model.hpp"
#include "cli.hpp"

namespace catena::app {

// Collective. `catena check`: validate and describe the scene.
void command_check(MPI_Comm comm, const CommandLine& cl);
// Collective. `catena run`: solve and write the output file.
void command_run(MPI_Comm comm, const CommandLine& cl);
// Collective; rank 0 reads the file and prints. `catena stats`: EN 50318 contact-force
// statistics per pantograph of a dynamic run's output (command_stats.cpp).
void command_stats(MPI_Comm comm, const CommandLine& cl);
// Collective; rank 0 reads and writes. `catena export`: a dynamic run's contact-force series
// and statistics as CSV (command_export.cpp).
void command_export(MPI_Comm comm, const CommandLine& cl);
// Collective; rank 0 reads and draws. `catena plot`: the figures of a run's output
// (contact force, spectrum, uplift at supports, static shape; command_plot.cpp).
void command_plot(MPI_Comm comm, const CommandLine& cl);
// Collective; rank 0 prints. `catena elasticity`: the static elasticity curve of one span
// of a catenary scene (command_elasticity.cpp).
void command_elasticity(MPI_Comm comm, const CommandLine& cl);
// Collective; rank 0 prints. `catena modes`: the lowest vibration modes about the static
// equilibrium, written to an HDF5/XDMF pair (command_modes.cpp).
void command_modes(MPI_Comm comm, const CommandLine& cl);
// Collective; the groups of --ranks-per-case ranks run cases, rank 0 reports. `catena
// study`: a scene under several settings against a reference (command_study.cpp).
void command_study(MPI_Comm comm, const CommandLine& cl);
// Collective; as command_study. `catena sweep`: a pantograph scene under several settings,
// each run's EN 50318 statistics tabulated (command_sweep.cpp).
void command_sweep(MPI_Comm comm, const CommandLine& cl);
// Collective. The dynamic analysis of command_run.
void run_dynamic(MPI_Comm comm, const CommandLine& cl, const model::Model& m);

// Thrown by a dynamic run stopped by SIGTERM/SIGINT after its checkpoint and output were
// written; main() exits with 128 + signal, as a shell reports a killed program.
struct RunInterrupted {
  int signal = 0;
  double time = 0.0;  // s, simulated time reached
};

}  // namespace catena::app

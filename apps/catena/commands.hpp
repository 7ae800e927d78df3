#pragma once
#include <mpi.h>

#include "cli.hpp"

namespace catena::app {

// Collective. `catena check`: validate and describe the scene.
void command_check(MPI_Comm comm, const CommandLine& cl);
// Collective. `catena run`: solve and write the output file.
void command_run(MPI_Comm comm, const CommandLine& cl);

}  // namespace catena::app

#pragma once
// What `catena --version` prints, and the end-of-command report of PETSc options that no
// solver read.
#include <mpi.h>

#include <string>
#include <vector>

namespace catena::app {

// Not collective. "catena 0.1.0 (commit 4395be6)" and the versions of PETSc, MPI and HDF5
// it runs on, one per line.
std::string version_text();

// Not collective (rank 0 prints). Warns on stderr for each of `given` (the command line's
// PETSc options, "-hht_snes_rtol") that no PETSc object read during the command: a
// misspelling, or an option for a solver this command does not create. Options Catena
// sets itself are not reported.
void warn_unused_petsc_options(int rank, const std::vector<std::string>& given);

}  // namespace catena::app

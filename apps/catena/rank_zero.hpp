#pragma once
// Serial commands under mpirun (`catena stats`, `export`, `plot`): rank 0 does the work, the
// other ranks wait and leave as it does.
#include <mpi.h>

#include <functional>
#include <string>

namespace catena::app {

// Collective. Runs `work` on rank 0 only. Every rank then leaves alike: rank 0 rethrows its
// own exception, the others an InputError naming `file` (main prints rank 0's message only).
void on_rank_zero(MPI_Comm comm, const std::string& file, const std::function<void()>& work);

}  // namespace catena::app

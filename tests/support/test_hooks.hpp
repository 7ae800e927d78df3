#pragma once
// Hooks run by the shared test main() after the tests and before MPI_Finalize
// (PETSc must be finalised before MPI).
#include <functional>

namespace catena::test {
void register_before_mpi_finalize(std::function<void()> hook);
void run_before_mpi_finalize_hooks();
}  // namespace catena::test

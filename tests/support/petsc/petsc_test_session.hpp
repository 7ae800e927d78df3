#pragma once
// Initialises PETSc once per test binary (on MPI_COMM_WORLD) and finalises it before MPI.
namespace catena::test {
void ensure_petsc();
}

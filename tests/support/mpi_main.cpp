// main() for every Catena test binary: initialises MPI (PETSc is initialised by the tests
// that need it through catena::PetscSession) and runs GoogleTest; only rank 0 prints.
#include <gtest/gtest.h>
#include <mpi.h>

#include "test_hooks.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int rc = RUN_ALL_TESTS();
  catena::test::run_before_mpi_finalize_hooks();
  int global_rc = 0;
  MPI_Allreduce(&rc, &global_rc, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return global_rc;
}

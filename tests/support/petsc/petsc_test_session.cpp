#include "petsc_test_session.hpp"

#include <petscsys.h>

#include "test_hooks.hpp"

namespace catena::test {
void ensure_petsc() {
  PetscBool initialized = PETSC_FALSE;
  PetscInitialized(&initialized);
  if (initialized) return;
  PetscInitializeNoArguments();
  register_before_mpi_finalize([] { PetscFinalize(); });
}
}  // namespace catena::test

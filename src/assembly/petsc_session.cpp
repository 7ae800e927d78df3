#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/petsc_handle.hpp"

namespace catena {

PetscSession::PetscSession(int* argc, char*** argv, const char* help) {
  CATENA_PETSC(PetscInitialize(argc, argv, nullptr, help));
  keep_petsc_errors();
}

PetscSession::~PetscSession() {
  stop_keeping_petsc_errors();
  PetscFinalize();
}

}  // namespace catena

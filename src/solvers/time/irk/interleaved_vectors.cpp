#include "catena/solvers/time/irk/interleaved_vectors.hpp"

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers {

VecHandle create_interleaved_vector(Vec part, int parts) {
  MPI_Comm comm = PETSC_COMM_SELF;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(part), &comm));
  PetscInt n_owned = 0;
  CATENA_PETSC(VecGetLocalSize(part, &n_owned));
  VecHandle v;
  CATENA_PETSC(VecCreateMPI(comm, n_owned * parts, PETSC_DETERMINE, v.out()));
  return v;
}

void split_interleaved(Vec block, const std::vector<Vec>& parts) {
  const auto s = static_cast<PetscInt>(parts.size());
  const PetscScalar* b = nullptr;
  CATENA_PETSC(VecGetArrayRead(block, &b));
  for (PetscInt i = 0; i < s; ++i) {
    PetscInt n_owned = 0;
    PetscScalar* p = nullptr;
    CATENA_PETSC(VecGetLocalSize(parts[static_cast<size_t>(i)], &n_owned));
    CATENA_PETSC(VecGetArrayWrite(parts[static_cast<size_t>(i)], &p));
    for (PetscInt l = 0; l < n_owned; ++l) p[l] = b[l * s + i];
    CATENA_PETSC(VecRestoreArrayWrite(parts[static_cast<size_t>(i)], &p));
  }
  CATENA_PETSC(VecRestoreArrayRead(block, &b));
}

void join_interleaved(const std::vector<Vec>& parts, Vec block) {
  const auto s = static_cast<PetscInt>(parts.size());
  PetscScalar* b = nullptr;
  CATENA_PETSC(VecGetArrayWrite(block, &b));
  for (PetscInt i = 0; i < s; ++i) {
    PetscInt n_owned = 0;
    const PetscScalar* p = nullptr;
    CATENA_PETSC(VecGetLocalSize(parts[static_cast<size_t>(i)], &n_owned));
    CATENA_PETSC(VecGetArrayRead(parts[static_cast<size_t>(i)], &p));
    for (PetscInt l = 0; l < n_owned; ++l) b[l * s + i] = p[l];
    CATENA_PETSC(VecRestoreArrayRead(parts[static_cast<size_t>(i)], &p));
  }
  CATENA_PETSC(VecRestoreArrayWrite(block, &b));
}

}  // namespace catena::solvers

#include <petscvec.h>

#include <algorithm>
#include <cmath>

#include "catena/assembly/petsc_call.hpp"
#include "catena/solvers/time_integrator.hpp"

namespace catena::solvers {

double weighted_error_norm(const ErrorTolerance& tol, Vec error, Vec q0, Vec q1) {
  PetscInt n_local = 0, n_global = 0;
  CATENA_PETSC(VecGetLocalSize(error, &n_local));
  CATENA_PETSC(VecGetSize(error, &n_global));
  const PetscScalar *e = nullptr, *a = nullptr, *b = nullptr, *r = nullptr;
  CATENA_PETSC(VecGetArrayRead(error, &e));
  CATENA_PETSC(VecGetArrayRead(q0, &a));
  CATENA_PETSC(VecGetArrayRead(q1, &b));
  if (tol.reference) CATENA_PETSC(VecGetArrayRead(tol.reference, &r));
  double sum = 0.0;
  for (PetscInt i = 0; i < n_local; ++i) {
    const double ref = r ? r[i] : 0.0;
    const double scale =
        tol.atol + tol.rtol * std::max(std::abs(a[i] - ref), std::abs(b[i] - ref));
    const double x = e[i] / scale;
    sum += x * x;
  }
  if (r) CATENA_PETSC(VecRestoreArrayRead(tol.reference, &r));
  CATENA_PETSC(VecRestoreArrayRead(q1, &b));
  CATENA_PETSC(VecRestoreArrayRead(q0, &a));
  CATENA_PETSC(VecRestoreArrayRead(error, &e));
  double total = 0.0;
  MPI_Comm comm = PETSC_COMM_SELF;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(error), &comm));
  MPI_Allreduce(&sum, &total, 1, MPI_DOUBLE, MPI_SUM, comm);
  return n_global > 0 ? std::sqrt(total / static_cast<double>(n_global)) : 0.0;
}

}  // namespace catena::solvers

#include <petscvec.h>

#include <algorithm>
#include <cmath>

#include "catena/assembly/petsc_call.hpp"
#include "catena/solvers/time/time_integrator.hpp"

namespace catena::solvers {

double weighted_error_norm(const ErrorTolerance& tol, Vec error, Vec q0, Vec q1) {
  PetscInt n_local = 0;
  CATENA_PETSC(VecGetLocalSize(error, &n_local));
  const PetscScalar *e = nullptr, *a = nullptr, *b = nullptr, *r = nullptr, *skip = nullptr;
  CATENA_PETSC(VecGetArrayRead(error, &e));
  CATENA_PETSC(VecGetArrayRead(q0, &a));
  CATENA_PETSC(VecGetArrayRead(q1, &b));
  if (tol.reference) CATENA_PETSC(VecGetArrayRead(tol.reference, &r));
  if (tol.algebraic) CATENA_PETSC(VecGetArrayRead(tol.algebraic, &skip));
  double sums[2] = {0.0, 0.0};  // Σ x², number of entries tested
  double& sum = sums[0];
  for (PetscInt i = 0; i < n_local; ++i) {
    if (skip && skip[i] != 0.0) continue;
    sums[1] += 1.0;
    const double ref = r ? r[i] : 0.0;
    const double scale = tol.atol + tol.rtol * std::max(std::abs(a[i] - ref), std::abs(b[i] - ref));
    const double x = e[i] / scale;
    sum += x * x;
  }
  if (skip) CATENA_PETSC(VecRestoreArrayRead(tol.algebraic, &skip));
  if (r) CATENA_PETSC(VecRestoreArrayRead(tol.reference, &r));
  CATENA_PETSC(VecRestoreArrayRead(q1, &b));
  CATENA_PETSC(VecRestoreArrayRead(q0, &a));
  CATENA_PETSC(VecRestoreArrayRead(error, &e));
  double total[2] = {0.0, 0.0};
  MPI_Comm comm = PETSC_COMM_SELF;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(error), &comm));
  MPI_Allreduce(sums, total, 2, MPI_DOUBLE, MPI_SUM, comm);
  return total[1] > 0.0 ? std::sqrt(total[0] / total[1]) : 0.0;
}

}  // namespace catena::solvers

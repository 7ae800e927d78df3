#include <petscvec.h>

#include <cmath>

#include "catena/assembly/petsc_call.hpp"
#include "catena/solvers/time/time_integrator.hpp"

namespace catena::solvers {

PetscInt worst_dof(Vec residual, PetscInt rows_per_dof) {
  PetscReal most = 0.0, least = 0.0;
  PetscInt imax = -1, imin = -1;
  CATENA_PETSC(VecMax(residual, &imax, &most));
  CATENA_PETSC(VecMin(residual, &imin, &least));
  const PetscInt row = std::abs(least) > std::abs(most) ? imin : imax;
  return row < 0 ? row : row / rows_per_dof;
}

}  // namespace catena::solvers

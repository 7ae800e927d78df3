#include <petscvec.h>

#include <cmath>

#include "catena/assembly/petsc_call.hpp"
#include "catena/solvers/time/newton_outcome.hpp"
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

StepOutcome newton_outcome(const NewtonResult& result, Vec residual, IntegratorCounters& counters,
                           PetscInt rows_per_dof) {
  StepOutcome out;
  out.converged = result.converged;
  out.newton_iterations = result.iterations;
  out.residual_norm = result.residual_norm;
  counters.newton_iterations += result.iterations;
  if (!result.converged) {
    ++counters.newton_failures;
    out.failure = result.failure;
    out.worst_dof = worst_dof(residual, rows_per_dof);
  }
  return out;
}

}  // namespace catena::solvers

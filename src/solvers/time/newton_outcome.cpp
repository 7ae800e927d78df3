#include "catena/solvers/time/newton_outcome.hpp"

namespace catena::solvers {

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

#pragma once
// The outcome of an integrator's attempt from the Newton solve of its step system
// (HHT, the implicit Runge–Kutta stages, the multistep methods): the same few fields and
// counters for each, written once.
#include <petscvec.h>

#include "catena/solvers/newton/reusable_newton.hpp"
#include "catena/solvers/time/time_integrator.hpp"

namespace catena::solvers {

// Collective (on failure: worst_dof). StepOutcome's converged, iterations and residual norm
// from `result`, its iterations added to `counters`; on failure also one more Newton failure
// counted, the reason and the worst DOF of `residual` (rows_per_dof as for worst_dof). The
// caller discards its pending step on failure and fills the error estimate on success.
StepOutcome newton_outcome(const NewtonResult& result, Vec residual, IntegratorCounters& counters,
                           PetscInt rows_per_dof = 1);

}  // namespace catena::solvers

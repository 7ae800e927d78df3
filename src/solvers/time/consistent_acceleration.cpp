#include "catena/solvers/time/consistent_acceleration.hpp"

#include <cmath>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/newton/mumps_status.hpp"

namespace catena::solvers {

AccelerationSolver::AccelerationSolver(assembly::SecondOrderSystem& system, Mat mass)
    : system_(system), algebraic_(system, mass), mass_(mass) {
  rhs_ = system.create_vector();
  if (algebraic_.active()) {
    target_ = system.create_vector();
    saddle_ = system.create_matrix();
  }
  // M alone is positive definite (or singular, reported below): no pivoting, so PETSc's LU
  // on one rank and the interface split on more, as the HHT matrix M + c_C C + c_K K. A
  // MUMPS LDLᵀ of M set the 10 km line's peak at np 2 (333 MiB per rank after it, 298 with
  // the split); LU, not PETSc's Cholesky, for its nested-dissection order. The saddle-point
  // matrix pivots (MUMPS).
  ksp_ = algebraic_.active() ? create_direct_ksp(system.comm(), "mass_", JacobianSymmetry::general)
                             : create_direct_ksp(system.comm(), "mass_", JacobianSymmetry::general,
                                                 Pivoting::not_needed, mass_);
  // G constant: factored once here, at any state (the reference's zero vector will do).
  if (system.constraints_linear()) factor(rhs_.get(), 0.0);
}

void AccelerationSolver::factor(Vec q, double t) {
  Mat A = mass_;
  if (algebraic_.active() && !system_.constraints_linear()) {
    // The same state as the last factorisation's (a projected state's velocity projection,
    // then its acceleration): its factors serve.
    PetscBool same = PETSC_FALSE;
    if (factored_q_.get() && t == factored_t_) CATENA_PETSC(VecEqual(q, factored_q_.get(), &same));
    if (same) return;
    if (!factored_q_.get()) factored_q_ = system_.create_vector();
    CATENA_PETSC(VecCopy(q, factored_q_.get()));
    factored_t_ = t;
  }
  if (algebraic_.active()) {
    // [M Gᵀ; G 0]: the constraints' rows and columns alone, the constant M added.
    system_.constraint_jacobian({q, nullptr, {}, t}, {0.0, 0.0, 0.0, 1.0, 1.0}, saddle_.get());
    CATENA_PETSC(MatAXPY(saddle_.get(), 1.0, mass_, SAME_NONZERO_PATTERN));
    A = saddle_.get();
  }
  CATENA_PETSC(KSPSetOperators(ksp_.get(), A, A));
  CATENA_PETSC(KSPSetUp(ksp_.get()));
  ++factorizations_;
  while (enlarge_mumps_workspace(ksp_.get(), direct_solve_status(ksp_.get())))
    CATENA_PETSC(KSPSetUp(ksp_.get()));
  if (const DirectSolveStatus status = direct_solve_status(ksp_.get()); status.failed())
    throw NumericalError(
        std::string(algebraic_.active() ? "the constrained mass matrix [M G'; G 0]"
                                        : "the mass matrix") +
        " is singular (" + status.describe() +
        "): every free DOF needs mass; massless nodes (e.g. joined only by massless bars "
        "or springs) need a point mass" +
        (algebraic_.active() ? "; constraints must not repeat each other or a support" : ""));
}

void AccelerationSolver::solve(double t, Vec q, Vec v, Vec a) {
  // f without the constraint forces (λ = 0): they are unknowns here.
  algebraic_.zero_algebraic(q);
  if (!system_.constraints_linear()) factor(q, t);  // G at this state
  system_.force({q, v, {}, t}, rhs_.get());
  CATENA_PETSC(VecScale(rhs_.get(), -1.0));
  if (algebraic_.active()) {
    system_.constraint_acceleration({q, v, {}, t}, target_.get());
    algebraic_.take_algebraic(rhs_.get(), target_.get());
  }
  CATENA_PETSC(KSPSolve(ksp_.get(), rhs_.get(), a));
  if (const DirectSolveStatus status = direct_solve_status(ksp_.get()); status.failed())
    throw NumericalError("the acceleration solve failed (" + status.describe() + ")");
  algebraic_.take_algebraic(q, a);
  algebraic_.zero_algebraic(a);
}

double AccelerationSolver::project_velocity(double t, Vec q, Vec v) {
  if (!algebraic_.active()) return 0.0;
  algebraic_.zero_algebraic(q);
  if (!system_.constraints_linear()) factor(q, t);
  CATENA_PETSC(MatMult(mass_, v, rhs_.get()));
  system_.constraint_velocity({q, nullptr, {}, t}, target_.get());
  algebraic_.take_algebraic(rhs_.get(), target_.get());
  VecHandle projected = system_.create_vector();
  CATENA_PETSC(KSPSolve(ksp_.get(), rhs_.get(), projected.get()));
  if (const DirectSolveStatus status = direct_solve_status(ksp_.get()); status.failed())
    throw NumericalError("the velocities' projection onto the constraints failed (" +
                         status.describe() + ")");
  algebraic_.zero_algebraic(projected.get());
  CATENA_PETSC(VecAXPY(v, -1.0, projected.get()));  // v − v′
  PetscReal change = 0.0;
  CATENA_PETSC(VecNorm(v, NORM_INFINITY, &change));
  CATENA_PETSC(VecCopy(projected.get(), v));
  return change;
}

int AccelerationSolver::project_position(double t, Vec q, double tolerance, int max_steps) {
  if (!algebraic_.active()) return 0;
  algebraic_.zero_algebraic(q);
  VecHandle step = system_.create_vector();
  for (int k = 0;; ++k) {
    system_.constraint_residual({q, nullptr, {}, t}, rhs_.get());  // nodal rows 0: λ = 0
    PetscReal violation = 0.0;
    CATENA_PETSC(VecNorm(rhs_.get(), NORM_INFINITY, &violation));
    if (violation <= tolerance) return k;
    if (k == max_steps || !std::isfinite(violation)) return -1;
    if (!system_.constraints_linear()) factor(q, t);  // G at this state
    CATENA_PETSC(VecScale(rhs_.get(), -1.0));
    CATENA_PETSC(KSPSolve(ksp_.get(), rhs_.get(), step.get()));
    if (const DirectSolveStatus status = direct_solve_status(ksp_.get()); status.failed())
      throw NumericalError("the positions' projection onto the constraints failed (" +
                           status.describe() + ")");
    algebraic_.zero_algebraic(step.get());
    CATENA_PETSC(VecAXPY(q, 1.0, step.get()));
  }
}

double project_initial_velocity(assembly::SecondOrderSystem& system, double t, Vec q, Vec v) {
  if (!system.has_constraints()) return 0.0;
  // At rest with scleronomic constraints (every catenary start): nothing to project, and no
  // factorisation spent on finding that out.
  PetscReal speed = 0.0, target = 0.0;
  CATENA_PETSC(VecNorm(v, NORM_INFINITY, &speed));
  {
    VecHandle beta = system.create_vector();
    system.constraint_velocity({q, nullptr, {}, t}, beta.get());
    CATENA_PETSC(VecNorm(beta.get(), NORM_INFINITY, &target));
  }
  if (speed == 0.0 && target == 0.0) return 0.0;
  MatHandle mass = system.create_matrix();
  system.jacobian({q, nullptr, {}}, {0.0, 0.0, 1.0}, mass.get());
  return AccelerationSolver(system, mass.get()).project_velocity(t, q, v);
}

void consistent_acceleration(assembly::SecondOrderSystem& system, Mat mass, double t, Vec q, Vec v,
                             Vec a) {
  AccelerationSolver(system, mass).solve(t, q, v, a);
}

}  // namespace catena::solvers

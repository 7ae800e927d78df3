#pragma once
// The acceleration consistent with a state: M a = −f(t, q, v). Needed to start HHT (whose
// recurrence carries a) and to predict the first IRK stages.
//
// With constraints (Lagrange multipliers) it is the acceleration-level system
//   [M  Gᵀ] [a]   [−f(t, q, v)]
//   [G  0 ] [λ] = [ ü(t)       ]     (G a = ü: the constraints are linear in q),
// which also gives the multipliers consistent with the state. Both matrices are
// constant, so AccelerationSolver factors once and solves many times.
#include <petscmat.h>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/algebraic_part.hpp"

namespace catena::solvers {

class AccelerationSolver {
 public:
  // Collective. Factors M (Cholesky, options prefix -mass_) or, with constraints, the
  // saddle-point matrix above (LU). Throws NumericalError if it is singular (a free DOF
  // without mass, or redundant constraints), naming the likely cause.
  AccelerationSolver(assembly::SecondOrderSystem& system, Mat mass);
  // Collective. a at (t, q, v). With constraints it also writes λ into the multiplier
  // slots of q (their previous value is ignored) and leaves a's multiplier slots zero.
  void solve(double t, Vec q, Vec v, Vec a);

 private:
  assembly::SecondOrderSystem& system_;
  AlgebraicPart algebraic_;
  MatHandle saddle_;
  KspHandle ksp_;
  VecHandle rhs_, target_;
};

// Collective. One-off AccelerationSolver(system, mass).solve(t, q, v, a).
void consistent_acceleration(assembly::SecondOrderSystem& system, Mat mass, double t, Vec q, Vec v,
                             Vec a);

}  // namespace catena::solvers

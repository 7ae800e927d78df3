#pragma once
// The acceleration consistent with a state: M a = −f(t, q, v). Needed to start HHT (whose
// recurrence carries a) and to predict the first IRK stages.
//
// With constraints (Lagrange multipliers) it is the acceleration-level system
//   [M  Gᵀ] [a]   [−f(t, q, v)]
//   [G  0 ] [λ] = [ γ(q, v, t) ]     (G a = γ: couplings/constraint_coupling.hpp),
// which also gives the multipliers consistent with the state. Where the constraints are
// linear, both matrices are constant and AccelerationSolver factors once and solves many
// times; a rigid body's frame makes G depend on q, and each solve factors at its state.
#include <petscmat.h>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/algebraic_part.hpp"

namespace catena::solvers {

class AccelerationSolver {
 public:
  // Collective. Factors M (LU without pivoting: PETSc's on one rank, the interface split
  // on more; options prefix -mass_) or, with constraints, the saddle-point matrix above
  // (MUMPS LU). Throws NumericalError if it is singular (a free DOF
  // without mass, or redundant constraints), naming the likely cause.
  AccelerationSolver(assembly::SecondOrderSystem& system, Mat mass);
  // Collective. a at (t, q, v). With constraints it also writes λ into the multiplier
  // slots of q (their previous value is ignored) and leaves a's multiplier slots zero.
  void solve(double t, Vec q, Vec v, Vec a);
  // Collective. Projects v onto the velocities the constraints allow at (t, q): the v′
  // nearest to v in the kinetic-energy norm with G v′ = β(t) (a prescribed motion's
  // velocity; 0 for the others),
  //   [M  Gᵀ] [v′]   [M v]
  //   [G  0 ] [μ ] = [β  ],
  // as an impulse through the joints would (the mass-weighted least change). v's
  // multiplier slots stay zero. Returns max |v′ − v| over the nodal slots.
  double project_velocity(double t, Vec q, Vec v);
  // Collective. Moves q onto the positions the constraints allow at t, g(q′, t) = 0, by
  // Newton steps towards the q′ nearest to q in the kinetic-energy norm,
  //   [M  Gᵀ] [Δq]   [   0    ]
  //   [G  0 ] [μ ] = [−g(q, t)],   q ← q + Δq,
  // until max |g| ≤ tolerance (units of g: metres for a node's constraint, 1 for a body
  // frame's). One step is exact for linear constraints. q's multiplier slots are zeroed.
  // Returns the steps taken, or −1 if max_steps did not reach the tolerance.
  int project_position(double t, Vec q, double tolerance, int max_steps);
  // Not collective. Factorisations so far (one, or one per state with nonlinear G).
  long factorizations() const { return factorizations_; }

 private:
  assembly::SecondOrderSystem& system_;
  AlgebraicPart algebraic_;
  MatHandle saddle_;
  Mat mass_;
  KspHandle ksp_;
  VecHandle rhs_, target_;
  long factorizations_ = 0;
  // Nonlinear G: the state of the last factorisation (q with zero multiplier slots, t).
  VecHandle factored_q_;
  double factored_t_ = 0.0;

  // Collective. Factors M, or the saddle-point matrix with G at (q, t) (not again at the
  // state of the last factorisation); throws if singular.
  void factor(Vec q, double t);
};

// Collective. One-off AccelerationSolver(system, M).project_velocity(t, q, v), M assembled
// here; 0 without constraints.
double project_initial_velocity(assembly::SecondOrderSystem& system, double t, Vec q, Vec v);

// Collective. One-off AccelerationSolver(system, mass).solve(t, q, v, a).
void consistent_acceleration(assembly::SecondOrderSystem& system, Mat mass, double t, Vec q, Vec v,
                             Vec a);

}  // namespace catena::solvers

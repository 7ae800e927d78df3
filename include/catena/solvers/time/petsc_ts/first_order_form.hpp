#pragma once
// The second-order system M a + f(t, q, v) = 0 written as a first-order implicit ODE for
// PETSc TS (petsc_ts_integrator.hpp), with state U = [q; v]:
//
//   G(t, U, U̇) = [ q̇ − v            ]          ∂G/∂U + σ ∂G/∂U̇ = [ σI     −I     ]
//                [ M v̇ + f(t, q, v) ] = 0,                       [ K    C + σM   ]
//
// (K = ∂f/∂q, C = ∂f/∂v, σ the TS shift). The q rows carry units of velocity, the v rows
// of force; Newton satisfies the (linear) q rows to round-off at its first iteration.
//
// Layout: DOF-major interleaving, entry 2g = q_g and 2g + 1 = v_g for free DOF g, so each
// rank owns rows 2·[first, last) of its own DOFs and the bandwidth doubles instead of
// growing by n (MUMPS's fill stays that of the n×n pattern, times four). The same idea as
// BlockMatrix (block_matrix.hpp) specialised to this 2×2 structure.
#include <petscmat.h>

#include <vector>

#include "catena/assembly/petsc_handle.hpp"

namespace catena::solvers {

class FirstOrderForm {
 public:
  // Collective. K, C, M: assembled n×n MPIAIJ matrices of the system (their nonzero
  // patterns are merged, the diagonal added, so the 2n×2n matrix is preallocated exactly
  // for whatever later assemblies of K, C and M insert).
  FirstOrderForm(Mat K, Mat C, Mat M);

  Mat matrix() const { return B_.get(); }
  // Collective. [σI, −I; K, C + σM] into matrix() (pattern fixed, so MUMPS's symbolic
  // analysis is reused across assemblies).
  void assemble(double sigma, Mat K, Mat C, Mat M);

  // Collective. A 2n vector laid out as matrix()'s rows.
  VecHandle create_vector() const;
  // Not collective. Copies between U = [q; v] (interleaved) and the n-vectors q, v (owned
  // entries only; either may be null in split).
  void split(Vec U, Vec q, Vec v) const;
  void join(Vec q, Vec v, Vec U) const;

 private:
  PetscInt first_ = 0, n_owned_ = 0;
  // Per owned DOF row: the merged, sorted column list of K, C and M (global n-indices).
  std::vector<std::vector<PetscInt>> columns_;
  MatHandle B_;
};

}  // namespace catena::solvers

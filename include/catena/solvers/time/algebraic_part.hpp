#pragma once
// The algebraic part of the constrained equations of motion, as integrators see it.
//
// With Lagrange multipliers the system (assembly/second_order_system.hpp) is the index-3
// DAE  M a + f(t, q, v) + Gᵀλ = 0,  g(q, t) = 0. The integrators keep one vector layout:
// the multiplier slots of q hold λ, those of v and a are zero, and the Newton unknown's
// multiplier slots hold λ itself (at the step end for HHT, at each stage for implicit
// Runge–Kutta) where its nodal slots hold accelerations — or, for the multistep methods,
// whose unknown is a correction δ to predicted positions, a correction to the predicted λ.
// Integrators never look inside the slots: this class gives them the few operations they need, and
// does nothing (at no cost) when the scene has no constraints.
//
// Scaling (Negrut, Rampalli, Ottarsson & Sajdak, J. Comput. Nonlinear Dyn. 2 (2007)
// 73–85): the constraint rows g(q) (metres) are multiplied by m̄/c, where c is the
// coefficient of the unknown acceleration in q (βh² for HHT, h² for a stage) and m̄ the
// mean diagonal of M; the rows then read m̄·G in Newton's matrix, of the size of the
// mass entries beside them, and the residual is in newtons like the rest.
#include <petscmat.h>

#include <functional>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/assembly/second_order_system.hpp"

namespace catena::solvers {

class AlgebraicPart {
 public:
  // Collective. mass: the system's mass matrix (for m̄).
  AlgebraicPart(assembly::SecondOrderSystem& system, Mat mass);

  bool active() const { return active_; }
  // m̄: mean of M's diagonal over the nodal DOFs (kg).
  double mass_scale() const { return mass_scale_; }
  // 1 in the multiplier slots (null when inactive).
  Vec mask() const { return mask_.get(); }

  // Collective. target's multiplier slots ← source's (nodal slots unchanged).
  void take_algebraic(Vec target, Vec source) const;
  // Collective. Zeroes the multiplier slots.
  void zero_algebraic(Vec x) const;
  // Collective. Multiplies the multiplier entries of r by factor.
  void scale_rows(Vec r, double factor) const;
  // Collective. The round-off floor of the scaled constraint rows, (m̄/c)·|g| with g
  // evaluated in floating point: 8 ε max|q| per row, times √rows. Newton tolerances below
  // it cannot be met (0 when inactive).
  double residual_floor(double coefficient, Vec q) const;
  // The Newton convergence measure for a residual whose constraint rows carry the floor
  // above: √(‖F_nodal‖² + (w ‖F_constraint‖)²), w = atol / (atol + floor), so that a
  // solve to ‖F‖ ≤ atol leaves the force rows within atol and the constraint rows within
  // atol + floor. A plain ‖F‖₂ ≤ atol + floor would let the force rows stop at the floor,
  // which grows like 1/h²: on a mechanism of light bodies (Andrews' squeezer, inertias of
  // 1e-7 kg m²) at h = 2.5e-6 s that is 5e-5 N, and the positions came out ten times
  // less accurate than at h = 1e-5 s. `blocks`: entries per DOF (the IRK stage vector's
  // interleaved stages). Empty (the 2-norm) when inactive. Collective when called.
  std::function<double(Vec)> residual_measure(double atol, double floor, int blocks = 1) const;
  // Collective. Multiplies the multiplier rows of J (laid out like the system's vectors,
  // or `blocks` interleaved copies of it: the implicit Runge–Kutta stage matrix) by factor.
  void scale_rows(Mat J, double factor, int blocks = 1);

 private:
  bool active_ = false;
  double mass_scale_ = 1.0;
  VecHandle mask_;
  VecHandle row_scale_;  // per block count: cached diagonal for MatDiagonalScale
  int row_scale_blocks_ = 0;
  double row_scale_factor_ = 0.0;
};

}  // namespace catena::solvers

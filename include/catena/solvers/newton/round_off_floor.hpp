#pragma once
// The round-off floor of the residual of a stiff structure, for Newton tolerances.
//
// Element forces are differences of large numbers: an axial force EA·(|r_B − r_A|/L − 1)
// computed from positions |r| ~ 10⁴ m over L = 0.25 m elements carries an error of about
// ε·EA·|r|/L per element, i.e. ε·K_ii·|q_i| per DOF with K_ii ≈ 2EA/L the tangent's
// diagonal. Summed over the DOFs, ‖f‖ cannot be computed more accurately than
//   floor = 2 ε ‖diag(K) ∘ q‖₂,
// measured at 0.027 N on the 10 km benchmark line (docs/performance.md), where the
// default tolerance 1e-8 N made every attempt fail. Integrators add this floor to their
// Newton tolerance; on small or soft models it is far below it and changes nothing.
// diag(K) is kept from the last tangent, q is the current state (so a decaying solution
// keeps a decaying floor).
#include <petscmat.h>

#include "catena/assembly/petsc_handle.hpp"

namespace catena::solvers {

class RoundOffFloor {
 public:
  // Collective. Keeps diag(K) (K the tangent ∂f/∂q just evaluated).
  void set_tangent(Mat K);
  bool known() const { return diagonal_.get() != nullptr; }
  // Collective. 2 ε ‖diag(K) ∘ q‖₂ (0 before set_tangent).
  double at(Vec q);

 private:
  VecHandle diagonal_, work_;
};

}  // namespace catena::solvers

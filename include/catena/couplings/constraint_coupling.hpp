#pragma once
// What every constraint coupling (the Lagrange multipliers λ of model constraint `index`,
// one per equation, and the nodal unknowns its g(q, t) = 0 reads) tells the system besides its
// residual and matrix: whether g is linear in q, and the right-hand side of the
// acceleration-level constraint
//   d²g/dt² = G a + γ̃(q, v, t) = 0   ⇒   G a = γ(q, v, t) = −γ̃,
// which the consistent initial acceleration (solvers/time/consistent_acceleration.hpp)
// solves with the equations of motion. A linear constraint's γ is −∂²g/∂t² (a prescribed
// motion's acceleration); a quadratic one's is −vᵀ H v per row (H = ∂²g/∂q², constant).
//
// Over its dofs() — the three multipliers first, then the nodal unknowns — a constraint adds
// Gᵀλ to the nodal rows and g to the multiplier rows; its matrix is
//   c_K Σ_k λ_k H_k  (nodal block; zero when g is linear)  + c_λ Gᵀ + c_g G.
#include <algorithm>
#include <span>

#include "catena/couplings/coupling.hpp"

namespace catena::couplings {

class ConstraintCoupling : public Coupling {
 public:
  explicit ConstraintCoupling(int index) : index_(index) {}

  // Index into model.constraints.
  int index() const { return index_; }
  // False if G depends on q or t (SecondOrderSystem::constraints_linear() is then false on
  // every rank, and the integrators re-evaluate Gᵀ with the tangent).
  virtual bool linear() const = 0;
  // γ at the state s (its active DOFs, as evaluate() sees them: all of dofs() but for a
  // slider's; multiplier slots first, their values ignored), one per multiplier into `out`.
  virtual void acceleration_target(const CouplingState& s, std::span<double> out) const = 0;
  // β of the velocity-level constraint G v = β = −∂g/∂t at s.t, one per multiplier: zero
  // unless the constraint moves with time (a prescribed motion's velocity).
  virtual void velocity_target(const CouplingState& s, std::span<double> out) const;

  bool dense() const override { return false; }
  // Its nodes may be unknowns of a local patch, but the multipliers never are.
  PatchRole patch_role() const override { return PatchRole::excluded; }

 private:
  int index_;
};

inline void ConstraintCoupling::velocity_target(const CouplingState&, std::span<double> out) const {
  std::fill(out.begin(), out.end(), 0.0);
}

}  // namespace catena::couplings

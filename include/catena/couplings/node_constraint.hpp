#pragma once
// A kinematic constraint on node positions enforced by three Lagrange multipliers λ
// (model::Constraint): g(q, t) = r_A − target = 0, with target r_B (coincident), X_A
// (pinned) or X_A + u(t) (prescribed). Over its DOFs [λ (3), r_A (3), r_B (3, coincident)]
// it adds Gᵀλ to the nodal rows (+λ on A, −λ on B) and g to the multiplier rows, in metres.
// G is constant (g is linear in q), so its matrix is c_λ Gᵀ + c_g G, and it keeps a zero
// on the multiplier diagonal (the slot a direct solver pivots across).
#include <vector>

#include "catena/core/vec3.hpp"
#include "catena/couplings/constraint_coupling.hpp"
#include "catena/model/model.hpp"

namespace catena::couplings {

class NodeConstraint final : public ConstraintCoupling {
 public:
  // `index`: into model.constraints (coincident, pinned or prescribed).
  NodeConstraint(const model::Model& model, int index);

  void pattern(std::vector<std::pair<int, int>>& entries) const override;
  void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                Scratch& scratch) const override;

  bool linear() const override { return true; }
  // ∂²u/∂t² of a prescribed motion at s.t (zero for the others).
  void acceleration_target(const CouplingState& s, std::span<double> out) const override;
  // u̇ of a prescribed motion at s.t (zero for the others).
  void velocity_target(const CouplingState& s, std::span<double> out) const override;

 private:
  model::Constraint constraint_;
  Vec3 reference_a_;  // X_A
};

}  // namespace catena::couplings

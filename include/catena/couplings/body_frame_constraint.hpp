#pragma once
// The constraints that keep a rigid body's axes e1, e2, e3 (the 9 axis unknowns of its
// node, model::RigidBody) orthonormal, three multipliers each (model::ConstraintType):
//   frame_lengths:  g_k = ½(e_k·e_k − 1)                 G: row k holds e_kᵀ at e_k
//   frame_angles:   g_k = e_i·e_j, (i, j) = (2,3), (3,1), (1,2) for k = 1, 2, 3
//                                                        G: row k holds e_jᵀ at e_i, e_iᵀ at e_j
// Quadratic in q, so G depends on q and Gᵀλ has the constant second derivatives
//   frame_lengths:  ∂(Gᵀλ)/∂e_k = λ_k I            frame_angles: ∂(Gᵀλ)_{e_i}/∂e_j = λ_k I
// (the c_K part of its matrix), and the acceleration-level constraint G a = γ has
//   frame_lengths:  γ_k = −ė_k·ė_k                 frame_angles: γ_k = −2 ė_i·ė_j.
// Over its DOFs [λ (3), e1 (3), e2 (3), e3 (3)].
#include <vector>

#include "catena/couplings/constraint_coupling.hpp"
#include "catena/model/model.hpp"

namespace catena::couplings {

class BodyFrameConstraint final : public ConstraintCoupling {
 public:
  // `index`: into model.constraints, of type frame_lengths or frame_angles.
  BodyFrameConstraint(const model::Model& model, int index);

  void pattern(std::vector<std::pair<int, int>>& entries) const override;
  void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                Scratch& scratch) const override;
  bool linear() const override { return false; }
  void acceleration_target(const CouplingState& s, std::span<double> out) const override;

 private:
  // Row k's axes (0-based): (k, k) for the lengths, (i, j) for the angles.
  std::array<std::pair<int, int>, 3> axes_;
  bool lengths_;
};

}  // namespace catena::couplings

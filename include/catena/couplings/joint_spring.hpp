#pragma once
// A spring, a dashpot, a constant actuator and dry friction on a revolute or prismatic
// joint's coordinate ξ (model::Joint). The spring's potential ½ k (ξ − ξ₀)², the work of the
// actuator F and of the dashpot c, capped by the limit L, and the friction μ give the
// generalised force on ξ (sign convention f = f_int + f_damp − f_ext)
//   φ(ξ, ξ̇, t) = P(u) + g(ξ̇),   u = k (ξ − ξ₀(t)) + c (ξ̇ − ξ̇₀(t)) − F,
//   P(u) = L tanh(u/L) (u without a limit),   g(ξ̇) = μ ξ̇/√(ξ̇² + w²)  (w the stick speed),
// with ξ₀(t) = neutral + velocity·t + amplitude·sin(2π frequency t) (a moving neutral makes
// the spring and dashpot a position servo with gains k and c), and
//   f = φ ∂ξ/∂q,          ξ̇ = ∂ξ/∂q · v,
//   K = ∂f/∂q = φ ∂²ξ/∂q² + k_t ∂ξ/∂q ∂ξ/∂qᵀ + c_t ∂ξ/∂q (∂²ξ/∂q² v)ᵀ,
//   C = ∂f/∂v = c_t ∂ξ/∂q ∂ξ/∂qᵀ,
// k_t = ∂φ/∂ξ = P'(u) k and c_t = ∂φ/∂ξ̇ = P'(u) c + g'(ξ̇), P' = 1 − tanh²(u/L), g' = μ w²/
// (ξ̇² + w²)^{3/2},
// with ∂ξ/∂q and ∂²ξ/∂q² exact by forward-mode differentiation (elements/dual.hpp). Over the
// DOFs [body A's node (12), body B's node (12)] (B the ground: A's only). The coordinates,
// in the joint's reference frame (u its axis, n₁ ⊥ u, n₂ = u × n₁, each carried by its side):
//   revolute   ξ = atan2((n₁_B × n₁_A)·u_B, n₁_A·n₁_B), the rotation of A relative to B about
//              u, in (−π, π] (the spring acts on ξ − ξ₀ taken the short way round: within half a
//              turn of its neutral)
//   prismatic  ξ = (p_A − p_B)·u_B, A's slide along u relative to B.
#include <vector>

#include "catena/couplings/coupling.hpp"
#include "catena/model/model.hpp"

namespace catena::couplings {

class JointSpring final : public Coupling {
 public:
  // `joint`: into model.joints, a revolute or prismatic joint with has_coordinate_force().
  JointSpring(const model::Model& model, int joint);

  void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                Scratch& scratch) const override;
  bool has_damping() const override { return damping_ != 0.0 || friction_ != 0.0; }
  bool in_force_scale() const override { return true; }
  // The bodies' nodes belong to their frame constraints, which patches leave out.
  PatchRole patch_role() const override { return PatchRole::excluded; }

  // ξ at the state q (dofs() order), for output and tests.
  double coordinate(std::span<const double> q) const;

 private:
  model::JointType type_;
  double stiffness_, damping_, neutral_, actuator_;
  double neutral_velocity_, neutral_amplitude_, neutral_frequency_;  // the moving neutral
  double limit_, friction_, stick_speed_;
  int n_ = 12;  // 12 (to ground) or 24
  // Body coordinates of the joint frame's vectors and point on each side (the ground's
  // are global constants: `ground_*`).
  Vec3 point_a_, point_b_, axis_b_, n1_a_, n1_b_;
  Vec3 ground_point_, ground_axis_, ground_n1_;
  bool to_ground_ = true;
};

}  // namespace catena::couplings

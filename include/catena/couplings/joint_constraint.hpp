#pragma once
// A joint (model::Joint) as a constraint: one multiplier per equation, over the DOFs
// [λ (n), body A's node (12: r, e1, e2, e3), then body B's node (12) or a node's position
// (3), or nothing for the ground].
//
// In natural coordinates every point and direction fixed in a body is linear in its node's
// unknowns: the point with body coordinates ξ is r + ξ_k e_k, the direction with body
// components a is a_k e_k (model::RigidBody). Each equation is then one of two forms in
// such expressions x, y (affine in q, constant on the ground side):
//   component   g = (x_A − x_B)_d                 linear: G constant, no Hessian
//   dot         g = x · y                         G = [w_j y + v_j x]_j,
//                                                 ∂(Gᵀλ)/∂q: λ (w_j v_k + v_j w_k) I₃,
//                                                 γ = −2 ẋ·ẏ
// with x = Σ_j w_j q_j + x₀, y = Σ_j v_j q_j + y₀ over the 3-vector blocks q_j of the
// nodal DOFs. Per type (X the joint point, u the axis, n₁ ⊥ u, n₂ = u × n₁, all in the
// reference configuration, each carried by the body it is fixed in):
//   spherical    p_A − p_B = 0                                           (3 components)
//   revolute     + u_A·n₁_B = 0, u_A·n₂_B = 0                            (+2 dots)
//   cylindrical  u_A·n₁_B, u_A·n₂_B, (p_A − p_B)·n₁_B, (p_A − p_B)·n₂_B  (4 dots)
//   prismatic    cylindrical's + n₁_A·n₂_B = 0                          (5 dots)
//   fixed        spherical's + u_A·n₁_B, u_A·n₂_B, n₁_A·n₂_B            (3 + 3)
// (García de Jalón & Bayo 1994, ch. 2: the constraints of natural coordinates are linear or
// quadratic.) The first three multipliers of a spherical, revolute or fixed joint are the
// force on A at the point, with a minus sign (as a node constraint's).
#include <vector>

#include "catena/core/vec3.hpp"
#include "catena/couplings/constraint_coupling.hpp"
#include "catena/model/model.hpp"

namespace catena::couplings {

class JointConstraint final : public ConstraintCoupling {
 public:
  // `index`: into model.constraints, of type joint.
  JointConstraint(const model::Model& model, int index);

  bool dense() const override { return true; }
  void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                Scratch& scratch) const override;
  bool linear() const override;
  void acceleration_target(const CouplingState& s, std::span<double> out) const override;
  void velocity_target(const CouplingState& s, std::span<double> out) const override;

  // A point or direction as an affine function of the nodal blocks: Σ_j w[j] q_j + constant.
  struct Affine {
    std::vector<double> w;  // one weight per nodal block
    Vec3 constant = Vec3::Zero();
  };
  // One term of multiplier `row`'s equation, times the weight `weight` names (0: one; 1, 2:
  // the prescribed motion's c₁(t), c₂(t) below).
  struct Equation {
    bool dot = false;  // false: component `d` of x; true: x · y
    int d = 0;
    Affine x, y;
    int row = 0;
    int weight = 0;
  };
  const std::vector<Equation>& equations() const { return equations_; }
  // n₁ of a joint with axis u (unit): the unit vector ⊥ u that both a joint's equations and
  // its spring (joint_spring.hpp) measure from.
  static Vec3 normal(const Vec3& u);
  // Multipliers (equations).
  int rows() const { return rows_; }

 private:
  std::vector<Equation> equations_;
  int rows_ = 0;
  int blocks_ = 0;  // nodal 3-vector blocks (4 per body, 1 for a node)
  // A prescribed motion of the coordinate, ξ_p(t) = v t + A sin(2πft), as the last equation:
  //   revolute   g = cos ξ_p (n₁_A·n₂_B) − sin ξ_p (n₁_A·n₁_B) = sin(ξ − ξ_p)
  //   prismatic  g = (p_A − p_B)·u_B − ξ_p
  enum class Drive { none, angle, slide };
  Drive drive_ = Drive::none;
  double velocity_ = 0.0, amplitude_ = 0.0, frequency_ = 0.0;
  // The weights (1, c₁, c₂) and the offset ξ_p of the driven row, with their first and second
  // time derivatives.
  struct Weights {
    double c[3] = {1, 0, 0}, c_t[3] = {0, 0, 0}, c_tt[3] = {0, 0, 0};
    double offset = 0.0, offset_t = 0.0, offset_tt = 0.0;
  };
  Weights weights(double t) const;

  // x at the state (nodal part of q, after the multipliers).
  Vec3 value(const Affine& a, std::span<const double> nodal) const;
};

}  // namespace catena::couplings

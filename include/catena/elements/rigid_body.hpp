#pragma once
// The inertia and weight of a rigid body in natural coordinates (model::RigidBody): one
// node whose 12 unknowns are a body point r and the body's axes e1, e2, e3 (global
// components), so that the body point with body coordinates ξ is at x = r + ξ_k e_k.
//
// The kinetic energy ½∫ρ|ẋ|² dV is then a constant quadratic form in (ṙ, ė1, ė2, ė3)
// (García de Jalón & Bayo, "Kinematic and Dynamic Simulation of Multibody Systems",
// Springer 1994, ch. 3):
//   M = M̂ ⊗ I3,  M̂ = [ m    m ξcᵀ ]      ξc: centre of mass from r (body coordinates)
//                    [ m ξc  J    ]      J = ∫ρ ξ ξᵀ dV = ½ tr(I_c) 1 − I_c + m ξc ξcᵀ
// with I_c the inertia tensor about the centre of mass in body axes. Gravity's potential
// −g·∫ρ x dV = −g·(m r + m ξc_k e_k) gives the constant force f = −λ_path (m g, m ξc_k g).
// No stiffness, no damping: the body's nonlinearity is all in the constraints that keep
// its axes orthonormal (couplings/body_frame_constraint.hpp).
#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::elements {

class RigidBodyInertia final : public Element {
 public:
  // mass > 0 [kg], centre_of_mass [m] and inertia [kg·m²] about it, both in body axes;
  // gravity [m/s²]. The inertia must be a physical body's (positive principal moments that
  // satisfy the triangle inequalities strictly), else M is singular (checked by the reader).
  RigidBodyInertia(double mass, const Vec3& centre_of_mass, const Mat3& inertia,
                   const Vec3& gravity);
  int n_nodes() const override { return 1; }
  int dofs_per_node() const override { return 12; }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return false; }
  void mass(double* M) const override;
  SectionResult section_result(const LocalState&) const override { return {}; }

  // M̂ (4 × 4): the coefficients of M = M̂ ⊗ I3.
  const Eigen::Matrix4d& coefficients() const { return coefficients_; }

 private:
  Eigen::Matrix4d coefficients_;
  Vec3 gravity_;
};

}  // namespace catena::elements

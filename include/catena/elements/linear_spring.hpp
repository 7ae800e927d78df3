#pragma once
// Linear springs and dashpots acting per global axis, without preload:
//   LinearSpring (two nodes):  f_B = k∘((x_B − x_A) − (X_B − X_A)) + c∘(v_B − v_A), f_A = −f_B
//   GroundSpring (one node):   f   = k∘(x − X) + c∘v                (elastic support)
// X are reference positions; ∘ is the component-wise product. Being axis-aligned they are
// small-rotation models (pads, bearings, support flexibility), not rotation invariant.
// Units: k [N/m], c [N·s/m]. Local DOFs: positions only, node-major.
#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::elements {

struct SpringSection {
  Vec3 stiffness = Vec3::Zero();
  Vec3 damping = Vec3::Zero();
};

class LinearSpring final : public Element {
 public:
  LinearSpring(const Vec3& reference_a, const Vec3& reference_b, const SpringSection& section);
  int n_nodes() const override { return 2; }
  int dofs_per_node() const override { return 3; }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return !section_.damping.isZero(0.0); }
  void mass(double* M) const override;
  SectionResult section_result(const LocalState& s) const override;

 private:
  Vec3 reference_offset_;
  SpringSection section_;
};

class GroundSpring final : public Element {
 public:
  GroundSpring(const Vec3& reference, const SpringSection& section);
  int n_nodes() const override { return 1; }
  int dofs_per_node() const override { return 3; }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return !section_.damping.isZero(0.0); }
  void mass(double* M) const override;
  SectionResult section_result(const LocalState& s) const override;

 private:
  Vec3 reference_;
  SpringSection section_;
};

}  // namespace catena::elements

#pragma once
// A node against a rigid plane: a unilateral penalty contact with viscous damping and
// regularised Coulomb friction (the contact of seed 000's crane pipe with the ground, a
// cable laid on a floor). With g = (x − p)·n the gap to the plane (p a point of it, n its
// unit normal, towards the free side) and ġ = v·n its rate, the plane pushes with
//   N = −k g − c ġ          where g < 0 and the sum is positive (no pull: 0 otherwise),
//   F = N n − μ N v_t/√(|v_t|² + w²),   v_t = v − (v·n) n,
// the friction term opposing the sliding velocity v_t, regularised over the stick speed w
// as a slider's Coulomb friction is (docs/formulation.md). The kernel's force is f = −F
// (f = f_int + f_damp − f_ext), and where N > 0
//   K = ∂f/∂x = k (n − μ φ) nᵀ,
//   C = ∂f/∂v = c (n − μ φ) nᵀ + μ N (I/s − v_t v_tᵀ/s³)(I − n nᵀ),
// φ = v_t/s, s = √(|v_t|² + w²). The contact switches where N crosses 0, a kink the
// integrators meet as they meet the pantograph's loss of contact. Local DOFs: the node's
// position (3).
#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::elements {

struct SurfaceContactLaw {
  Vec3 point = Vec3::Zero();    // m, a point of the plane
  Vec3 normal = Vec3::UnitZ();  // unit, towards the side the node is free on
  double stiffness = 0.0;       // N/m, k > 0
  double damping = 0.0;         // N·s/m, c ≥ 0, in contact only
  double friction = 0.0;        // μ ≥ 0
  double stick_speed = 1e-3;    // m/s, w > 0
};

class SurfaceContact final : public Element {
 public:
  explicit SurfaceContact(const SurfaceContactLaw& law);
  int n_nodes() const override { return 1; }
  int dofs_per_node() const override { return 3; }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return law_.damping > 0.0 || law_.friction > 0.0; }
  void mass(double* M) const override;
  SectionResult section_result(const LocalState& s) const override;

  // Not collective. The normal force N ≥ 0 (N) at the node's position x and velocity v (v
  // empty: at rest), for output and tests.
  double normal_force(std::span<const double> x, std::span<const double> v) const;

 private:
  SurfaceContactLaw law_;
};

}  // namespace catena::elements

#pragma once
// The end of a line cut from a longer one (model::AbsorbingEnd): what the rest of the line
// would do to the cut end, to first order about the run's initial state. A semi-infinite
// tensioned cable pulls its end with the initial end force F₀ and answers the end's
// velocity as a dashpot of its wave impedances (the force that a wave travelling away
// from the end needs at it), so that waves arriving from the model leave it instead of
// being reflected:
//   f = C v − F₀,   C = Z_a t tᵀ + Z_t (I − t tᵀ),
//   Z_a = √(EA m'),  Z_t = √(T m' / λ),  T = |F₀|,  t = F₀ / T,  λ = 1 + T/EA,
// with m' the mass per unstretched length and λ the stretch (a transverse wave runs at
// √(T/(λ m')) in unstretched length). Exact for the axial and transverse waves of a taut
// string; a wire's bending stiffness makes short waves dispersive, which the dashpot does not
// match (docs/formulation.md, "Absorbing ends"). K = 0: the rest of the line adds no
// stiffness to first order beyond what the dashpot gives. The end's slope r_x is held by
// the constant generalised force G₀ the rest of the structure put on it at the start (zero
// where the static start left the slope free; a catenary window's ends hold it where the
// line has it: apps/catena/window_statics.hpp), and is otherwise free.
// Units: N, N·s/m, N·m (G₀). Local DOFs: the node's position and slope [r, r_x].
#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::elements {

struct AbsorbingEndLaw {
  Vec3 force = Vec3::Zero();        // F₀, N: the force on the end node (the line beyond pulls)
  Mat3 damping = Mat3::Zero();      // C, N·s/m
  Vec3 slope_force = Vec3::Zero();  // G₀, N·m: on r_x (the line beyond holds the slope)
};

// The law of a cable end with end force `end_force` (pulling outwards: the line is in
// tension) and section EA (N), m' (kg per unstretched metre).
AbsorbingEndLaw cable_end_law(const Vec3& end_force, double EA, double mass_per_length);

class AbsorbingEnd final : public Element {
 public:
  explicit AbsorbingEnd(const AbsorbingEndLaw& law) : law_(law) {}
  int n_nodes() const override { return 1; }
  int dofs_per_node() const override { return 6; }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  // Always: the system asks once, at its construction, before the law is known.
  bool has_damping() const override { return true; }
  void mass(double* M) const override;
  SectionResult section_result(const LocalState&) const override { return {}; }
  const AbsorbingEndLaw& law() const { return law_; }

 private:
  AbsorbingEndLaw law_;
};

}  // namespace catena::elements

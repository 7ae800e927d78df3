#pragma once
// Two-node bar between node positions: droppers, stays, truss members.
//
//   local DOFs (6): [ x_A (3), x_B (3) ]
//   l = |x_B − x_A|, e = (x_B − x_A)/l, ε = l/l0 − 1,  N = EA ε + c·l̇
//   f_B = N e, f_A = −N e ; lumped mass μ·l0/2 per node; gravity on the lumped masses.
// Tension-only bars (slack droppers) carry N = 0 when l < l0, and then no damping force
// either. The switch is sharp: the Jacobian is that of the active branch (no
// regularisation), which Newton handles because the force is continuous at l = l0.
//
// A bar whose unstretched length l0 differs from its mesh length L (a dropper sized by
// shape finding) would be stretched in the reference configuration, where the static
// solver starts. Given L, the bar's unstretched length follows the static load path with
// the loads: l0(λ) = L + λ (l0 − L), λ = LoadPath::loads (docs/formulation.md), as the
// cables' prestrain does; dynamics runs at λ = 1. Mass and weight use l0 throughout.
//
// Units: EA [N], l0 [m], L [m], c [N·s/m], μ [kg/m].
#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::elements {

struct BarSection {
  double EA = 0.0;
  double mass_per_length = 0.0;
  double damping = 0.0;
  bool tension_only = false;
};

class TensionBar final : public Element {
 public:
  // mesh_length: L above; 0 = none (l0 at every point of the load path).
  TensionBar(double unstretched_length, const BarSection& section, const Vec3& gravity,
             double mesh_length = 0.0);

  int n_nodes() const override { return 2; }
  int dofs_per_node() const override { return 3; }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return section_.damping != 0.0; }
  void mass(double* M) const override;
  SectionResult section_result(const LocalState& s) const override;

 private:
  // Unstretched length at this point of the static load path.
  double unstretched_length(const LoadPath& path) const;

  double l0_;
  double mesh_length_;
  BarSection section_;
  Vec3 node_weight_;  // gravity force on each lumped node mass, N
};

}  // namespace catena::elements

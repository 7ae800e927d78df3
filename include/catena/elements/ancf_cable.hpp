#pragma once
// ANCF cable 3D, gradient-deficient (Gerstmayr & Shabana, Nonlinear Dyn. 45 (2006)
// 109–130; Berzeri & Shabana, J. Sound Vib. 235 (2000) 539–565).
//
//   local DOFs (12):  [ r_A (3), r_A,x (3), r_B (3), r_B,x (3) ]      node-major
//   r(x) = S1 r_A + S2 r_A,x + S3 r_B + S4 r_B,x ,   x ∈ [0, L] (mesh length),
//   S = cubic Hermite (elements/hermite.hpp).
//
// Strain energy per mesh length, with a = 1 + ε_p (ε_p along the static load path, see
// LocalState and path_prestrain;
// the unstretched element length is L/a), u = r', w = r'':
//   axial (Biot strain, exact for the elastic catenary):  ε = a|u| − 1,  ½ (EA/a) ε²
//   bending (CableSection::curvature, core/curvature_measure.hpp), ½ EI κ² per unit
//   unstretched length, with the arc lengths ds₀ = dx/a (unstretched), ds = |u| dx:
//     per reference length (default): κ₀ = a |u×w|/|u|²,  energy ½ (EI a) (p/g − c²/g²)
//     per deformed length:            κ = |u×w|/|u|³,     energy ½ (EI/a) (p/g² − c²/g³)
// with |u×w|² = (u·u)(w·w) − (u·w)² = gp − c² (g = u·u, p = w·w, c = u·w): smooth rational
// functions whose gradient and Hessian in (u, w) are closed form. The element vectors
// follow from u = Σ S'_i e_i, w = Σ S''_i e_i.
// Kelvin–Voigt axial damping: N = EA (ε + τ ε̇), objective (ε̇ = 0 under rigid motion).
// Quadrature: the axial strain (and its rate) is sampled at the Lobatto 3 points
// x = 0, L/2, L (Simpson weights), which avoids membrane locking in bending-dominated
// states of slender cables; bending uses 3 Gauss points (docs/formulation.md).
//
// Units: EA [N], EI [N·m²], mass_per_length [kg/m of unstretched length], τ [s],
// gravity [m/s²], distributed load [N/m of mesh length].
#include <array>

#include "catena/core/curvature_measure.hpp"
#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::elements {

struct CableSection {
  double EA = 0.0;
  double EI = 0.0;
  double mass_per_length = 0.0;
  double damping_time = 0.0;
  double prestrain = 0.0;  // ε_p: unstretched length = L / (1 + ε_p)
  // Slack in compression (a dropper cable): where the element's mean strain ε̄ (Simpson's
  // rule over its three axial points) is below −kSlackBand, its mean axial force is
  // kSlackStiffness·EA·ε̄, without damping; smoothed across |ε̄| < kSlackBand. The strain's
  // variation about ε̄ within the element stays elastic (ancf_cable.cpp).
  bool tension_only = false;
  // Along the static load path, ε_p is put on with the loads (ε_p·loads), not before them
  // (see LoadPath): a dropper's prestrain is its shape-found length, not a tension.
  bool prestrain_with_loads = false;
  CurvatureMeasure curvature = CurvatureMeasure::reference_length;  // the bending law
};

class AncfCable final : public Element {
 public:
  // `length` is the mesh (reference) length L > 0; reference slopes have |r_x| = 1.
  AncfCable(double length, const CableSection& section, const Vec3& gravity,
            const Vec3& distributed_load);

  int n_nodes() const override { return 2; }
  int dofs_per_node() const override { return 6; }
  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return section_.damping_time != 0.0; }
  void mass(double* M) const override;
  SectionResult section_result(const LocalState& s) const override;

  double length() const { return length_; }

  // Least prestrain held while the static load path puts the loads on (see LoadPath).
  static constexpr double kPathPrestrain = 1.0e-3;
  // Prestrain at a point of the load path: ε_t·p + r·(ε_p − ε_t), ε_t = max(ε_p, kPathPrestrain).
  static double path_prestrain(double prestrain, const LoadPath& path);
  // The section's prestrain at a point of the load path (path_prestrain, or ε_p·loads
  // when it is put on with the loads).
  static double section_prestrain(const CableSection& section, const LoadPath& path);

  // Axial stiffness left to a slack tension-only cable, as a fraction of EA. Not zero: a
  // slack dropper's interior nodes would have no stiffness along the dropper, and a static
  // solve with a slack dropper (elasticity) a singular matrix. Small enough that a slack
  // dropper stays straight: at 1e-6 a dropper of 1e5 N/m shortened by 10 cm pushes with
  // 10 mN, far below its Euler load (π²EI/l² ≈ 0.5 N for EI = 0.02 N·m², l = 0.6 m), and
  // below any force the contact-force statistics resolve (docs/catenary.md).
  static constexpr double kSlackStiffness = 1.0e-6;
  // Strain half-band over which the tension-only law is smoothed (C¹, see ancf_cable.cpp):
  // at ε = 0 a dropper of EA = 6e4 N carries EA·δ/4 = 0.3 N instead of 0.
  static constexpr double kSlackBand = 2.0e-5;

 private:
  double length_;
  CableSection section_;
  // μ_x g + q at full load, N/m of mesh length (a Vec3, not the four nodal blocks: the
  // residual's loop is bound by memory traffic on long lines, docs/performance.md).
  Vec3 load_;
};

}  // namespace catena::elements

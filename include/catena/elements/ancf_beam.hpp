#pragma once
// 3D ANCF beam with torsion: a Kirchhoff rod on the fully parameterised ANCF kinematics of
// Shabana & Yakoub (J. Mech. Des. 123 (2001) 606–613). Formulation, quadrature choices and
// their justification: docs/formulation_beam.md.
//
// Local DOFs (24), node-major, per node the full nodal layout [r, r_x, r_y, r_z]:
//
//     node A (x = 0)                          node B (x = L)
//   [ r_A  r_A,x  r_A,y  r_A,z |  r_B  r_B,x  r_B,y  r_B,z ]      (8 blocks of 3)
//      0    3      6      9       12   15     18     21          first local index
//
// Kinematics: centreline r_c(x) = cubic Hermite of (r, r_x) at both nodes (hermite.hpp),
// cross-section directors d_y(x), d_z(x) = linear interpolation of r_y, r_z;
// r(x, y, z) = r_c(x) + y d_y(x) + z d_z(x), x ∈ [0, L], L = |r_B − r_A| (reference chord).
//
// Strain measures (each minus its value in the reference configuration, which is stress
// free whatever its curvature), with t̂ = r_c'/|r_c'|:
//   axial      ε = |r_c'| − 1                                   Lobatto 3 (x = 0, L/2, L)
//   bending    k = r_c' × r_c'' / |r_c'|², κ_y = k·ê_y, κ_z = k·ê_z     Gauss, 3 points
//              (ê_y, ê_z: orthonormal section frame ⊥ t̂ built from the directors;
//              BeamSection::curvature = deformed_length divides by |r_c'|³ instead:
//              core/curvature_measure.hpp)
//   twist      κ_x = φ/L, φ = atan2(S, C) the nodal frames' relative angle about t̂:
//              S = ½ (d_y,B·d_z,A − d_z,B·d_y,A) (= L·½(d_y'·d_z − d_z'·d_y)),
//              C = ½ (d_y,A·d_y,B + d_z,A·d_z,B); constant, exact for uniform twist
//              (valid while the two nodal frames of an element differ by less than π)
//   nodes      γ_y = t̂·d_y, γ_z = t̂·d_z (Kirchhoff constraint),
//              s_1 = (|d_y|² − 1)/2, s_2 = (|d_z|² − 1)/2, s_3 = d_y·d_z (rigid section)
// Energy  ∫ ½[EA ε² + EI_y κ_y² + EI_z κ_z² + GJ κ_x²] dx
//       + Σ_nodes (L/2)·½[GA_y γ_y² + GA_z γ_z² + EA (s_1² + s_2² + s_3²)].
// Why these rules (docs/formulation_beam.md): every constraint-like term is sampled where
// the element can satisfy it exactly for any bent shape, with as many samples as the DOFs
// that can accommodate it, so nothing locks and nothing is left without stiffness:
//  - axial: ε at the nodes is |r_x| − 1 (one slope length per node) and at the midpoint
//    is set by the chord; Gauss sampling of ε² adds samples the cubic cannot satisfy
//    while it bends (membrane locking: Mattiasson errors grow with EA·L²/EI), 2-point
//    Gauss leaves a zero-energy slope-stretch mode; Simpson/Lobatto 3 has neither.
//  - directors: orthonormality and γ = 0 at the nodes fix the nodal frames up to the
//    roll about t̂, which the twist resists; at interior points they would lock
//    (linear interpolation of two rotated unit vectors is not unit).
// Bending is Euler–Bernoulli (curvature of the centreline); GA_y, GA_z only weight the
// director–tangent constraint, shear deformation is not modelled.
//
// Kelvin–Voigt damping on every strain e_i with stiffness k_i: the generalized stress is
// σ_i = k_i (e_i − e_i,ref + τ ė_i), ė_i = ∂e_i/∂q · v (objective by construction).
// Residual sign (element.hpp): f = f_int + f_damp − λ f_ext, f_ext = ∫ S_cᵀ(ρA g + q) dx,
// λ = LocalState::path.loads.
// K and C are exact: gradients and Hessians of the strain measures with respect to their
// local arguments come from forward-mode AD (dual.hpp), mapped to the DOFs by the (linear)
// shape functions.
#include <array>
#include <span>

#include "catena/core/curvature_measure.hpp"
#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::elements {

// Reference (mesh) data of a beam node. t, d_y, d_z: unit, mutually orthogonal,
// right-handed (t × d_y = d_z).
struct BeamNodeRef {
  Vec3 r = Vec3::Zero();     // m, position
  Vec3 t = Vec3::UnitX();    // −, centreline tangent ∂r/∂x
  Vec3 d_y = Vec3::UnitY();  // −, section y axis ∂r/∂y
  Vec3 d_z = Vec3::UnitZ();  // −, section z axis ∂r/∂z
};

// Section properties (the assembly layer converts model::BeamProps). Bending ABOUT the
// y axis (curvature in the x–z plane) is resisted by EI_y.
struct BeamSection {
  double EA = 0.0;                    // N, axial stiffness (also the section rigidity)
  double GA_y = 0.0, GA_z = 0.0;      // N, weights of the Kirchhoff constraints γ_y, γ_z
  double GJ = 0.0;                    // N·m², torsional stiffness
  double EI_y = 0.0, EI_z = 0.0;      // N·m², bending about the section y and z axes
  double mass_per_length = 0.0;       // kg/m, ρA
  double rho_Iy = 0.0, rho_Iz = 0.0;  // kg·m, ρ∫z² dA and ρ∫y² dA
  double damping_time = 0.0;          // s, Kelvin–Voigt τ on all strains
  CurvatureMeasure curvature = CurvatureMeasure::reference_length;  // the bending law
};

// Dead loads per unit reference length, scaled by LocalState::path.loads.
struct BeamLoads {
  Vec3 gravity = Vec3::Zero();      // m/s², acceleration of gravity
  Vec3 distributed = Vec3::Zero();  // N/m, distributed force
};

class AncfBeam final : public Element {
 public:
  static constexpr int kNodes = 2;
  static constexpr int kDofsPerNode = 12;
  static constexpr int kDofs = kNodes * kDofsPerNode;
  // Quadrature (fractions of L on [0, 1] in ancf_beam.cpp): Lobatto 3 for ε, Gauss for κ.
  static constexpr int kAxialPoints = 3;
  static constexpr int kBendingPoints = 3;

  AncfBeam(const BeamNodeRef& node_a, const BeamNodeRef& node_b, const BeamSection& section,
           const BeamLoads& loads);

  int n_nodes() const override { return kNodes; }
  int dofs_per_node() const override { return kDofsPerNode; }

  void evaluate(const LocalState& s, Request r, LocalOutput out) const override;
  bool has_damping() const override { return section_.damping_time != 0.0; }
  void mass(double* M) const override;
  // Axial force EA (ε + τ ε̇) [N] and ε [−] at x = L/2.
  SectionResult section_result(const LocalState& s) const override;

  // Elastic strain energy [J] at the state q (24 values); for tests and energy monitors.
  double strain_energy(std::span<const double> q) const;
  // The reference state [r, t, d_y, d_z] per node: stress free.
  const std::array<double, kDofs>& reference_state() const { return q_ref_; }
  double length() const { return length_; }

 private:
  // Strain samples: axial (1 per point), bending (2 per point), twist (1), nodes (5 each).
  static constexpr int kStrainSamples = kAxialPoints + 2 * kBendingPoints + 1 + 5 * kNodes;

  // Calls visit(map, weight, stiffnesses, first_sample, group) for every sampling point,
  // in the fixed order that indexes e_ref_ (ancf_beam.cpp).
  template <class Visitor>
  void for_each_point(Visitor&& visit) const;

  double length_;
  BeamSection section_;
  std::array<double, kDofs> q_ref_;
  std::array<double, kStrainSamples> e_ref_;  // reference strains (stress-free reference)
  std::array<double, kDofs> f_ext_;           // ∫ S_cᵀ (ρA g + q) dx, at load factor 1
  std::array<double, kDofs * kDofs> mass_;    // row-major
};

}  // namespace catena::elements

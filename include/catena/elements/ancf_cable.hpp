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
//   bending, exact curvature of the centre line:          κ² = |u×w|²/|u|⁶ ,  ½ (EI/a) κ²
// with |u×w|² = (u·u)(w·w) − (u·w)², so κ² = p/g² − c²/g³ (g = u·u, p = w·w, c = u·w): a
// smooth rational function whose gradient and Hessian in (u, w) are closed form. The
// element vectors follow from u = Σ S'_i e_i, w = Σ S''_i e_i.
// Kelvin–Voigt axial damping: N = EA (ε + τ ε̇), objective (ε̇ = 0 under rigid motion).
// Quadrature: the axial strain (and its rate) is sampled at the Lobatto 3 points
// x = 0, L/2, L (Simpson weights), which avoids membrane locking in bending-dominated
// states of slender cables; bending uses 3 Gauss points (docs/formulation.md).
//
// Units: EA [N], EI [N·m²], mass_per_length [kg/m of unstretched length], τ [s],
// gravity [m/s²], distributed load [N/m of mesh length].
#include <array>

#include "catena/core/vec3.hpp"
#include "catena/elements/element.hpp"

namespace catena::elements {

struct CableSection {
  double EA = 0.0;
  double EI = 0.0;
  double mass_per_length = 0.0;
  double damping_time = 0.0;
  double prestrain = 0.0;  // ε_p: unstretched length = L / (1 + ε_p)
};

class AncfCable final : public Element {
 public:
  // `length` is the mesh (reference) length L > 0; reference slopes have |r_x| = 1.
  AncfCable(double length, const CableSection& section, const Vec3& gravity,
            const Vec3& distributed_load);

  std::string_view kind() const override { return "ancf_cable"; }
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

 private:

  double length_;
  CableSection section_;
  // ∫ Sᵀ (μ_x g + q) dx at full load, per Hermite block (4 blocks of 3).
  std::array<Vec3, 4> external_force_;
};

}  // namespace catena::elements

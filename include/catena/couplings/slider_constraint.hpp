#pragma once
// A slider (model::Slider) as a constraint: its node's point r and its arc length s along a
// path of cable or beam elements, held together by
//   g(q) = r − r_path(s) = 0,   r_path(s) = Σ_b S_b(x(s)) q_b                 (3 equations)
// over the DOFs [λ (3), r (3), s, then every path node's r and r_x (6 each, ascending)], of
// which it acts on λ, r, s and the two nodes of the path element holding s (19 DOFs, chosen
// from the state: active_dofs_at).
// On the path element holding s, q_b are its blocks r_A, r_A,x, r_B, r_B,x and S_b the ANCF
// Hermite functions (elements/hermite.hpp) at x = s − start (L − (s − start) on an element
// walked backwards, model::element_reversed); σ = dx/ds = ±1. With t = ∂r_path/∂s = σ Σ S_b' q_b
// and κ = ∂²r_path/∂s² = Σ S_b'' q_b:
//   nodal rows (Gᵀλ):  r: λ     s: −t·λ + c ṡ     q_b: −S_b λ
//   G:                 [I, −t, −S_b I]
//   c_K block (∂(Gᵀλ)/∂q):  (s, s) −κ·λ,  (s, q_b) and (q_b, s) −σ S_b' λ
//   c_C block:              (s, s) c                (c: the slider's damping)
// Coulomb friction (model::Slider::friction μ, stick speed v) adds to the s row
//   F = μ n φ(ṡ),  n = |t × λ| = |t| |λ_⊥|,  φ(ṡ) = ṡ/√(ṡ² + v²)
// (λ_⊥: the multipliers' part across the path, the normal force; n is |t| times it, as the
// row's t·λ is |t| times the force along the path), whose derivatives go to the λ columns
// (c_λ μ φ ∂n/∂λ), the c_K block (through t: μ φ ∂n/∂t · ∂t/∂(s, q_b)) and the c_C block
// (c_C μ n φ'(ṡ)). φ is a smoothed sign: below v the force grows with the speed (a
// creep of ṡ = v φ/√(1 − φ²) where a load of φ times the friction limit pushes), above it
// the force is μ times the normal force to within (v/ṡ)²/2.
//   γ = 2 ṡ ṫ + ṡ² κ,  ṫ = σ Σ S_b' q̇_b      (G a = γ: the acceleration-level constraint)
// The s row says the multipliers' tangential part is the friction force; with c = 0 the path
// pushes on the node only across itself. The slopes are shared at the nodes, so r_path and t
// are continuous as s crosses an element boundary (κ jumps). Beyond the path's ends the
// path goes on along its end tangent (so that a Newton iterate may overshoot); a step that
// ends there stops the run (solvers/time/state_guard.hpp: the slider left its path).
//
// s is an unknown, so the element it acts on follows the state, not the time: its matrix
// pattern holds λ, r and s against every path DOF (rows and columns), as a moving contact's
// holds the head against its path, and each evaluation fills the 19 × 19 block of the
// element holding s.
#include <vector>

#include "catena/couplings/constraint_coupling.hpp"
#include "catena/model/model.hpp"
#include "catena/model/path_stations.hpp"

namespace catena::couplings {

class SliderConstraint final : public ConstraintCoupling {
 public:
  // `index`: into model.constraints, of type slider.
  SliderConstraint(const model::Model& model, int index);

  void pattern(std::vector<std::pair<int, int>>& entries) const override;
  void evaluate(const CouplingState& s, double* f, std::span<const MatrixRequest> m,
                Scratch& scratch) const override;
  bool has_damping() const override { return damping_ != 0.0 || friction_ > 0.0; }
  bool linear() const override { return false; }
  void acceleration_target(const CouplingState& s, std::span<double> out) const override;
  bool acts_on_all() const override { return false; }
  bool state_dependent_activity() const override { return true; }
  // λ, r, s (positions 0..6), then the first and the last node (r, r_x) of the path element
  // holding s.
  void active_dofs_at(double t, const DofValues& q, std::vector<int>& positions) const override;

  // Positions in dofs() (and in the active DOFs) of the multipliers, r and s; then, in dofs()
  // the path's nodes, in the active DOFs the element's two.
  static constexpr int kLambda = 0, kPoint = 3, kSlide = 6, kPath = 7;
  // The path's length, m (s ∈ [0, length] is on it).
  double path_length() const { return stations_.length(); }

 private:
  // Where s lies: the path element, its σ, and the shape functions at x(s).
  struct Place {
    std::size_t element = 0;
    double sigma = 1.0;
    double S[4], dS[4], ddS[4];
  };
  // Positions in the active DOFs of the element's blocks r_A, r_A,x, r_B, r_B,x.
  static constexpr int kFirst[4] = {kPath, kPath + 3, kPath + 6, kPath + 9};
  Place place(double s) const;
  // The path element holding s (clamped to the path: beyond an end, the end element).
  std::size_t element_holding(double s) const;

  model::PathStations stations_;
  std::vector<char> reversed_;              // per path element
  std::vector<int> element_a_, element_b_;  // per path element: position of its first/last
                                            // node's DOFs in dofs()
  double damping_ = 0.0;
  double friction_ = 0.0, stick_speed_ = 1.0;  // Coulomb: μ and v (m/s)
};

}  // namespace catena::couplings

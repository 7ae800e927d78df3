#pragma once
// HHT-α (Hilber, Hughes & Taylor, Earthquake Eng. Struct. Dyn. 5 (1977) 283–292) for
//   M a + f(t, q, v) = 0          (f = f_int + f_damp − f_ext, see elements/element.hpp)
// in the form of Negrut, Rampalli, Ottarsson & Sajdak (J. Comput. Nonlinear Dyn. 2 (2007)
// 73–85), with the new acceleration as the unknown:
//   M a₁ + (1 + α) f(t₁, q₁, v₁) − α f(t₀, q₀, v₀) = 0,
//   q₁ = q₀ + h v₀ + h² [(½ − β) a₀ + β a₁],   v₁ = v₀ + h [(1 − γ) a₀ + γ a₁],
//   β = (1 − α)²/4,  γ = ½ − α,  α ∈ [−1/3, 0].
// Newton's matrix is J = M + (1 + α)(γ h C + β h² K): c_M = 1, c_C = (1+α)γh,
// c_K = (1+α)βh². Second order; unconditionally stable for linear problems; spectral
// radius (1 + α)/(1 − α) as h·ω → ∞ (α = 0: the trapezoidal rule, no numerical damping).
//
// Newton: ReusableNewton — the matrix (and its factorisation) is kept across steps of
// equal h while the iteration contracts fast (simplified Newton), or rebuilt at every
// iterate (full Newton); or one linearly implicit Newton step per time step (fixed cost:
// HhtOptions::linearly_implicit, docs/integrators.md).
// Local error estimate (Zienkiewicz & Xie, Earthquake Eng. Struct. Dyn. 20 (1991) 871–887):
//   e_q = h² (β − 1/6)(a₁ − a₀) = O(h³),
// the difference between the Newmark displacement and a Taylor expansion with a linear
// acceleration; it costs two vector operations.
// Dense output: cubic Hermite interpolation of q from (q, v) and of v from (v, a) at both
// ends of the step (third order, above the method's second).
//
// Central differences (HhtOptions::central_difference; integrator.type central_difference):
// the same step with α = 0, β = 0, γ = ½ — Newmark's explicit member, the velocity form of
// the central-difference (Störmer–Verlet) scheme:
//   q₁ = q₀ + h v₀ + ½h² a₀,   v₁ = v₀ + ½h (a₀ + a₁),   M a₁ + f(t₁, q₁, v₁) = 0.
// The positions are explicit; what depends on v₁ (damping, the contact's dashpot) makes the
// acceleration implicit, solved by the same Newton iteration on J = M + ½h C, which holds
// no stiffness: with constant damping it is factored once for the run. Second order, no
// numerical damping, conditionally stable: h·ω ≤ 2 for the highest undamped mode ω
// (Hughes, The Finite Element Method, 2000, §9.1; with γ = ½ and the damping implicit, as
// here, damping does not lower it). The first set_state computes ω_max of K φ = ω² M φ at
// its state (modes/modal_analysis.hpp, highest_frequency) and stable_step() reports
// 2/ω_max, which the driver enforces. Lagrange-multiplier constraints are refused (β = 0 leaves the
// positions, and so the constraints, independent of the unknown a₁). It is the explicit
// integrator of seed methods for flexible multibody systems (central differences with
// Newton for the implicit part).
//
// Options database prefix: -hht_ (e.g. -hht_snes_monitor, -hht_pc_type lu).
#include <memory>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/newton/local_newton.hpp"
#include "catena/solvers/time/step_state.hpp"

namespace catena::solvers {

struct HhtOptions {
  double alpha = -0.1;  // ∈ [−1/3, 0]
  double rtol = 1e-10;  // Newton: relative to the step's force scale
  double atol = 1e-8;   // N
  int max_newton_iterations = 10;
  bool full_newton = false;
  // Local Newton correction (local_newton.hpp) and its settings; -hht_local_newton_layers
  // (0: off), -hht_local_newton_worn and -hht_local_newton_max_window override them.
  bool local_newton = true;
  LocalNewtonSettings local_newton_settings;
  // Linearly implicit (fixed cost): one Newton step per time step from the predictor, with
  // the matrix of the last tangent (ReusableNewton::linear_step), re-evaluated every
  // `tangent_every` steps (0: only at the first step and after a failure). f(q₁, v₁) for
  // the next step's α term is the step's linear model of it, not a new evaluation. No
  // constraints (refused by the scene reader).
  bool linearly_implicit = false;
  int tangent_every = 0;
  // Central differences: α ignored (0), β = 0, γ = ½; no local correction, not linearly
  // implicit, no constraints.
  bool central_difference = false;
};

class HhtIntegrator final : public StepStateIntegrator {
 public:
  // Collective. Throws InputError if α is out of range.
  HhtIntegrator(assembly::SecondOrderSystem& system, const HhtOptions& options);
  ~HhtIntegrator() override;

  std::string name() const override;
  int order() const override { return 2; }
  bool has_embedded_estimate() const override { return true; }
  int estimate_order() const override { return 3; }
  void set_state(double t, Vec q, Vec v, Vec a) override;
  StepOutcome attempt(double h, const ErrorTolerance* tol) override;
  void accept() override;
  void interpolate(double t, Vec q, Vec v) override;
  const IntegratorCounters& counters() const override;
  void save_resume_state(ResumeState& out) const override;
  void restore_resume_state(const ResumeState& in) override;
  bool resumes_exactly() const override { return true; }
  // Central differences: 2/ω_max of the tangent and mass at the first state set (computed
  // by that set_state); +∞ for HHT.
  double stable_step() const override;
  std::string stable_step_reason() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::solvers

#pragma once
// Linear multistep integrators for  M a + f(t, q, v) = 0  (+ Gᵀλ, g(q) = 0): variable-step
// BDF of order 1 to 5 (Gear; Brenan, Campbell & Petzold, Numerical Solution of
// Initial-Value Problems in DAEs, 1996) and Park's stiffly stable method (K. C. Park,
// J. Appl. Mech. 42 (1975) 464–470), in the form D. Pogorelov gives for multibody systems
// (Numer. Algorithms 19 (1998) 183–194, §4): one differentiation formula D, applied twice,
//   v₁ = D(q₁, q₀, q₋₁, ...),   a₁ = D(v₁, v₀, v₋₁, ...),   M a₁ + f(t₁, q₁, v₁) = 0,
// with the position correction δ = q₁ − q̂ from a predictor q̂ as Newton's unknown. With
// D's weight w₀ on the new value, ∂v₁/∂δ = w₀ and ∂a₁/∂δ = w₀², so Newton's matrix is
//   J = w₀² M + w₀ C + K        (+ Gᵀ columns; constraint rows m̄ w₀² G, algebraic_part.hpp).
// D is the derivative of the polynomial through the actual times (multistep_formulas.hpp),
// so a step may take any length: a rejected or halved step is retried from the same
// history with the formula of its own length, and nothing needs restarting. The driver
// keeps the ratio of successive steps below the formula's zero-stability limit
// (max_step_ratio).
//
// Which formula: BDF-k needs k points of history (t₀ back to t₋ₖ₊₁), Park's method 3; a
// run starts (set_state, a restart) with the current point only and raises the order a
// step at a time: BDF-1 (backward Euler), BDF-2, ..., then the method's own. The start's
// low-order steps bound a fixed-step run's global order by 2, which is why the scene
// reader refuses BDF above order 2 without adaptive steps (the error control takes small
// first steps instead).
//
// Stability (constant steps, undamped modes x'' = −ω²x): BDF-1, BDF-2 and Park are
// A-stable, BDF-1 and BDF-2 L-stable; Park's spectral radius tends to 0 as hω → ∞ too.
// BDF-3 to 5 are not A-stable (Dahlquist's barrier: no A-stable multistep method has order
// above 2): an undamped mode with hω below 1.93 (BDF-3), 4.71 (BDF-4) or from 0.72 to 9.39
// (BDF-5) grows; damping must remove it (docs/integrators.md).
//
// Error estimate: with the predictor q̂ of the formula's order p from q₀, v₀ and p − 1
// past positions (Hermite), both q(t₁) − q̂ and the local error e are of order p + 1 with
// the same leading term up to a factor: e ≈ ρ (q(t₁) − q̂), ρ = c/(w₀h), c = 1 for BDF and
// ½ for Park (half of its error comes from BDF-2's part). Newton's result δ = q₁ − q̂ is
// their sum, so
//   e ≈ ρ/(1 + ρ) · δ
// (Milne's device; the derivation, nonstiff like that of every BDF code, is in
// docs/integrators.md).
// Dense output: cubic Hermite interpolation from (q, v, a) at both ends of the step.
// Newton: ReusableNewton (simplified: the factorisation kept across steps while w₀ stays
// within kMatrixTolerance of the one it was built with, or full). Options prefix: -multistep_.
#include <memory>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/step_state.hpp"

namespace catena::solvers {

enum class MultistepFamily { bdf, park };

struct MultistepOptions {
  MultistepFamily family = MultistepFamily::bdf;
  int order = 2;        // BDF: 1 to 5 (Park: 2)
  double rtol = 1e-10;  // Newton: relative to the step's force scale
  double atol = 1e-8;   // N
  int max_newton_iterations = 10;
  bool full_newton = false;
};

class MultistepIntegrator final : public StepStateIntegrator {
 public:
  // Collective. Throws InputError if the order is outside 1 to 5.
  MultistepIntegrator(assembly::SecondOrderSystem& system, const MultistepOptions& options);
  ~MultistepIntegrator() override;

  std::string name() const override;  // "bdf(order=2)", "park"
  int order() const override;
  bool has_embedded_estimate() const override { return true; }
  int estimate_order() const override { return order() + 1; }
  void set_state(double t, Vec q, Vec v, Vec a) override;
  StepOutcome attempt(double h, const ErrorTolerance* tol) override;
  void accept() override;
  void interpolate(double t, Vec q, Vec v) override;
  const IntegratorCounters& counters() const override;
  double max_step_ratio() const override;
  void save_resume_state(ResumeState& out) const override;
  void restore_resume_state(const ResumeState& in) override;
  bool resumes_exactly() const override { return true; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::solvers

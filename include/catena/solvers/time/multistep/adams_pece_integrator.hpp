#pragma once
// Adams–Bashforth–Moulton in PECE form (predict, evaluate, correct, evaluate) for
//   M a + f(t, q, v) = 0   as the first-order system  q' = v, v' = a(t, q, v),
// the explicit multistep method of D. Pogorelov's seed paper on multibody DAEs
// (Numer. Algorithms 19 (1998) 183–194, §3), of order k = 1 or 2, with variable steps:
//   P: q̂ = q₀ + Σ b_j v_{−j},          v̂ = v₀ + Σ b_j a_{−j}        (Adams–Bashforth)
//   E: â = a(t₁, q̂, v̂)
//   C: q₁ = q₀ + c₀ v̂ + Σ c_j v_{1−j},  v₁ = v₀ + c₀ â + Σ c_j a_{1−j}  (Adams–Moulton)
//   E: a₁ = a(t₁, q₁, v₁)
// with b, c the integrals over the step of the polynomials through the actual past times
// (multistep_formulas.hpp). Each evaluation is one force and one solve with the mass
// matrix, factored once for the run (consistent_acceleration.hpp): no Newton, no tangent.
// k = 1 is Euler's predictor with a backward Euler corrector, k = 2 AB-2 with the
// trapezoidal rule. A run starts at order 1 and climbs as its history grows.
//
// Stability (conditional): every eigenvalue μ of the linearised first-order system must
// lie where the PECE recurrence is stable. For k = 1 and 2 that region contains the left
// half-disc of radius r_k = 1 and 1.28 (computed from the recurrence's roots), so
//   h ≤ r_k / R,  R = max(ω_max, ν_max),
// with ω_max the highest undamped frequency (K φ = ω² M φ) and ν_max the largest eigenvalue
// of C φ = ν M φ: an underdamped mode has |μ| = ω, an overdamped one a real μ ≥ −ν. Both are
// computed at the first state set (modes/modal_analysis.hpp); stable_step() reports the
// limit and the driver enforces it. Higher orders are left out: ABM-3 and ABM-4 in PECE form
// have no stable interval of the imaginary axis at all (undamped modes grow at any step),
// and ABM-5's reaches only hω = 0.26 (docs/integrators.md).
// Error estimate: Milne's device with the constant-step error constants,
//   e = C_M/(C_B − C_M) (q₁ − q̂) = −½ (k = 1), −⅙ (k = 2) times (q₁ − q̂).
// Lagrange-multiplier constraints: each evaluation solves [M Gᵀ; G 0][a; λ] = [−f; γ], and
// after the corrector the positions and velocities are projected onto g(q, t₁) = 0 and
// G v = β(t₁) (the nearest in the kinetic-energy norm), so that they do not drift: the seed
// paper's stabilisation that solves the equations of index 3, 2 and 1 at the corrected
// state (its ABM3). The step limit is then taken over the nodal unknowns alone.
#include <memory>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/step_state.hpp"

namespace catena::solvers {

struct AdamsPeceOptions {
  int order = 2;  // 1 or 2
};

class AdamsPeceIntegrator final : public StepStateIntegrator {
 public:
  // Collective. Factors the mass matrix (with linear constraints the saddle-point matrix;
  // with nonlinear ones each solve factors it at its state). Throws InputError for an order
  // outside 1 to 2.
  AdamsPeceIntegrator(assembly::SecondOrderSystem& system, const AdamsPeceOptions& options);
  ~AdamsPeceIntegrator() override;

  std::string name() const override;  // "abm(order=2)"
  int order() const override;
  bool has_embedded_estimate() const override { return true; }
  int estimate_order() const override { return order() + 1; }
  // The first call computes ω_max and ν_max at that state (the stability limit).
  void set_state(double t, Vec q, Vec v, Vec a) override;
  StepOutcome attempt(double h, const ErrorTolerance* tol) override;
  void accept() override;
  void interpolate(double t, Vec q, Vec v) override;
  const IntegratorCounters& counters() const override;
  double stable_step() const override;
  std::string stable_step_reason() const override;
  void save_resume_state(ResumeState& out) const override;
  void restore_resume_state(const ResumeState& in) override;
  bool resumes_exactly() const override { return true; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::solvers

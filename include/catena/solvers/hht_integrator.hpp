#pragma once
// HHT-α (Hilber, Hughes & Taylor, Earthquake Eng. Struct. Dyn. 5 (1977) 283–292) for
//   M a + f(q, v) = 0          (f = f_int + f_damp − f_ext, see elements/element.hpp)
// in the form of Negrut, Rampalli, Ottarsson & Sajdak (J. Comput. Nonlinear Dyn. 2 (2007)
// 73–85), with the new acceleration as the unknown:
//   M a₁ + (1 + α) f(q₁, v₁) − α f(q₀, v₀) = 0,
//   q₁ = q₀ + h v₀ + h² [(½ − β) a₀ + β a₁],   v₁ = v₀ + h [(1 − γ) a₀ + γ a₁],
//   β = (1 − α)²/4,  γ = ½ − α,  α ∈ [−1/3, 0].
// Newton's matrix is J = M + (1 + α)(γ h C + β h² K): c_M = 1, c_C = (1+α)γh,
// c_K = (1+α)βh². Second order; unconditionally stable for linear problems; spectral
// radius (1 + α)/(1 − α) as h·ω → ∞ (α = 0: the trapezoidal rule, no numerical damping).
//
// Options database prefix: -hht_ (e.g. -hht_snes_monitor, -hht_pc_type lu).
#include <memory>

#include "catena/assembly/second_order_system.hpp"

namespace catena::solvers {

struct HhtOptions {
  double alpha = -0.1;  // ∈ [−1/3, 0]
  double dt = 1e-3;     // s, > 0
  double rtol = 1e-10;  // Newton: relative to the step's force scale
  double atol = 1e-8;   // N
  int max_newton_iterations = 20;
};

struct HhtStepReport {
  int newton_iterations = 0;
  double residual_norm = 0.0;
};

class HhtIntegrator {
 public:
  // Collective. Throws InputError if α or dt are out of range.
  HhtIntegrator(assembly::SecondOrderSystem& system, const HhtOptions& options);
  ~HhtIntegrator();
  HhtIntegrator(const HhtIntegrator&) = delete;
  HhtIntegrator& operator=(const HhtIntegrator&) = delete;

  // Collective. Sets t, q, v and computes the consistent acceleration M a = −f(q, v).
  void initialize(double t, Vec q, Vec v);
  // Collective. Advances one step of size dt; throws NumericalError if Newton fails.
  HhtStepReport step();

  double time() const;
  Vec q() const;  // current state (owned by the integrator; copy to keep)
  Vec v() const;
  Vec a() const;
  // Spectral radius at infinite h·ω for these options: (1 + α)/(1 − α).
  double spectral_radius_at_infinity() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::solvers

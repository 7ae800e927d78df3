#pragma once
// RATTLE (Andersen, J. Comput. Phys. 52 (1983) 24–34), the two-stage Lobatto IIIA–IIIB pair
// for constrained mechanical systems (Jay, SIAM J. Numer. Anal. 33 (1996) 368–387; Hairer,
// Lubich & Wanner, Geometric Numerical Integration, 2nd ed., 2006, VII.1), for
//   M a + f(t, q, v) + G(q)ᵀλ = 0,   g(q, t) = 0:
//   v½ = v₀ + ½h K₁,   q₁ = q₀ + h v½,
//   M K₁ + f(t₀, q₀, v½) + G(q₀)ᵀΛ₁ = 0,   g(q₁, t₁) = 0              (phase 1: K₁, Λ₁),
//   v₁ = v½ + ½h K₂,
//   M K₂ + f(t₁, q₁, v½) + G(q₁)ᵀΛ₂ = 0,   G(q₁) v₁ = β(t₁)            (phase 2: K₂, Λ₂).
// The positions are the Lobatto IIIA and the velocities the Lobatto IIIB stages of s = 2:
// both stages take a velocity-dependent force at v½ (implicit in the first, known in the
// second); the step ends on both the position and the velocity constraints. With a constant
// M and conservative forces (rigid bodies in natural coordinates under gravity, elastic
// elements without damping) the method is symplectic and symmetric: the energy error stays
// bounded, with no drift, over any number of steps, and quadratic first integrals such as
// the angular momentum about a fixed axis are kept (docs/integrators.md, "RATTLE").
// Without constraints and damping it is the Störmer–Verlet scheme (central differences).
// Second order in q, v and λ; no numerical damping, no embedded estimate (adaptive steps
// use step doubling). The force rows of each phase are evaluated at known positions, so
// the stiffness is explicit: stable for h·ω_max ≤ 2 as central differences, ω_max the
// highest frequency of the structure without its constraints at the initial state (the
// driver refuses longer fixed steps and caps adaptive ones there). A method for
// mechanisms and soft structures; a stiff cable needs hht or radau.
//
// Newton: each phase is one solve of ReusableNewton on the one matrix
//   J = [M + ½h C   Gᵀ]        (phase 2: no C, its force is known)
//       [m̄ G        0 ]
// (constraint rows scaled by m̄/(½h²) in phase 1 and m̄/(½h) in phase 2, so that both read
// m̄ G), at the point of its last refresh; it holds no stiffness (the positions of each
// phase's force rows are known), so a mechanism's matrix changes only with G and C.
// Phase 1 evaluates the forces twice per iterate (its force rows at q₀, its constraint
// rows at q₁), phase 2 once.
//
// Options database prefix: -rattle_ (e.g. -rattle_snes_monitor).
#include <memory>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/step_state.hpp"

namespace catena::solvers {

struct RattleOptions {
  double rtol = 1e-10;  // Newton: relative to the step's force scale
  double atol = 1e-8;   // N
  int max_newton_iterations = 10;
  bool full_newton = false;
};

class RattleIntegrator final : public StepStateIntegrator {
 public:
  // Collective.
  RattleIntegrator(assembly::SecondOrderSystem& system, const RattleOptions& options);
  ~RattleIntegrator() override;

  std::string name() const override { return "rattle"; }
  int order() const override { return 2; }
  bool has_embedded_estimate() const override { return false; }
  void set_state(double t, Vec q, Vec v, Vec a) override;
  StepOutcome attempt(double h, const ErrorTolerance* tol) override;
  void accept() override;
  void interpolate(double t, Vec q, Vec v) override;
  const IntegratorCounters& counters() const override;
  void save_resume_state(ResumeState& out) const override;
  void restore_resume_state(const ResumeState& in) override;
  bool resumes_exactly() const override { return true; }
  // 2/ω_max at the first state set (computed by that set_state), as central differences.
  double stable_step() const override;
  std::string stable_step_reason() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::solvers

#pragma once
// Implicit Runge–Kutta in K-form for the second-order system M a + f(t, q, v) = 0
// (Gerstmayr's HOTINT scheme, seed 000): the unknowns of a step are the s stage
// accelerations K_i, and the stage states follow from them,
//   u_i = q0 + c_i h v0 + h² Σ_j (A²)_ij K_j,    v_i = v0 + h Σ_j a_ij K_j,
//   R_i = M K_i + f(t0 + c_i h, u_i, v_i) = 0,                         i = 1..s,
//   q1 = q0 + h v0 + h² Σ_j (bᵀA)_j K_j,        v1 = v0 + h Σ_j b_j K_j.
// (The position recurrence uses Σ_j a_ij = c_i; tableaus: butcher_tableau.hpp.)
//
// Newton: the s·n stage system has blocks
//   ∂R_i/∂K_j = δ_ij M + h a_ij C + h² (A²)_ij K.
// Simplified Newton (default) takes one K, C for all stages, evaluated at the current
// iterate's last stage (u_s, v_s) whenever it is refreshed, and keeps the factorisation
// over steps of equal h while the iteration contracts fast (ReusableNewton); full Newton
// linearises stage i at (u_i, v_i) at every iterate. Linear algebra:
//   decoupled (default where exact: simplified Newton and an A with distinct nonzero
//     eigenvalues — Gauss, Radau IIA, Lobatto IIIC): the RADAU5 transformation
//     A = T D T⁻¹ splits the system into one n-sized block per real eigenvalue and one real
//     2n-sized block per complex pair, each factored by MUMPS (decoupled_stage_solver.hpp);
//     the Newton iterates are the coupled ones to round-off;
//   coupled (full Newton, Lobatto IIIA, SDIRK, or on request): the whole s·n matrix as one
//     MPIAIJ matrix (BlockMatrix, DOF-major) factored by MUMPS LU.
//
// Predictor: the previous step's acceleration polynomial (the collocation polynomial
// through its K_j at t_prev + c_j h_prev) extrapolated to the new stage times.
//
// Embedded error estimate (Radau IIA, odd s; docs/tableaus.md): with d = b̂ − b,
//   r_u = h² Σ_j (Aᵀd)_j K_j,   r_v = h (γ0 a0 + Σ_j d_j K_j),
//   (M + hγ0 C + (hγ0)² K) x_v = M r_v − hγ0 K r_u,   x_u = r_u + hγ0 x_v,
// ‖x_u‖ = O(h^{s+1}) in the weighted norm — one more n-sized factorisation per matrix
// with the coupled stage solve; none with the decoupled one, whose real block (γ0 is A's
// real eigenvalue) is that filter matrix.
//
// Dense output: the collocation polynomial (Gauss, Radau IIA s ≥ 2, Lobatto IIIA), which
// is continuous at the step ends; cubic Hermite for the others (Radau IIA s = 1, Lobatto
// IIIC, SDIRK, whose polynomial does not pass through q1).
//
// Options database prefixes: -irk_ (stage Newton: -irk_snes_monitor, -irk_pc_type ...;
// decoupled: the PC is the decoupled solve, its blocks' KSPs -irk_block0_, -irk_block1_ ...),
// -irk_estimate_ (the estimate's filter solve), -mass_ (initial acceleration).
#include <memory>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/irk/butcher_tableau.hpp"
#include "catena/solvers/time/step_state.hpp"

namespace catena::solvers {

// How the stage Newton's linear systems are solved (see the header comment).
enum class StageLinearAlgebra {
  automatic,  // decoupled where exact, else coupled
  decoupled,  // decoupled; InputError where it is not exact
  coupled,
};

struct IrkOptions {
  TableauFamily family = TableauFamily::radau_iia;
  int stages = 3;
  double rtol = 1e-10;  // Newton: relative to the step's force scale
  double atol = 1e-8;   // N
  int max_newton_iterations = 10;
  bool full_newton = false;
  StageLinearAlgebra linear_algebra = StageLinearAlgebra::automatic;
};

class IrkIntegrator final : public StepStateIntegrator {
 public:
  // Collective. Throws InputError for an unknown family/stage count, or for
  // linear_algebra = decoupled where it is not exact (the message says why).
  IrkIntegrator(assembly::SecondOrderSystem& system, const IrkOptions& options);
  ~IrkIntegrator() override;

  std::string name() const override;
  int order() const override;
  bool has_embedded_estimate() const override;
  int estimate_order() const override;
  int velocity_order() const override;
  void set_state(double t, Vec q, Vec v, Vec a) override;
  void forget_jacobian() override;
  StepOutcome attempt(double h, const ErrorTolerance* tol) override;
  void accept() override;
  void interpolate(double t, Vec q, Vec v) override;
  const IntegratorCounters& counters() const override;
  void save_resume_state(ResumeState& out) const override;
  void restore_resume_state(const ResumeState& in) override;
  bool resumes_exactly() const override { return true; }

  const ButcherTableau& tableau() const;
  // True if the stage Newton uses the decoupled linear algebra.
  bool decoupled() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::solvers

#pragma once
// A bridge to PETSc's time steppers (TS) for M a + f(t, q, v) = 0: one TSStep per
// attempt(h), the step size chosen by our driver (transient_solver.hpp). The method comes
// from the options database with the plain TS prefix (-ts_type bdf, -ts_bdf_order 2,
// -ts_rosw_type ra34pw2, -snes_monitor, ...); TSSetFromOptions is applied last.
//
// -ts_type alpha2 (default): the second-order form, TSSetI2Function/TSSetI2Jacobian,
//   F(t, U, V, A) = M A + f(t, U, V),   J = K + shiftV·C + shiftA·M
//   (PETSc's convention J = ∂F/∂U + shiftV ∂F/∂V + shiftA ∂F/∂A). HHT-α (Negrut's α ∈
//   [−1/3, 0], PetscTsOptions::alpha) maps onto PETSc's generalised-α as
//   alpha_m = 1, alpha_f = 1 + α, gamma = ½ − α, beta = (1 − α)²/4,
//   the same method as HhtIntegrator on linear problems (PETSc evaluates f at the
//   interpolated state, HHT interpolates the forces: with a nonlinear f they differ by
//   about a local error, both second order). -ts_alpha_radius, -ts_alpha_alpha_m, ...
//   override the mapping. PETSc 3.18 restarts alpha2 with twice the acceleration of two
//   backward-Euler half steps, which makes it first order; the bridge makes that start
//   return the state's own acceleration (petsc_ts_integrator.cpp, "start-up"), so
//   restarts lose nothing.
// any other type: the first-order form of first_order_form.hpp, U = [q; v] interleaved per
//   DOF, TSSetIFunction/TSSetIJacobian with G = [q̇ − v; M v̇ + f] and
//   J = [σI, −I; K, C + σM] (one MPIAIJ 2n×2n matrix).
//
// Linear solves: KSPPREONLY + PCLU with MUMPS (overridable: -ksp_type, -pc_type, ...).
// Newton (SNES newtonls, full steps) converges by Catena's test, as in ReusableNewton:
// ‖F‖₂ ≤ atol + rtol·s, s the element force norm, or a relative update below 1e-12;
// -snes_atol/-snes_rtol are not used. Rosenbrock types get SNES ksponly (one linear
// solve per stage). PETSc's adaptivity is off (TSAdapt none) unless -ts_adapt_type is
// given; then a step may end before t + h when PETSc's own test shortens it, and time()
// says where. A failed TSStep (TSGetConvergedReason < 0) is reported in StepOutcome, not
// thrown. Types: alpha2, alpha, bdf, beuler, cn, theta, rosw; others are refused
// (src/solvers/time/petsc_ts/petsc_ts_methods.hpp says why).
//
// History (honest about multistep methods): the TS is kept alive between accepted steps,
// so BDF keeps its back values and alpha2 its acceleration. A converged attempt that the
// driver discards is undone by TSRollBack for types with history (bdf, alpha2, alpha), and by
// copying the start state back and TSRestartStep otherwise; a failed attempt and
// set_state() always restart (BDF then restarts at order 1 with a half step, i.e. loses
// its history; step doubling's rejected pairs call set_state, so with step doubling a
// rejection costs BDF its history).
//
// Dense output: TSInterpolate where the type has a good interpolant (bdf, rosw ra34pw2), else
// cubic Hermite of q from (q, v) and of v from (v, a) at both step ends (a: alpha2's own,
// else M a = −f solved at the ends when first needed); table in
// src/solvers/time/petsc_ts/petsc_ts_methods.hpp, order() too.
//
// Restarts are not bit for bit (resumes_exactly() is false): the TS keeps its history (BDF's
// back values, its SNES and factorisation) inside the TS object, which PETSc 3.18's public API
// does not let us save and set; a restart starts the TS afresh from (t, q, v, a).
//
// Not supported: Lagrange-multiplier constraints.
#include <memory>

#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/time/step_state.hpp"

namespace catena::solvers {

struct PetscTsOptions {
  double alpha = -0.1;  // HHT α for -ts_type alpha2, ∈ [−1/3, 0]
  double rtol = 1e-10;  // Newton: relative to the element force scale
  double atol = 1e-8;   // N
  int max_newton_iterations = 10;
};

class PetscTsIntegrator final : public StepStateIntegrator {
 public:
  // Collective. Reads the TS options database. Throws InputError if α is out of range.
  PetscTsIntegrator(assembly::SecondOrderSystem& system, const PetscTsOptions& options);
  ~PetscTsIntegrator() override;

  std::string name() const override;  // "petsc(<ts type>)"
  int order() const override;
  bool has_embedded_estimate() const override { return false; }
  void set_state(double t, Vec q, Vec v, Vec a) override;
  StepOutcome attempt(double h, const ErrorTolerance* tol) override;
  void accept() override;
  void interpolate(double t, Vec q, Vec v) override;
  const IntegratorCounters& counters() const override;
  // a() (StepStateIntegrator) is collective on first use after a step of a first-order type.

  // The TS type in use ("alpha2", "bdf", ...).
  std::string ts_type() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace catena::solvers

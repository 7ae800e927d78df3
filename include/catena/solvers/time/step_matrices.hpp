#pragma once
// The matrices of an integrator that solves one system-sized Newton problem per step (HHT,
// central differences, the multistep methods): what each builds its Newton matrix from.
//   M           assembled once (constant in ANCF), with a copy without its stored zeros
//               for the product M a of every residual (compact_matrix.hpp);
//   K, C        the element tangents ∂f/∂q and ∂f/∂v at a remembered point (C only where
//               the system has damping), with the round-off floor's diagonal of K;
//   J           the Newton matrix, given M's full pattern once so that MatCopy/MatAXPY
//               keep it;
//   Gᵀ          the multipliers' columns and the algebraic part, where the system has
//               constraints: constant where they are linear in q, else evaluated with K.
// The integrators derive their private state from this struct, so that their formulas
// read `mass`, `K`, `evaluate_tangent(...)` as before; what differs (the coefficients of
// J, the unknown) stays theirs.
#include <memory>
#include <string>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/newton/reusable_newton.hpp"
#include "catena/solvers/newton/round_off_floor.hpp"
#include "catena/solvers/resume_state.hpp"
#include "catena/solvers/time/algebraic_part.hpp"

namespace catena::solvers {

struct StepMatrices {
  // Collective. q: a state of the system's layout (M is constant, and so is Gᵀ where the
  // constraints are linear; else evaluate_tangent sets it).
  StepMatrices(assembly::SecondOrderSystem& system, Vec q);

  assembly::SecondOrderSystem& system;
  MatHandle mass, mass_product, K, C, jacobian, coupling;
  std::unique_ptr<AlgebraicPart> algebraic;
  RoundOffFloor round_off;  // of f (round_off_floor.hpp)
  // Where K and C were last evaluated (kept for a restart, which evaluates them there again).
  VecHandle tangent_q, tangent_v;
  double tangent_t = 0.0;

  // C, or null where the system has no damping (C = 0: neither assembled nor added).
  Mat damping_matrix() const { return system.has_damping() ? C.get() : nullptr; }
  // Collective. K, C and the round-off floor's tangent at (q, v, t), the point remembered.
  void evaluate_tangent(Vec q, Vec v, double t);
  // Whether J needs a pivoting factorisation: only multipliers add zero diagonal rows (the
  // other rows keep mass, or stiffness at a massless node), and J has them marked, for an
  // elimination order that takes them last (constraints_last_ordering.hpp).
  Pivoting pivoting() const {
    return algebraic->active() ? Pivoting::constraints_last : Pivoting::not_needed;
  }
  // Collective. The step's Newton solver on J (non-symmetric in general: damping), with
  // the pivoting above; options prefix `prefix` (e.g. "hht_"), `residual` its work vector.
  std::unique_ptr<ReusableNewton> make_newton(const std::string& prefix, int max_iterations,
                                              bool full_newton, Vec residual,
                                              ReusableNewton::Residual f,
                                              ReusableNewton::MatrixBuilder build) const;

  // Restarts. Not collective. The tangent's point as entries "<prefix>.tangent_q",
  // "<prefix>.tangent_v", "<prefix>.tangent_t", "<prefix>.round_off_known".
  void save_tangent(ResumeState& out, const std::string& prefix) const;
  // Collective. K, C and the floor as they were: evaluated again at the saved point, if one
  // was saved; returns whether it evaluated (one element tangent pass).
  bool restore_tangent(const ResumeState& in, const std::string& prefix);
};

}  // namespace catena::solvers

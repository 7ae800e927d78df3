#pragma once
// Undamped vibration modes about a state (normally the static equilibrium): the
// generalised eigenproblem K φ = ω² M φ with K = ∂f/∂q the tangent stiffness there (its
// stress stiffening included, so a tensioned wire's modes are the string's) and M the
// mass matrix, both over the free DOFs (supports eliminated). Solved by SLEPc's
// Krylov–Schur with shift-and-invert about 0 and a MUMPS LDLᵀ factorisation of K, so the
// lowest modes converge first; every solve's status is checked.
//
// Options database prefix: -modes_ (e.g. -modes_eps_monitor, -modes_eps_tol 1e-12,
// -modes_st_ksp_type); set last, so the command line wins.
#include <petscvec.h>

#include <vector>

#include "catena/assembly/petsc_handle.hpp"
#include "catena/assembly/second_order_system.hpp"

namespace catena::solvers {

struct ModalOptions {
  int count = 20;            // modes wanted, lowest first
  double tolerance = 1e-10;  // relative residual of each eigenpair
};

struct Modes {
  std::vector<double> frequency;  // Hz, ascending
  // Shapes over the system's unknowns, normalised to unit modal mass (φᵀ M φ = 1 kg).
  std::vector<VecHandle> shape;
  std::vector<double> residual;  // |K φ − ω² M φ| / (ω² |M φ|), per mode
  int n_iterations = 0;          // Krylov–Schur restarts
};

// Throws InputError when the model has Lagrange multipliers (modes are of K and M alone)
// or absorbing ends (dashpots, which undamped modes leave out, on nodes free without them):
// callers check before the shape finding and static solve that precede the modes.
void refuse_constraints_for_modes(const model::Model& model);

// Collective. The `options.count` lowest modes about q (no multipliers: a model with
// constraints is refused with a message). Throws NumericalError when K cannot be factored
// (a mechanism or an unstable state) or fewer modes converge than asked for.
Modes compute_modes(assembly::SecondOrderSystem& system, Vec q, const ModalOptions& options);

// Collective. The highest undamped frequency ω_max (rad/s) of K φ = ω² M φ, K symmetric
// (its symmetric part is what the Rayleigh quotient sees) and M positive definite: SLEPc's
// Krylov–Schur on M⁻¹K (a Cholesky factorisation of M, largest magnitude first), converged
// to a relative residual of 1e-5 (the eigenvalue to about its square). Options prefix
// -highest_. Throws NumericalError if M cannot be factored (a DOF without mass) or the
// solver does not converge.
double highest_frequency(Mat K, Mat M);

// Collective. Every mode of K φ = ω² M φ over the DOFs in `keep` (this rank's owned global
// indices, ascending; the other DOFs held at zero) with frequency ≤ cutoff (Hz), by
// SLEPc's spectrum slicing (Krylov–Schur, shift-and-invert, the MUMPS LDLᵀ's inertia
// counting the eigenvalues below each shift, so none is missed). Shapes are vectors laid
// out as `like`, zero outside `keep`, normalised to unit modal mass. K and M must be
// symmetric (the structure's, not the Newton matrices'). Throws NumericalError when K
// cannot be factored or a mode fails to converge, InputError (naming `key` of
// `scene`) when no mode lies below the cut-off.
Modes compute_modes_below(Mat K, Mat M, const std::vector<PetscInt>& keep, double cutoff, Vec like,
                          const std::string& scene, const std::string& key);

}  // namespace catena::solvers

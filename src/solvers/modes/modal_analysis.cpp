#include "catena/solvers/modes/modal_analysis.hpp"

#include <slepceps.h>
#include <slepcsys.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/newton/mumps_status.hpp"

namespace catena::solvers {
namespace {

using EpsHandle = PetscHandle<EPS, EPSDestroy>;

constexpr const char* kPrefix = "modes_";

}  // namespace

Modes compute_modes(assembly::SecondOrderSystem& system, Vec q, const ModalOptions& options) {
  if (system.has_constraints())
    throw InputError({system.model().source_file, 0, "constraints"},
                     "modes of a scene with constraints (Lagrange multipliers) are not "
                     "computed: their mass matrix is singular in the multipliers. Hold the "
                     "nodes with supports ('fix') instead");
  MatHandle K = system.create_matrix(), M = system.create_matrix();
  const assembly::EvalPoint at{q, nullptr, {}, 0.0};
  system.jacobian(at, {1.0, 0.0, 0.0, 0.0, 0.0}, K.get());
  system.jacobian(at, {0.0, 0.0, 1.0, 0.0, 0.0}, M.get());
  CATENA_PETSC(MatSetOption(K.get(), MAT_SYMMETRIC, PETSC_TRUE));
  CATENA_PETSC(MatSetOption(M.get(), MAT_SYMMETRIC, PETSC_TRUE));
  PetscInt n = 0;
  CATENA_PETSC(MatGetSize(K.get(), &n, nullptr));
  if (options.count > n)
    throw InputError({system.model().source_file, 0, "--count"},
                     std::to_string(options.count) + " modes asked for, but the model has " +
                         std::to_string(n) + " free DOFs; ask for at most that many");

  // SLEPc after PETSc: SlepcInitialize then registers SLEPc only (PETSc's finalisation
  // finalises it), so the sessions that never compute modes do not pay for it.
  PetscBool slepc_ready = PETSC_FALSE;
  CATENA_PETSC(SlepcInitialized(&slepc_ready));
  if (!slepc_ready) CATENA_PETSC(SlepcInitializeNoArguments());
  EpsHandle eps;
  CATENA_PETSC(EPSCreate(system.comm(), eps.out()));
  CATENA_PETSC(EPSSetOperators(eps.get(), K.get(), M.get()));
  CATENA_PETSC(EPSSetProblemType(eps.get(), EPS_GHEP));
  CATENA_PETSC(EPSSetType(eps.get(), EPSKRYLOVSCHUR));
  CATENA_PETSC(EPSSetDimensions(eps.get(), options.count, PETSC_DEFAULT, PETSC_DEFAULT));
  CATENA_PETSC(EPSSetTolerances(eps.get(), options.tolerance, PETSC_DEFAULT));
  // Shift-and-invert about 0: the eigenvalues of K⁻¹M are 1/ω², the lowest modes the
  // largest and best separated ones.
  CATENA_PETSC(EPSSetWhichEigenpairs(eps.get(), EPS_TARGET_MAGNITUDE));
  CATENA_PETSC(EPSSetTarget(eps.get(), 0.0));
  ST st = nullptr;
  CATENA_PETSC(EPSGetST(eps.get(), &st));
  CATENA_PETSC(STSetType(st, STSINVERT));
  KSP ksp = nullptr;
  CATENA_PETSC(STGetKSP(st, &ksp));
  CATENA_PETSC(KSPSetType(ksp, KSPPREONLY));
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  CATENA_PETSC(PCSetType(pc, PCCHOLESKY));
  CATENA_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  enable_mumps_null_pivot_detection(std::string(kPrefix) + "st_");
  CATENA_PETSC(EPSSetOptionsPrefix(eps.get(), kPrefix));
  CATENA_PETSC(EPSSetFromOptions(eps.get()));
  CATENA_PETSC(EPSSetUp(eps.get()));
  if (const DirectSolveStatus factor = direct_solve_status(ksp); factor.failed())
    throw NumericalError(
        "modes: the tangent stiffness cannot be factored (" + factor.describe() +
        "): the structure is a mechanism at this state, or the state is not an equilibrium "
        "the modes can be taken about");
  CATENA_PETSC(EPSSolve(eps.get()));
  if (const DirectSolveStatus solve = direct_solve_status(ksp); solve.failed())
    throw NumericalError("modes: a shift-and-invert solve failed (" + solve.describe() + ")");
  EPSConvergedReason reason;
  CATENA_PETSC(EPSGetConvergedReason(eps.get(), &reason));
  PetscInt converged = 0, iterations = 0;
  CATENA_PETSC(EPSGetConverged(eps.get(), &converged));
  CATENA_PETSC(EPSGetIterationNumber(eps.get(), &iterations));
  if (reason < 0 || converged < options.count)
    throw NumericalError("modes: " + std::to_string(converged) + " of " +
                         std::to_string(options.count) + " modes converged in " +
                         std::to_string(iterations) + " Krylov-Schur restarts (EPS reason " +
                         std::to_string(reason) +
                         "); ask for fewer, or more with -modes_eps_max_it");

  Modes modes;
  modes.n_iterations = static_cast<int>(iterations);
  std::vector<double> eigenvalue(static_cast<std::size_t>(converged));
  std::vector<VecHandle> vectors;
  for (PetscInt i = 0; i < converged; ++i) {
    PetscScalar kr = 0.0, ki = 0.0;
    VecHandle x = system.create_vector();
    CATENA_PETSC(EPSGetEigenpair(eps.get(), i, &kr, &ki, x.get(), nullptr));
    eigenvalue[static_cast<std::size_t>(i)] = PetscRealPart(kr);
    vectors.push_back(std::move(x));
  }
  // Lowest first (the target ordering sorts by |λ|, which for K SPD is the same; sorted
  // anyway so that the output never depends on it).
  std::vector<std::size_t> order(eigenvalue.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return eigenvalue[a] < eigenvalue[b]; });
  VecHandle Mx = system.create_vector(), Kx = system.create_vector();
  for (std::size_t k = 0; k < static_cast<std::size_t>(options.count); ++k) {
    const std::size_t i = order[k];
    const double lambda = eigenvalue[i];
    if (!(lambda > 0.0))
      throw NumericalError("modes: eigenvalue " + std::to_string(lambda) +
                           " <= 0 (ω² must be positive at a stable equilibrium): the state is "
                           "unstable or a mechanism");
    Vec x = vectors[i].get();
    CATENA_PETSC(MatMult(M.get(), x, Mx.get()));
    PetscScalar modal_mass = 0.0;
    CATENA_PETSC(VecDot(x, Mx.get(), &modal_mass));
    CATENA_PETSC(VecScale(x, 1.0 / std::sqrt(PetscRealPart(modal_mass))));
    CATENA_PETSC(VecScale(Mx.get(), 1.0 / std::sqrt(PetscRealPart(modal_mass))));
    CATENA_PETSC(MatMult(K.get(), x, Kx.get()));
    PetscReal mass_norm = 0.0, miss = 0.0;
    CATENA_PETSC(VecNorm(Mx.get(), NORM_2, &mass_norm));
    CATENA_PETSC(VecAXPY(Kx.get(), -lambda, Mx.get()));
    CATENA_PETSC(VecNorm(Kx.get(), NORM_2, &miss));
    modes.frequency.push_back(std::sqrt(lambda) / (2.0 * std::numbers::pi));
    modes.residual.push_back(miss / (lambda * mass_norm));
    modes.shape.push_back(std::move(vectors[i]));
  }
  return modes;
}

}  // namespace catena::solvers

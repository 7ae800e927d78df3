#include "catena/solvers/modes/modal_analysis.hpp"

#include <slepceps.h>
#include <slepcsys.h>

#include <algorithm>
#include <cmath>
#include <functional>
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

// SLEPc after PETSc: SlepcInitialize then registers SLEPc only (PETSc's finalisation
// finalises it), so the sessions that never compute modes do not pay for it.
void ensure_slepc() {
  PetscBool slepc_ready = PETSC_FALSE;
  CATENA_PETSC(SlepcInitialized(&slepc_ready));
  if (!slepc_ready) CATENA_PETSC(SlepcInitializeNoArguments());
}

// Krylov–Schur on the symmetric pencil (K, M) with spectral transformation `st_type` whose
// solves are one MUMPS Cholesky factorisation (of K for shift-and-invert, of M for the shift:
// M⁻¹K); the ST's KSP.
KSP krylov_schur(EPS eps, Mat K, Mat M, STType st_type, double tolerance, PetscInt max_it) {
  CATENA_PETSC(EPSSetOperators(eps, K, M));
  CATENA_PETSC(EPSSetProblemType(eps, EPS_GHEP));
  CATENA_PETSC(EPSSetType(eps, EPSKRYLOVSCHUR));
  CATENA_PETSC(EPSSetTolerances(eps, tolerance, max_it));
  ST st = nullptr;
  CATENA_PETSC(EPSGetST(eps, &st));
  CATENA_PETSC(STSetType(st, st_type));
  KSP ksp = nullptr;
  CATENA_PETSC(STGetKSP(st, &ksp));
  CATENA_PETSC(KSPSetType(ksp, KSPPREONLY));
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  CATENA_PETSC(PCSetType(pc, PCCHOLESKY));
  CATENA_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  return ksp;
}

// Krylov–Schur on K φ = λ M φ with shift-and-invert and a MUMPS LDLᵀ; `configure` sets what
// is wanted (which eigenpairs, how many) before the options database is read.
// `slicing`: spectrum slicing factors in a child solver of its own, so the parent's
// factorisation is not there to check (SLEPc's inertia counts fail loudly instead).
EpsHandle make_eps(MPI_Comm comm, Mat K, Mat M, double tolerance,
                   const std::function<void(EPS)>& configure, bool slicing = false) {
  ensure_slepc();
  EpsHandle eps;
  CATENA_PETSC(EPSCreate(comm, eps.out()));
  KSP ksp = krylov_schur(eps.get(), K, M, STSINVERT, tolerance, PETSC_DEFAULT);
  enable_mumps_null_pivot_detection(std::string(kPrefix) + "st_");
  configure(eps.get());
  CATENA_PETSC(EPSSetOptionsPrefix(eps.get(), kPrefix));
  CATENA_PETSC(EPSSetFromOptions(eps.get()));
  CATENA_PETSC(EPSSetUp(eps.get()));
  if (slicing) return eps;
  if (const DirectSolveStatus factor = direct_solve_status(ksp); factor.failed())
    throw NumericalError(
        "modes: the tangent stiffness cannot be factored (" + factor.describe() +
        "): the structure is a mechanism at this state, or the state is not an equilibrium "
        "the modes can be taken about");
  return eps;
}

// Solves; the converged count (throws if the solver reports divergence). Messages name the
// solver by its options prefix ("modes_", "highest_"), which is also where its options go.
PetscInt solve(EPS eps, PetscInt* iterations, bool slicing = false) {
  CATENA_PETSC(EPSSolve(eps));
  const char* prefix_text = nullptr;
  CATENA_PETSC(EPSGetOptionsPrefix(eps, &prefix_text));
  const std::string prefix = prefix_text ? prefix_text : "";
  if (!slicing) {
    ST st = nullptr;
    KSP ksp = nullptr;
    CATENA_PETSC(EPSGetST(eps, &st));
    CATENA_PETSC(STGetKSP(st, &ksp));
    if (const DirectSolveStatus status = direct_solve_status(ksp); status.failed())
      throw NumericalError(prefix + "eps: a solve of its spectral transformation failed (" +
                           status.describe() + ")");
  }
  EPSConvergedReason reason;
  CATENA_PETSC(EPSGetConvergedReason(eps, &reason));
  PetscInt converged = 0;
  CATENA_PETSC(EPSGetConverged(eps, &converged));
  CATENA_PETSC(EPSGetIterationNumber(eps, iterations));
  if (reason < 0)
    throw NumericalError(prefix + "eps: the eigensolver diverged after " +
                         std::to_string(*iterations) + " Krylov-Schur restarts (EPS reason " +
                         std::to_string(reason) + "), " + std::to_string(converged) +
                         " eigenpairs converged; more with -" + prefix + "eps_max_it");
  return converged;
}

// The first `count` of the `converged` eigenpairs, lowest first, each normalised to unit
// modal mass, with its residual; `make` gives a vector laid out as K's columns.
Modes collect(EPS eps, Mat K, Mat M, PetscInt converged, PetscInt count,
              const std::function<VecHandle()>& make) {
  Modes modes;
  std::vector<double> eigenvalue(static_cast<std::size_t>(converged));
  std::vector<VecHandle> vectors;
  for (PetscInt i = 0; i < converged; ++i) {
    PetscScalar kr = 0.0, ki = 0.0;
    VecHandle x = make();
    CATENA_PETSC(EPSGetEigenpair(eps, i, &kr, &ki, x.get(), nullptr));
    eigenvalue[static_cast<std::size_t>(i)] = PetscRealPart(kr);
    vectors.push_back(std::move(x));
  }
  // Lowest first (the target ordering sorts by |λ|, which for K SPD is the same; sorted
  // anyway so that the output never depends on it).
  std::vector<std::size_t> order(eigenvalue.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return eigenvalue[a] < eigenvalue[b]; });
  VecHandle Mx = make(), Kx = make();
  for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
    const std::size_t i = order[k];
    const double lambda = eigenvalue[i];
    if (!(lambda > 0.0))
      throw NumericalError("modes: eigenvalue " + std::to_string(lambda) +
                           " <= 0 (ω² must be positive at a stable equilibrium): the state is "
                           "unstable or a mechanism");
    Vec x = vectors[i].get();
    CATENA_PETSC(MatMult(M, x, Mx.get()));
    PetscScalar modal_mass = 0.0;
    CATENA_PETSC(VecDot(x, Mx.get(), &modal_mass));
    CATENA_PETSC(VecScale(x, 1.0 / std::sqrt(PetscRealPart(modal_mass))));
    CATENA_PETSC(VecScale(Mx.get(), 1.0 / std::sqrt(PetscRealPart(modal_mass))));
    CATENA_PETSC(MatMult(K, x, Kx.get()));
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

}  // namespace

void refuse_constraints_for_modes(const model::Model& model) {
  if (!model.constraints.empty())
    throw InputError({model.source_file, 0, "constraints"},
                     "modes of a scene with constraints (Lagrange multipliers: constraints, "
                     "rigid bodies' frames, joints, sliders, bilateral contacts) are not "
                     "computed: their mass matrix is singular in the multipliers. Hold the "
                     "nodes with supports ('fix') instead");
  if (!model.absorbing_ends.empty() || (model.catenary && model.catenary->absorbing_ends))
    throw InputError({model.source_file, 0, "absorbing_ends"},
                     "modes of a scene with absorbing ends are not computed: an absorbing end "
                     "is a dashpot, which undamped modes leave out, and its node is free "
                     "without it. For the modes of the cut line, hold its ends with supports "
                     "('fix: pinned'; a catenary: ends: anchored) instead");
}

Modes compute_modes(assembly::SecondOrderSystem& system, Vec q, const ModalOptions& options) {
  refuse_constraints_for_modes(system.model());
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
  // Shift-and-invert about 0: the eigenvalues of K⁻¹M are 1/ω², the lowest modes the
  // largest and best separated ones.
  const EpsHandle eps = make_eps(system.comm(), K.get(), M.get(), options.tolerance, [&](EPS e) {
    CATENA_PETSC(EPSSetDimensions(e, options.count, PETSC_DEFAULT, PETSC_DEFAULT));
    CATENA_PETSC(EPSSetWhichEigenpairs(e, EPS_TARGET_MAGNITUDE));
    CATENA_PETSC(EPSSetTarget(e, 0.0));
  });
  PetscInt iterations = 0;
  const PetscInt converged = solve(eps.get(), &iterations);
  if (converged < options.count)
    throw NumericalError("modes: " + std::to_string(converged) + " of " +
                         std::to_string(options.count) + " modes converged in " +
                         std::to_string(iterations) +
                         " Krylov-Schur restarts; ask for fewer, or more with -modes_eps_max_it");
  Modes modes = collect(eps.get(), K.get(), M.get(), converged, options.count,
                        [&] { return system.create_vector(); });
  modes.n_iterations = static_cast<int>(iterations);
  return modes;
}

Modes compute_modes_below(Mat K, Mat M, const std::vector<PetscInt>& keep, double cutoff, Vec like,
                          const std::string& scene, const std::string& key) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(K));
  IsHandle rows;
  CATENA_PETSC(ISCreateGeneral(comm, static_cast<PetscInt>(keep.size()), keep.data(),
                               PETSC_COPY_VALUES, rows.out()));
  MatHandle K_kept, M_kept;
  CATENA_PETSC(MatCreateSubMatrix(K, rows.get(), rows.get(), MAT_INITIAL_MATRIX, K_kept.out()));
  CATENA_PETSC(MatCreateSubMatrix(M, rows.get(), rows.get(), MAT_INITIAL_MATRIX, M_kept.out()));
  CATENA_PETSC(MatSetOption(K_kept.get(), MAT_SYMMETRIC, PETSC_TRUE));
  CATENA_PETSC(MatSetOption(M_kept.get(), MAT_SYMMETRIC, PETSC_TRUE));
  const double omega = 2.0 * std::numbers::pi * cutoff;
  // Spectrum slicing needs the factorisation's inertia, exact in parallel with ICNTL(13).
  enable_mumps_exact_inertia(std::string(kPrefix) + "st_");
  const EpsHandle eps = make_eps(
      comm, K_kept.get(), M_kept.get(), 1e-10,
      [&](EPS e) {
        CATENA_PETSC(EPSSetWhichEigenpairs(e, EPS_ALL));
        CATENA_PETSC(EPSSetInterval(e, 0.0, omega * omega));
      },
      true);
  PetscInt iterations = 0;
  const PetscInt converged = solve(eps.get(), &iterations, true);
  if (converged == 0)
    throw InputError({scene, 0, key}, "no vibration mode below " + std::to_string(cutoff) +
                                          " Hz: raise the cut-off frequency");
  Modes kept = collect(eps.get(), K_kept.get(), M_kept.get(), converged, converged, [&] {
    VecHandle x;
    CATENA_PETSC(MatCreateVecs(K_kept.get(), x.out(), nullptr));
    return x;
  });
  Modes modes;
  modes.frequency = std::move(kept.frequency);
  modes.residual = std::move(kept.residual);
  modes.n_iterations = static_cast<int>(iterations);
  for (const VecHandle& shape : kept.shape) {
    VecHandle full;
    CATENA_PETSC(VecDuplicate(like, full.out()));
    CATENA_PETSC(VecSet(full.get(), 0.0));
    Vec part = nullptr;
    CATENA_PETSC(VecGetSubVector(full.get(), rows.get(), &part));
    CATENA_PETSC(VecCopy(shape.get(), part));
    CATENA_PETSC(VecRestoreSubVector(full.get(), rows.get(), &part));
    modes.shape.push_back(std::move(full));
  }
  return modes;
}

double highest_frequency(Mat K, Mat M) {
  ensure_slepc();
  MPI_Comm comm = MPI_COMM_NULL;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(K), &comm));
  EpsHandle eps;
  CATENA_PETSC(EPSCreate(comm, eps.out()));
  // A Ritz value's error is of the order of its residual squared: 1e-5 gives ω_max to
  // about 1e-10 (EN 50318: 6 digits the same from 1e-3 to 1e-6, 1e-8 took 1500 restarts of
  // a clustered spectrum where 1e-5 takes tens). The shift: M⁻¹K itself, largest first.
  KSP ksp = krylov_schur(eps.get(), K, M, STSHIFT, 1e-5, 10000);
  CATENA_PETSC(EPSSetWhichEigenpairs(eps.get(), EPS_LARGEST_MAGNITUDE));
  CATENA_PETSC(EPSSetDimensions(eps.get(), 1, PETSC_DEFAULT, PETSC_DEFAULT));
  CATENA_PETSC(EPSSetOptionsPrefix(eps.get(), "highest_"));
  CATENA_PETSC(EPSSetFromOptions(eps.get()));
  CATENA_PETSC(EPSSetUp(eps.get()));
  if (const DirectSolveStatus factor = direct_solve_status(ksp); factor.failed())
    throw NumericalError("the mass matrix cannot be factored (" + factor.describe() +
                         "): a DOF without mass has no highest frequency");
  PetscInt iterations = 0;
  if (solve(eps.get(), &iterations, false) < 1)
    throw NumericalError("the highest frequency did not converge in " + std::to_string(iterations) +
                         " Krylov-Schur restarts");
  PetscScalar kr = 0.0, ki = 0.0;
  CATENA_PETSC(EPSGetEigenpair(eps.get(), 0, &kr, &ki, nullptr, nullptr));
  return std::sqrt(std::max(0.0, static_cast<double>(PetscRealPart(kr))));
}

}  // namespace catena::solvers

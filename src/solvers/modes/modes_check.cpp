#include "catena/solvers/modes/modes_check.hpp"

#include <petscksp.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/petsc_handle.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/newton/mumps_status.hpp"

namespace catena::solvers {
namespace {

constexpr const char* kPrefix = "modes_check_";

// The number of eigenvalues of K φ = λ M φ over `keep` below `lambda`: the negative pivots
// of the LDLᵀ of K − λ M (Sylvester's law of inertia).
long eigenvalues_below(Mat K, Mat M, const std::vector<PetscInt>& keep, double lambda) {
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(K));
  IsHandle rows;
  CATENA_PETSC(ISCreateGeneral(comm, static_cast<PetscInt>(keep.size()), keep.data(),
                               PETSC_COPY_VALUES, rows.out()));
  MatHandle shifted, M_kept;
  CATENA_PETSC(MatCreateSubMatrix(K, rows.get(), rows.get(), MAT_INITIAL_MATRIX, shifted.out()));
  CATENA_PETSC(MatCreateSubMatrix(M, rows.get(), rows.get(), MAT_INITIAL_MATRIX, M_kept.out()));
  CATENA_PETSC(MatAXPY(shifted.get(), -lambda, M_kept.get(), DIFFERENT_NONZERO_PATTERN));
  CATENA_PETSC(MatSetOption(shifted.get(), MAT_SYMMETRIC, PETSC_TRUE));
  KspHandle ksp;
  CATENA_PETSC(KSPCreate(comm, ksp.out()));
  CATENA_PETSC(KSPSetOperators(ksp.get(), shifted.get(), shifted.get()));
  CATENA_PETSC(KSPSetType(ksp.get(), KSPPREONLY));
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp.get(), &pc));
  CATENA_PETSC(PCSetType(pc, PCCHOLESKY));
  CATENA_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  CATENA_PETSC(KSPSetOptionsPrefix(ksp.get(), kPrefix));
  enable_mumps_exact_inertia(kPrefix);
  discard_mumps_factors(kPrefix);
  CATENA_PETSC(KSPSetFromOptions(ksp.get()));
  CATENA_PETSC(KSPSetUp(ksp.get()));
  const DirectSolveStatus status = direct_solve_status(ksp.get());
  if (status.failed() || !status.mumps.symmetric)
    throw NumericalError("modal basis check: the LDLᵀ of K − ω²M at the cut-off failed (" +
                         status.describe() + ")");
  return status.mumps.negative_pivots;
}

}  // namespace

std::string modes_mismatch(Mat K, Mat M, const std::vector<PetscInt>& keep, double cutoff,
                           const std::vector<double>& frequency, const std::vector<Vec>& shapes,
                           double tolerance) {
  CATENA_ASSERT(frequency.size() == shapes.size(), "a frequency per shape");
  std::ostringstream why;
  if (!shapes.empty()) {
    VecHandle Mx, Kx;
    CATENA_PETSC(VecDuplicate(shapes.front(), Mx.out()));
    CATENA_PETSC(VecDuplicate(shapes.front(), Kx.out()));
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      const double omega = 2.0 * std::numbers::pi * frequency[i];
      const double lambda = omega * omega;
      CATENA_PETSC(MatMult(M, shapes[i], Mx.get()));
      // M-orthogonal to the mode before (the next lower frequency): a mode stored twice,
      // which would pass the residual and the count, is not.
      if (i > 0) {
        PetscScalar overlap = 0.0;
        CATENA_PETSC(VecDot(shapes[i - 1], Mx.get(), &overlap));
        if (!(std::abs(PetscRealPart(overlap)) <= tolerance)) {
          why << "modes " << i << " and " << i + 1
              << " are not M-orthogonal (φᵀ M φ' = " << PetscRealPart(overlap) << ")";
          return why.str();
        }
      }
      CATENA_PETSC(MatMult(K, shapes[i], Kx.get()));
      PetscScalar modal_mass = 0.0;
      PetscReal mass_norm = 0.0, miss = 0.0;
      CATENA_PETSC(VecDot(shapes[i], Mx.get(), &modal_mass));
      CATENA_PETSC(VecNorm(Mx.get(), NORM_2, &mass_norm));
      CATENA_PETSC(VecAXPY(Kx.get(), -lambda, Mx.get()));
      CATENA_PETSC(VecNorm(Kx.get(), NORM_2, &miss));
      const double residual = miss / (lambda * mass_norm);
      if (!(residual <= tolerance) || !(std::abs(PetscRealPart(modal_mass) - 1.0) <= tolerance)) {
        why << "mode " << i + 1 << " (" << frequency[i] << " Hz) is not a mode of this scene's "
            << "structure: relative residual " << residual << ", modal mass "
            << PetscRealPart(modal_mass) << " kg (tolerance " << tolerance << ")";
        return why.str();
      }
    }
  }
  const double omega = 2.0 * std::numbers::pi * cutoff;
  const long below = eigenvalues_below(K, M, keep, omega * omega);
  if (below != static_cast<long>(shapes.size())) {
    why << "this scene's structure has " << below << " modes below " << cutoff << " Hz, the "
        << "basis " << shapes.size();
    return why.str();
  }
  return {};
}

}  // namespace catena::solvers

#include "catena/solvers/newton/mumps_status.hpp"

#include <petscmat.h>

#include <algorithm>
#include <cstring>

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers {

namespace {
// Not collective. Whether pc factors with MUMPS (LU or Cholesky), and if so whether Cholesky.
bool factors_with_mumps(PC pc, bool* cholesky = nullptr) {
  PetscBool is_lu = PETSC_FALSE, is_cholesky = PETSC_FALSE;
  CATENA_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCLU, &is_lu));
  CATENA_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCCHOLESKY, &is_cholesky));
  if (cholesky) *cholesky = is_cholesky;
  if (!is_lu && !is_cholesky) return false;
  MatSolverType type = nullptr;
  CATENA_PETSC(PCFactorGetMatSolverType(pc, &type));
  return type && std::strcmp(type, MATSOLVERMUMPS) == 0;
}
}  // namespace

MumpsStatus mumps_status(KSP ksp) {
  MumpsStatus status;
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  bool is_cholesky = false;
  if (!factors_with_mumps(pc, &is_cholesky)) return status;
  Mat factor = nullptr;
  CATENA_PETSC(PCFactorGetMatrix(pc, &factor));
  PetscInt v1 = 0, v2 = 0, v12 = 0, v28 = 0;
  CATENA_PETSC(MatMumpsGetInfog(factor, 1, &v1));
  CATENA_PETSC(MatMumpsGetInfog(factor, 2, &v2));
  CATENA_PETSC(MatMumpsGetInfog(factor, 12, &v12));
  CATENA_PETSC(MatMumpsGetInfog(factor, 28, &v28));
  status.is_mumps = true;
  status.infog1 = v1;
  status.infog2 = v2;
  status.null_pivots = v28;
  status.symmetric = is_cholesky;
  status.negative_pivots = is_cholesky ? v12 : 0;
  return status;
}

std::string DirectSolveStatus::describe() const {
  std::string text = "KSP reason " + std::string(KSPConvergedReasons[reason]);
  if (preconditioner != PC_NOERROR)
    text += ", preconditioner failed: " + std::string(PCFailedReasons[preconditioner]);
  if (mumps.is_mumps)
    text += ", MUMPS INFOG(1) = " + std::to_string(mumps.infog1) +
            ", INFOG(2) = " + std::to_string(mumps.infog2) + ", " +
            std::to_string(mumps.null_pivots) + " null pivots";
  return text;
}

DirectSolveStatus direct_solve_status(KSP ksp) {
  DirectSolveStatus status;
  CATENA_PETSC(KSPGetConvergedReason(ksp, &status.reason));
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  CATENA_PETSC(PCGetFailedReason(pc, &status.preconditioner));
  status.mumps = mumps_status(ksp);
  return status;
}

bool enlarge_mumps_workspace(KSP ksp, const DirectSolveStatus& status) {
  const long code = status.mumps.infog1;
  if (!status.mumps.is_mumps ||
      !(code == -8 || code == -9 || code == -14 || code == -17 || code == -20))
    return false;
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  Mat factor = nullptr;
  CATENA_PETSC(PCFactorGetMatrix(pc, &factor));
  PetscInt margin = 0;
  CATENA_PETSC(MatMumpsGetIcntl(factor, 14, &margin));
  if (margin >= 1600) return false;
  // MUMPS sizes its workspace in the analysis, so a larger margin needs a new factor: the PC
  // reset (it keeps its type and solver), the operators set again, a new factor made now
  // and given the margin, so that the next set-up analyses and factors with it. Not through
  // the options database, which would outlive this solver (a study's next case).
  Mat A = nullptr, P = nullptr;
  CATENA_PETSC(KSPGetOperators(ksp, &A, &P));
  CATENA_PETSC(PetscObjectReference(reinterpret_cast<PetscObject>(A)));
  CATENA_PETSC(PetscObjectReference(reinterpret_cast<PetscObject>(P)));
  CATENA_PETSC(PCReset(pc));
  CATENA_PETSC(KSPSetOperators(ksp, A, P));
  CATENA_PETSC(MatDestroy(&A));
  CATENA_PETSC(MatDestroy(&P));
  CATENA_PETSC(PCFactorSetUpMatSolverType(pc));
  CATENA_PETSC(PCFactorGetMatrix(pc, &factor));
  CATENA_PETSC(MatMumpsSetIcntl(factor, 14, std::max<PetscInt>(2 * margin, margin + 100)));
  return true;
}

namespace {
// Sets -<prefix><option> to `value` unless the user gave it.
void set_default_option(const std::string& prefix, const char* option, const char* value) {
  const std::string name = "-" + prefix + option;
  PetscBool set = PETSC_FALSE;
  CATENA_PETSC(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &set));
  if (!set) CATENA_PETSC(PetscOptionsSetValue(nullptr, name.c_str(), value));
}
}  // namespace

void enable_mumps_null_pivot_detection(const std::string& prefix) {
  set_default_option(prefix, "mat_mumps_icntl_24", "1");
}

void enable_mumps_exact_inertia(const std::string& prefix) {
  set_default_option(prefix, "mat_mumps_icntl_13", "1");
}

void scale_mumps_at_each_factorisation(const std::string& prefix) {
  set_default_option(prefix, "mat_mumps_icntl_8", "7");
}

void scale_mumps_factor_at_each_factorisation(KSP ksp, const std::string& prefix) {
  const std::string option = "-" + prefix + "mat_mumps_icntl_8";
  PetscBool set = PETSC_FALSE;
  CATENA_PETSC(PetscOptionsHasName(nullptr, nullptr, option.c_str(), &set));
  if (set) return;
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  if (!factors_with_mumps(pc)) return;
  // The factor made now keeps the setting for the PC's later factorisations (as in
  // enlarge_mumps_workspace). It takes its options prefix from the matrix, which other
  // solvers may share (the stability check's): set to this solver's first.
  Mat A = nullptr, P = nullptr;
  CATENA_PETSC(KSPGetOperators(ksp, &A, &P));
  CATENA_PETSC(MatSetOptionsPrefixFactor(P, prefix.c_str()));
  CATENA_PETSC(PCFactorSetUpMatSolverType(pc));
  Mat factor = nullptr;
  CATENA_PETSC(PCFactorGetMatrix(pc, &factor));
  CATENA_PETSC(MatMumpsSetIcntl(factor, 8, 7));
}

void discard_mumps_factors(const std::string& prefix) {
  set_default_option(prefix, "mat_mumps_icntl_31", "1");
}

}  // namespace catena::solvers

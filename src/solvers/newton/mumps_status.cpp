#include "catena/solvers/newton/mumps_status.hpp"

#include <petscmat.h>

#include <cstring>

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers {

MumpsStatus mumps_status(KSP ksp) {
  MumpsStatus status;
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  PetscBool is_lu = PETSC_FALSE, is_cholesky = PETSC_FALSE;
  CATENA_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCLU, &is_lu));
  CATENA_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCCHOLESKY, &is_cholesky));
  if (!is_lu && !is_cholesky) return status;
  MatSolverType type = nullptr;
  CATENA_PETSC(PCFactorGetMatSolverType(pc, &type));
  if (!type || std::strcmp(type, MATSOLVERMUMPS) != 0) return status;
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
  if (mumps.is_mumps)
    text += ", MUMPS INFOG(1) = " + std::to_string(mumps.infog1) +
            ", INFOG(2) = " + std::to_string(mumps.infog2) + ", " +
            std::to_string(mumps.null_pivots) + " null pivots";
  return text;
}

DirectSolveStatus direct_solve_status(KSP ksp) {
  DirectSolveStatus status;
  CATENA_PETSC(KSPGetConvergedReason(ksp, &status.reason));
  status.mumps = mumps_status(ksp);
  return status;
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

}  // namespace catena::solvers

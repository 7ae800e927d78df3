#include "catena/solvers/direct_newton.hpp"

#include "catena/assembly/petsc_call.hpp"
#include "catena/solvers/mumps_status.hpp"

namespace catena::solvers {

void configure_direct_newton(SNES snes, const std::string& prefix, JacobianSymmetry symmetry) {
  CATENA_PETSC(SNESSetOptionsPrefix(snes, prefix.c_str()));
  CATENA_PETSC(SNESSetType(snes, SNESNEWTONLS));
  SNESLineSearch line_search = nullptr;
  CATENA_PETSC(SNESGetLineSearch(snes, &line_search));
  CATENA_PETSC(SNESLineSearchSetType(line_search, SNESLINESEARCHBASIC));
  // Transient residual growth is normal in full Newton; non-convergence is caught by the
  // iteration limit and NaN checks.
  CATENA_PETSC(SNESSetDivergenceTolerance(snes, -1.0));
  KSP ksp = nullptr;
  PC pc = nullptr;
  CATENA_PETSC(SNESGetKSP(snes, &ksp));
  CATENA_PETSC(KSPSetType(ksp, KSPPREONLY));
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  CATENA_PETSC(PCSetType(pc, symmetry == JacobianSymmetry::symmetric ? PCCHOLESKY : PCLU));
  CATENA_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  enable_mumps_null_pivot_detection(prefix);
  CATENA_PETSC(SNESSetFromOptions(snes));
}

}  // namespace catena::solvers

namespace catena::solvers {

KspHandle create_direct_ksp(MPI_Comm comm, const std::string& prefix, JacobianSymmetry symmetry) {
  KspHandle ksp;
  CATENA_PETSC(KSPCreate(comm, ksp.out()));
  CATENA_PETSC(KSPSetOptionsPrefix(ksp.get(), prefix.c_str()));
  CATENA_PETSC(KSPSetType(ksp.get(), KSPPREONLY));
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp.get(), &pc));
  CATENA_PETSC(PCSetType(pc, symmetry == JacobianSymmetry::symmetric ? PCCHOLESKY : PCLU));
  CATENA_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  enable_mumps_null_pivot_detection(prefix);
  CATENA_PETSC(KSPSetFromOptions(ksp.get()));
  return ksp;
}

}  // namespace catena::solvers

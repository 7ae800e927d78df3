#include "catena/solvers/newton/direct_newton.hpp"

#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/newton/constraints_last_ordering.hpp"
#include "catena/solvers/newton/interface_schur.hpp"
#include "catena/solvers/newton/mumps_status.hpp"

namespace catena::solvers {
namespace {

// Not collective. The factorisation package the options name, and the option that names
// it (either of PETSc's names; its value in any case); both "" when none does.
struct ChosenPackage {
  std::string option, package;
  bool petsc() const {
    PetscBool same = PETSC_FALSE;
    if (!package.empty()) CATENA_PETSC(PetscStrcasecmp(package.c_str(), MATSOLVERPETSC, &same));
    return same == PETSC_TRUE;
  }
};

ChosenPackage package_from_options(const std::string& prefix) {
  for (const char* name : {"pc_factor_mat_solver_type", "pc_factor_mat_solver_package"}) {
    const std::string option = "-" + prefix + name;
    char package[64] = "";
    PetscBool set = PETSC_FALSE;
    CATENA_PETSC(
        PetscOptionsGetString(nullptr, nullptr, option.c_str(), package, sizeof package, &set));
    if (set) return {option, package};
  }
  return {};
}

// Collective on the PC. The factorisation type and package for `symmetry` and `pivoting`.
void set_direct_factorisation(PC pc, const std::string& prefix, JacobianSymmetry symmetry,
                              Pivoting pivoting) {
  CATENA_PETSC(PCSetType(pc, symmetry == JacobianSymmetry::symmetric ? PCCHOLESKY : PCLU));
  MPI_Comm comm = MPI_COMM_NULL;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(pc), &comm));
  int size = 1;
  MPI_Comm_size(comm, &size);
  // PETSc's LU orders by nested dissection by default. No ordering is set here: an
  // explicit one is handed to MUMPS as well when the options switch to it, and MUMPS's
  // factors then filled in almost completely (226 s for one factorisation of the EN 50318
  // line instead of 0.02 s).
  const bool constraints_last = pivoting == Pivoting::constraints_last && size == 1;
  CATENA_PETSC(PCFactorSetMatSolverType(
      pc, (pivoting == Pivoting::not_needed && size == 1) || constraints_last ? MATSOLVERPETSC
                                                                              : MATSOLVERMUMPS));
  enable_mumps_null_pivot_detection(prefix);  // in case the options choose MUMPS
  // The multipliers-last order is PETSc's LU's only: unless the options choose another
  // package (which would be handed the order as well).
  const ChosenPackage chosen = package_from_options(prefix);
  if (constraints_last && (chosen.package.empty() || chosen.petsc()))
    CATENA_PETSC(PCFactorSetMatOrderingType(pc, constraints_last_ordering()));
  if (pivoting == Pivoting::required && chosen.petsc())
    throw InputError({"", 0, chosen.option},
                     "'" + chosen.package +
                         "': PETSc's LU does not pivot, and this Newton matrix has the zero "
                         "diagonal rows of Lagrange multipliers (joints, rigid bodies, "
                         "constraints); accepted: a pivoting package, e.g. mumps (the default)");
}

}  // namespace

void configure_direct_newton(SNES snes, const std::string& prefix, JacobianSymmetry symmetry,
                             Pivoting pivoting) {
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
  set_direct_factorisation(pc, prefix, symmetry, pivoting);
  MPI_Comm comm = MPI_COMM_NULL;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(snes), &comm));
  if (use_interface_split(comm, prefix, pivoting)) {
    Mat J = nullptr;
    CATENA_PETSC(SNESGetJacobian(snes, &J, nullptr, nullptr, nullptr));
    use_interface_schur(ksp, J);
  }
  CATENA_PETSC(SNESSetFromOptions(snes));
}

namespace {
// Whether the KSP's PC factors without pivoting: PETSc's LU, or on more ranks the interface
// Schur solve (a shell PC) of PETSc's LUs.
bool factors_unpivoted(PC pc) {
  PetscBool petsc = PETSC_FALSE;
  CATENA_PETSC(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCSHELL, &petsc));
  if (!petsc) {
    MatSolverType package = nullptr;
    CATENA_PETSC(PCFactorGetMatSolverType(pc, &package));
    if (package) CATENA_PETSC(PetscStrcmp(package, MATSOLVERPETSC, &petsc));
  }
  return petsc == PETSC_TRUE;
}
}  // namespace

bool switch_to_pivoting(KSP ksp, const std::string& prefix, JacobianSymmetry symmetry) {
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  if (!factors_unpivoted(pc) || !package_from_options(prefix).package.empty()) return false;
  // A PC of another type first, so that the factorisation's settings (the order) start
  // afresh; the options are applied again.
  CATENA_PETSC(PCReset(pc));
  CATENA_PETSC(PCSetType(pc, PCNONE));
  set_direct_factorisation(pc, prefix, symmetry, Pivoting::required);
  CATENA_PETSC(KSPSetFromOptions(ksp));
  return true;
}

bool fall_back_to_pivoting(KSP ksp, const std::string& prefix, JacobianSymmetry symmetry) {
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  PCFailedReason failed = PC_NOERROR;
  CATENA_PETSC(PCGetFailedReason(pc, &failed));
  if (failed != PC_FACTOR_NUMERIC_ZEROPIVOT || !switch_to_pivoting(ksp, prefix, symmetry))
    return false;
  MPI_Comm comm = MPI_COMM_NULL;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(ksp), &comm));
  CATENA_PETSC(PetscPrintf(
      comm,
      "note: %s: PETSc's LU of the Newton matrix met a zero pivot with the multipliers taken "
      "last (dependent constraints, or an unknown only a constraint holds, e.g. a slider on a "
      "straight path); MUMPS, which pivots, factors it from here on\n",
      prefix.empty() ? "newton" : prefix.substr(0, prefix.size() - 1).c_str()));
  return true;
}

bool use_interface_split(MPI_Comm comm, const std::string& prefix, Pivoting pivoting) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (size == 1 || (pivoting != Pivoting::not_needed && pivoting != Pivoting::constraints_last))
    return false;
  for (const char* option : {"pc_type", "pc_factor_mat_solver_type"}) {
    PetscBool set = PETSC_FALSE;
    CATENA_PETSC(PetscOptionsHasName(nullptr, nullptr, ("-" + prefix + option).c_str(), &set));
    if (set) return false;
  }
  return true;
}

KspHandle create_direct_ksp(MPI_Comm comm, const std::string& prefix, JacobianSymmetry symmetry,
                            Pivoting pivoting, Mat split) {
  KspHandle ksp;
  CATENA_PETSC(KSPCreate(comm, ksp.out()));
  CATENA_PETSC(KSPSetOptionsPrefix(ksp.get(), prefix.c_str()));
  CATENA_PETSC(KSPSetType(ksp.get(), KSPPREONLY));
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp.get(), &pc));
  set_direct_factorisation(pc, prefix, symmetry, pivoting);
  if (split && use_interface_split(comm, prefix, pivoting)) use_interface_schur(ksp.get(), split);
  CATENA_PETSC(KSPSetFromOptions(ksp.get()));
  return ksp;
}

}  // namespace catena::solvers

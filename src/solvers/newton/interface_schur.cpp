#include "catena/solvers/newton/interface_schur.hpp"

#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/petsc_handle.hpp"
#include "catena/solvers/newton/direct_newton.hpp"

namespace catena::solvers {
namespace {

constexpr const char* kInteriorKey = "catena_interior_rows";
constexpr const char* kInterfaceKey = "catena_interface_rows";

// The PC as the interface split of the composed index sets, S formed explicitly.
void set_splits(PC pc) {
  PetscObject interior = nullptr, interface = nullptr;
  CATENA_PETSC(PetscObjectQuery(reinterpret_cast<PetscObject>(pc), kInteriorKey, &interior));
  CATENA_PETSC(PetscObjectQuery(reinterpret_cast<PetscObject>(pc), kInterfaceKey, &interface));
  CATENA_PETSC(PCSetType(pc, PCFIELDSPLIT));
  CATENA_PETSC(PCFieldSplitSetIS(pc, "interior", reinterpret_cast<IS>(interior)));
  CATENA_PETSC(PCFieldSplitSetIS(pc, "interface", reinterpret_cast<IS>(interface)));
  CATENA_PETSC(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR));
  CATENA_PETSC(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_FULL));
  CATENA_PETSC(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_FULL, nullptr));
}

}  // namespace

void refresh_interface_schur(KSP ksp) {
  PC old = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &old));
  PetscObject interior = nullptr, interface = nullptr;
  CATENA_PETSC(PetscObjectQuery(reinterpret_cast<PetscObject>(old), kInteriorKey, &interior));
  CATENA_PETSC(PetscObjectQuery(reinterpret_cast<PetscObject>(old), kInterfaceKey, &interface));
  if (!interior) return;
  // PETSc 3.18 keeps the explicit S of the first set-up when the matrix changes (the
  // solve is then no longer exact: tests/mpi/test_solvers_interface_schur.cpp), and a
  // PCReset leaves the split unusable: a fresh PC forms S again with the new factors.
  MPI_Comm comm = MPI_COMM_NULL;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(old), &comm));
  const char* prefix = nullptr;
  CATENA_PETSC(PCGetOptionsPrefix(old, &prefix));
  Mat A = nullptr, P = nullptr;
  CATENA_PETSC(PCGetOperators(old, &A, &P));
  PC pc = nullptr;
  CATENA_PETSC(PCCreate(comm, &pc));
  CATENA_PETSC(PCSetOptionsPrefix(pc, prefix));
  CATENA_PETSC(PetscObjectCompose(reinterpret_cast<PetscObject>(pc), kInteriorKey, interior));
  CATENA_PETSC(PetscObjectCompose(reinterpret_cast<PetscObject>(pc), kInterfaceKey, interface));
  set_splits(pc);
  CATENA_PETSC(PCSetFromOptions(pc));
  CATENA_PETSC(PCSetOperators(pc, A, P));
  CATENA_PETSC(KSPSetPC(ksp, pc));  // the KSP takes a reference; the old PC goes
  CATENA_PETSC(PCDestroy(&pc));
}

// Rows coupled to more than this many unknowns of other ranks are hubs: a pantograph's,
// whose contact can reach any element of its contact wire (the pattern holds them all).
// A hub joins the interface alone; its neighbours need not.
constexpr PetscInt kHubColumns = 64;

long use_interface_schur(KSP ksp, Mat J, const std::string& prefix) {
  MPI_Comm comm = MPI_COMM_NULL;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(J), &comm));
  PetscInt first = 0, end = 0;
  CATENA_PETSC(MatGetOwnershipRange(J, &first, &end));
  // The off-process block's pattern (garray: its columns' global numbers). Every coupling
  // between ranks is an entry there, in the row of one rank or the other; the interface
  // must hold one end of each: the hubs, and every other row with an entry to a non-hub.
  Mat diagonal = nullptr, off = nullptr;
  const PetscInt* garray = nullptr;
  CATENA_PETSC(MatMPIAIJGetSeqAIJ(J, &diagonal, &off, &garray));
  PetscInt n_rows = 0, n_columns = 0;
  CATENA_PETSC(MatGetSize(off, nullptr, &n_columns));
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscBool done = PETSC_FALSE;
  CATENA_PETSC(MatGetRowIJ(off, 0, PETSC_FALSE, PETSC_FALSE, &n_rows, &ia, &ja, &done));
  VecHandle hubs;
  CATENA_PETSC(MatCreateVecs(J, hubs.out(), nullptr));
  {
    PetscScalar* h = nullptr;
    CATENA_PETSC(VecGetArray(hubs.get(), &h));
    for (PetscInt i = 0; i < n_rows; ++i) h[i] = ia[i + 1] - ia[i] > kHubColumns ? 1.0 : 0.0;
    CATENA_PETSC(VecRestoreArray(hubs.get(), &h));
  }
  // Whether each off-process column is a hub, from its owner.
  VecHandle column_hubs;
  CATENA_PETSC(VecCreateSeq(PETSC_COMM_SELF, n_columns, column_hubs.out()));
  {
    IS from = nullptr;
    CATENA_PETSC(ISCreateGeneral(PETSC_COMM_SELF, n_columns, garray, PETSC_USE_POINTER, &from));
    VecScatter scatter = nullptr;
    CATENA_PETSC(VecScatterCreate(hubs.get(), from, column_hubs.get(), nullptr, &scatter));
    CATENA_PETSC(
        VecScatterBegin(scatter, hubs.get(), column_hubs.get(), INSERT_VALUES, SCATTER_FORWARD));
    CATENA_PETSC(
        VecScatterEnd(scatter, hubs.get(), column_hubs.get(), INSERT_VALUES, SCATTER_FORWARD));
    CATENA_PETSC(VecScatterDestroy(&scatter));
    CATENA_PETSC(ISDestroy(&from));
  }
  std::vector<PetscInt> interior, interface;
  {
    const PetscScalar *h = nullptr, *column_hub = nullptr;
    CATENA_PETSC(VecGetArrayRead(hubs.get(), &h));
    CATENA_PETSC(VecGetArrayRead(column_hubs.get(), &column_hub));
    for (PetscInt i = 0; i < n_rows; ++i) {
      bool shared = h[i] > 0.0;
      for (PetscInt k = ia[i]; k < ia[i + 1] && !shared; ++k) shared = column_hub[ja[k]] == 0.0;
      (shared ? interface : interior).push_back(first + i);
    }
    CATENA_PETSC(VecRestoreArrayRead(column_hubs.get(), &column_hub));
    CATENA_PETSC(VecRestoreArrayRead(hubs.get(), &h));
  }
  CATENA_PETSC(MatRestoreRowIJ(off, 0, PETSC_FALSE, PETSC_FALSE, &n_rows, &ia, &ja, &done));
  IS is_interior = nullptr, is_interface = nullptr;
  CATENA_PETSC(ISCreateGeneral(comm, static_cast<PetscInt>(interior.size()), interior.data(),
                               PETSC_COPY_VALUES, &is_interior));
  CATENA_PETSC(ISCreateGeneral(comm, static_cast<PetscInt>(interface.size()), interface.data(),
                               PETSC_COPY_VALUES, &is_interface));
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  // The splits stay with the PC (composed), for refresh_interface_schur.
  CATENA_PETSC(PetscObjectCompose(reinterpret_cast<PetscObject>(pc), kInteriorKey,
                                  reinterpret_cast<PetscObject>(is_interior)));
  CATENA_PETSC(PetscObjectCompose(reinterpret_cast<PetscObject>(pc), kInterfaceKey,
                                  reinterpret_cast<PetscObject>(is_interface)));
  CATENA_PETSC(ISDestroy(&is_interior));
  CATENA_PETSC(ISDestroy(&is_interface));
  set_default_option(prefix, "fieldsplit_interior_ksp_type", "preonly");
  set_default_option(prefix, "fieldsplit_interior_pc_type", "bjacobi");
  set_default_option(prefix, "fieldsplit_interior_sub_pc_type", "lu");
  set_default_option(prefix, "fieldsplit_interface_ksp_type", "preonly");
  set_default_option(prefix, "fieldsplit_interface_pc_type", "redundant");
  set_default_option(prefix, "fieldsplit_interface_redundant_pc_type", "lu");
  set_splits(pc);
  CATENA_PETSC(KSPSetFromOptions(ksp));
  long n_interface = static_cast<long>(interface.size()), total = 0;
  MPI_Allreduce(&n_interface, &total, 1, MPI_LONG, MPI_SUM, comm);
  return total;
}

}  // namespace catena::solvers

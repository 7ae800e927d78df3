// The interface Schur solve (solvers/newton/interface_schur.hpp) on 1, 2 and 3 ranks: a
// block-tridiagonal chain (a line, 4 unknowns per node) with one hub row and column
// coupled to every unknown (a pantograph's, whose contact pattern reaches the whole
// contact wire). The split must keep the interface to the hub and the rows next to each
// cut, and its preonly solve must be exact: A x = b to round-off, the same x as LU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/petsc_handle.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/solvers/newton/interface_schur.hpp"
#include "petsc_test_session.hpp"

namespace {

constexpr PetscInt kBlock = 4, kNodes = 300, kRows = kBlock * kNodes + 1;  // + the hub

// Nonsymmetric, diagonally dominant: the chain's blocks couple neighbours only.
catena::MatHandle chain_with_hub() {
  catena::MatHandle A;
  CATENA_PETSC(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, kRows, kRows, 13, nullptr,
                            13, nullptr, A.out()));
  CATENA_PETSC(MatSetOption(A.get(), MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscInt first = 0, end = 0;
  CATENA_PETSC(MatGetOwnershipRange(A.get(), &first, &end));
  const PetscInt hub = kRows - 1;
  for (PetscInt i = first; i < end; ++i) {
    if (i == hub) {
      for (PetscInt j = 0; j < kRows; ++j)
        CATENA_PETSC(MatSetValue(A.get(), i, j, i == j ? 4.0 * kRows : 0.5, INSERT_VALUES));
      continue;
    }
    const PetscInt node = i / kBlock;
    for (PetscInt other = std::max<PetscInt>(0, node - 1);
         other <= std::min<PetscInt>(kNodes - 1, node + 1); ++other)
      for (PetscInt c = 0; c < kBlock; ++c) {
        const PetscInt j = kBlock * other + c;
        const double value = i == j ? 20.0 : 1.0 / (1.0 + static_cast<double>(i + 2 * j % 7));
        CATENA_PETSC(MatSetValue(A.get(), i, j, value, INSERT_VALUES));
      }
    CATENA_PETSC(MatSetValue(A.get(), i, hub, 0.25, INSERT_VALUES));
  }
  CATENA_PETSC(MatAssemblyBegin(A.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(A.get(), MAT_FINAL_ASSEMBLY));
  return A;
}

}  // namespace

TEST(InterfaceSchur, SolvesExactlyWithAnInterfaceOfTheHubAndTheCuts) {
  catena::test::ensure_petsc();
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  if (size == 1) GTEST_SKIP() << "one rank has no interface (HHT uses PETSc's LU there)";
  catena::MatHandle A = chain_with_hub();
  catena::VecHandle x_true, b, x, r;
  CATENA_PETSC(MatCreateVecs(A.get(), x_true.out(), b.out()));
  CATENA_PETSC(VecDuplicate(x_true.get(), x.out()));
  CATENA_PETSC(VecDuplicate(x_true.get(), r.out()));
  PetscInt first = 0, end = 0;
  CATENA_PETSC(VecGetOwnershipRange(x_true.get(), &first, &end));
  for (PetscInt i = first; i < end; ++i)
    CATENA_PETSC(VecSetValue(x_true.get(), i, std::sin(0.37 * static_cast<double>(i)) + 0.1 * i,
                             INSERT_VALUES));
  CATENA_PETSC(VecAssemblyBegin(x_true.get()));
  CATENA_PETSC(VecAssemblyEnd(x_true.get()));
  CATENA_PETSC(MatMult(A.get(), x_true.get(), b.get()));

  catena::KspHandle ksp;
  CATENA_PETSC(KSPCreate(PETSC_COMM_WORLD, ksp.out()));
  CATENA_PETSC(KSPSetOptionsPrefix(ksp.get(), "schur_test_"));
  CATENA_PETSC(KSPSetType(ksp.get(), KSPPREONLY));
  CATENA_PETSC(KSPSetOperators(ksp.get(), A.get(), A.get()));
  const long interface = catena::solvers::use_interface_schur(ksp.get(), A.get());
  // The hub, and at each of the size − 1 cuts the rows reaching across: one node on each
  // side, or three nodes' rows where the cut splits a node.
  EXPECT_GE(interface, 1 + 2 * kBlock * (size - 1));
  EXPECT_LE(interface, 1 + 3 * kBlock * (size - 1));
  CATENA_PETSC(KSPSolve(ksp.get(), b.get(), x.get()));
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  CATENA_PETSC(KSPGetConvergedReason(ksp.get(), &reason));
  EXPECT_GT(reason, 0);
  PetscReal error = 0.0, scale = 0.0;
  CATENA_PETSC(VecNorm(x_true.get(), NORM_INFINITY, &scale));
  CATENA_PETSC(VecAXPY(x.get(), -1.0, x_true.get()));
  CATENA_PETSC(VecNorm(x.get(), NORM_INFINITY, &error));
  EXPECT_LT(error, 1e-12 * scale);

  // A changed matrix of the same pattern (a refreshed Newton matrix) is factored again.
  CATENA_PETSC(MatScale(A.get(), 0.5));
  CATENA_PETSC(MatShift(A.get(), 3.0));
  CATENA_PETSC(MatMult(A.get(), x_true.get(), b.get()));
  CATENA_PETSC(KSPSetOperators(ksp.get(), A.get(), A.get()));
  CATENA_PETSC(KSPSolve(ksp.get(), b.get(), x.get()));
  CATENA_PETSC(VecAXPY(x.get(), -1.0, x_true.get()));
  CATENA_PETSC(VecNorm(x.get(), NORM_INFINITY, &error));
  EXPECT_LT(error, 1e-12 * scale);
}

namespace {

// A failed factorisation is the PC's failure (the KSP reports it, the solution is not
// finite), and it does not stick: the next matrix factors and solves again. `row` is set
// to `bad` in place, its pattern kept: an interior row of rank 0 (a zero pivot of its
// interior block) or the hub (an interface row: S gets a zero row, or a NaN).
void expect_failure_then_recovery(PetscInt row, PetscScalar bad) {
  catena::MatHandle A = chain_with_hub();
  catena::VecHandle b, x;
  CATENA_PETSC(MatCreateVecs(A.get(), x.out(), b.out()));
  CATENA_PETSC(VecSet(b.get(), 1.0));
  catena::KspHandle ksp;
  CATENA_PETSC(KSPCreate(PETSC_COMM_WORLD, ksp.out()));
  CATENA_PETSC(KSPSetType(ksp.get(), KSPPREONLY));
  CATENA_PETSC(KSPSetOperators(ksp.get(), A.get(), A.get()));
  catena::solvers::use_interface_schur(ksp.get(), A.get());
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  PetscInt first = 0, end = 0;
  CATENA_PETSC(MatGetOwnershipRange(A.get(), &first, &end));
  const bool owner = row >= first && row < end;
  std::vector<PetscInt> columns;
  std::vector<PetscScalar> saved;
  if (owner) {
    PetscInt n = 0;
    const PetscInt* c = nullptr;
    const PetscScalar* v = nullptr;
    CATENA_PETSC(MatGetRow(A.get(), row, &n, &c, &v));
    columns.assign(c, c + n);
    saved.assign(v, v + n);
    CATENA_PETSC(MatRestoreRow(A.get(), row, &n, &c, &v));
  }
  // Collective: `row` set to `values`, then a solve with the new values.
  const auto solve_with_row = [&](const std::vector<PetscScalar>& values) {
    if (owner)
      CATENA_PETSC(MatSetValues(A.get(), 1, &row, static_cast<PetscInt>(columns.size()),
                                columns.data(), values.data(), INSERT_VALUES));
    CATENA_PETSC(MatAssemblyBegin(A.get(), MAT_FINAL_ASSEMBLY));
    CATENA_PETSC(MatAssemblyEnd(A.get(), MAT_FINAL_ASSEMBLY));
    CATENA_PETSC(KSPSetOperators(ksp.get(), A.get(), A.get()));
    CATENA_PETSC(KSPSolve(ksp.get(), b.get(), x.get()));
    CATENA_PETSC(KSPGetConvergedReason(ksp.get(), &reason));
  };
  solve_with_row(std::vector<PetscScalar>(columns.size(), bad));
  EXPECT_EQ(reason, KSP_DIVERGED_PC_FAILED);
  PetscReal norm = 0.0;
  CATENA_PETSC(VecNorm(x.get(), NORM_INFINITY, &norm));
  EXPECT_FALSE(std::isfinite(norm));

  solve_with_row(saved);
  EXPECT_GT(reason, 0);
  catena::VecHandle r;
  CATENA_PETSC(VecDuplicate(b.get(), r.out()));
  CATENA_PETSC(MatMult(A.get(), x.get(), r.get()));
  CATENA_PETSC(VecAXPY(r.get(), -1.0, b.get()));
  CATENA_PETSC(VecNorm(r.get(), NORM_INFINITY, &norm));
  EXPECT_LT(norm, 1e-10);
}

bool more_than_one_rank() {
  catena::test::ensure_petsc();
  return catena::mpi_size(PETSC_COMM_WORLD) > 1;
}

}  // namespace

TEST(InterfaceSchur, AZeroPivotOfAnInteriorBlockIsReportedAndDoesNotStick) {
  if (!more_than_one_rank()) GTEST_SKIP() << "one rank has no interface";
  expect_failure_then_recovery(0, 0.0);
}

TEST(InterfaceSchur, ASingularSchurComplementIsReportedAndDoesNotStick) {
  if (!more_than_one_rank()) GTEST_SKIP() << "one rank has no interface";
  expect_failure_then_recovery(kRows - 1, 0.0);  // the hub's row: a zero row of S
}

TEST(InterfaceSchur, ANonFiniteSchurComplementIsReportedAndDoesNotStick) {
  if (!more_than_one_rank()) GTEST_SKIP() << "one rank has no interface";
  expect_failure_then_recovery(kRows - 1, std::numeric_limits<double>::quiet_NaN());
}

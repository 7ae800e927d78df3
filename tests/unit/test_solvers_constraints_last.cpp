// PETSc's LU with the multipliers eliminated last (solvers/newton/constraints_last_ordering
// .hpp), on one rank: a saddle-point matrix [A Gᵀ; G 0] (A a nonsymmetric chain with mass on
// its diagonal, G five constraints tying unknowns together or to a value) is solved to
// round-off by PETSc's own LU, which the same matrix under plain nested dissection fails
// with a zero pivot (so the order, not luck, makes it work); a matrix whose unknown only a
// constraint holds (x, s, λ with s on no diagonal) meets a zero pivot even so, and
// fall_back_to_pivoting hands it to MUMPS, which solves it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/petsc_handle.hpp"
#include "catena/solvers/newton/constraints_last_ordering.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "petsc_test_session.hpp"

namespace {

namespace cs = catena::solvers;
using catena::KspHandle;
using catena::MatHandle;
using catena::VecHandle;

constexpr PetscInt kChain = 60;
// (first, second) unknowns of each constraint: x_first − x_second = 0, or x_first = 0
// where second < 0.
const std::vector<std::pair<PetscInt, PetscInt>> kConstraints = {
    {3, 40}, {10, 11}, {25, -1}, {50, 7}, {59, 0}};

struct System {
  MatHandle J;
  VecHandle mask;
};

// Rows 0..kChain−1: the chain; the rest: one multiplier per constraint, diagonal entries
// present (zero), as Catena's matrices have them.
System saddle_point() {
  const auto n = kChain + static_cast<PetscInt>(kConstraints.size());
  System s;
  CATENA_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 8, nullptr, s.J.out()));
  for (PetscInt i = 0; i < kChain; ++i) {
    CATENA_PETSC(MatSetValue(s.J.get(), i, i, 4.0 + 0.01 * static_cast<double>(i), INSERT_VALUES));
    if (i > 0) CATENA_PETSC(MatSetValue(s.J.get(), i, i - 1, -1.0, INSERT_VALUES));
    if (i + 1 < kChain) CATENA_PETSC(MatSetValue(s.J.get(), i, i + 1, -1.3, INSERT_VALUES));
  }
  for (std::size_t k = 0; k < kConstraints.size(); ++k) {
    const PetscInt row = kChain + static_cast<PetscInt>(k);
    const auto [a, b] = kConstraints[k];
    // Scaled like Catena's constraint rows (m̄ G beside the mass entries).
    for (const auto& [column, value] : {std::pair{a, 2.0}, std::pair{b, -2.0}}) {
      if (column < 0) continue;
      CATENA_PETSC(MatSetValue(s.J.get(), row, column, value, INSERT_VALUES));
      CATENA_PETSC(MatSetValue(s.J.get(), column, row, value, INSERT_VALUES));
    }
    CATENA_PETSC(MatSetValue(s.J.get(), row, row, 0.0, INSERT_VALUES));
  }
  CATENA_PETSC(MatAssemblyBegin(s.J.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(s.J.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatCreateVecs(s.J.get(), s.mask.out(), nullptr));
  CATENA_PETSC(VecSet(s.mask.get(), 0.0));
  for (PetscInt row = kChain; row < n; ++row)
    CATENA_PETSC(VecSetValue(s.mask.get(), row, 1.0, INSERT_VALUES));
  CATENA_PETSC(VecAssemblyBegin(s.mask.get()));
  CATENA_PETSC(VecAssemblyEnd(s.mask.get()));
  return s;
}

// b = J x_true for a known x_true; returns the largest |x − x_true| of KSP's solution and
// its converged reason (negative: failed).
std::pair<double, KSPConvergedReason> solve_known(KSP ksp, Mat J) {
  VecHandle x_true, b, x;
  CATENA_PETSC(MatCreateVecs(J, x_true.out(), b.out()));
  CATENA_PETSC(VecDuplicate(x_true.get(), x.out()));
  PetscInt n = 0;
  CATENA_PETSC(VecGetSize(x_true.get(), &n));
  for (PetscInt i = 0; i < n; ++i)
    CATENA_PETSC(
        VecSetValue(x_true.get(), i, std::sin(0.7 * static_cast<double>(i)) + 0.2, INSERT_VALUES));
  CATENA_PETSC(VecAssemblyBegin(x_true.get()));
  CATENA_PETSC(VecAssemblyEnd(x_true.get()));
  CATENA_PETSC(MatMult(J, x_true.get(), b.get()));
  CATENA_PETSC(KSPSetOperators(ksp, J, J));
  CATENA_PETSC(KSPSolve(ksp, b.get(), x.get()));
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  CATENA_PETSC(KSPGetConvergedReason(ksp, &reason));
  CATENA_PETSC(VecAXPY(x.get(), -1.0, x_true.get()));
  PetscReal error = 0.0;
  CATENA_PETSC(VecNorm(x.get(), NORM_INFINITY, &error));
  return {error, reason};
}

std::string package(KSP ksp) {
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  MatSolverType type = nullptr;
  CATENA_PETSC(PCFactorGetMatSolverType(pc, &type));
  return type ? type : "";
}

TEST(ConstraintsLast, PetscLuSolvesTheSaddlePointThatNestedDissectionAloneCannot) {
  catena::test::ensure_petsc();
  {
    // Control: PETSc's LU in plain nested-dissection order.
    System plain = saddle_point();
    KspHandle ksp = cs::create_direct_ksp(PETSC_COMM_SELF, "constraints_plain_",
                                          cs::JacobianSymmetry::general, cs::Pivoting::not_needed);
    ASSERT_EQ(package(ksp.get()), MATSOLVERPETSC);
    EXPECT_LT(solve_known(ksp.get(), plain.J.get()).second, 0)
        << "plain nested dissection got past the multipliers' zero diagonal";
  }
  System s = saddle_point();
  cs::mark_constraint_rows(s.J.get(), s.mask.get());
  KspHandle ksp =
      cs::create_direct_ksp(PETSC_COMM_SELF, "constraints_last_", cs::JacobianSymmetry::general,
                            cs::Pivoting::constraints_last);
  EXPECT_EQ(package(ksp.get()), MATSOLVERPETSC);
  const auto [error, reason] = solve_known(ksp.get(), s.J.get());
  EXPECT_GT(reason, 0);
  EXPECT_LT(error, 1e-12);
}

TEST(ConstraintsLast, AZeroPivotHandsTheMatrixToMumps) {
  catena::test::ensure_petsc();
  // Unknowns (x, s, λ): x has mass, s appears in the constraint s = 0 only (as a slider's
  // arc length on a straight path), λ is its multiplier. Eliminated in the order x, s, λ,
  // s's pivot is zero; the matrix itself is not singular.
  MatHandle J;
  CATENA_PETSC(MatCreateSeqAIJ(PETSC_COMM_SELF, 3, 3, 3, nullptr, J.out()));
  const PetscInt all[3] = {0, 1, 2};
  const PetscScalar values[9] = {2.0, 0.0, 0.0, 0.0, 0.0, 1.5, 0.0, 1.5, 0.0};
  CATENA_PETSC(MatSetValues(J.get(), 3, all, 3, all, values, INSERT_VALUES));
  CATENA_PETSC(MatAssemblyBegin(J.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(J.get(), MAT_FINAL_ASSEMBLY));
  VecHandle mask;
  CATENA_PETSC(MatCreateVecs(J.get(), mask.out(), nullptr));
  CATENA_PETSC(VecSet(mask.get(), 0.0));
  CATENA_PETSC(VecSetValue(mask.get(), 2, 1.0, INSERT_VALUES));
  CATENA_PETSC(VecAssemblyBegin(mask.get()));
  CATENA_PETSC(VecAssemblyEnd(mask.get()));
  cs::mark_constraint_rows(J.get(), mask.get());
  const std::string prefix = "constraints_fallback_";
  KspHandle ksp = cs::create_direct_ksp(PETSC_COMM_SELF, prefix, cs::JacobianSymmetry::general,
                                        cs::Pivoting::constraints_last);
  EXPECT_LT(solve_known(ksp.get(), J.get()).second, 0);
  ASSERT_TRUE(cs::fall_back_to_pivoting(ksp.get(), prefix, cs::JacobianSymmetry::general));
  EXPECT_EQ(package(ksp.get()), MATSOLVERMUMPS);
  const auto [error, reason] = solve_known(ksp.get(), J.get());
  EXPECT_GT(reason, 0);
  EXPECT_LT(error, 1e-14);
  // Once MUMPS factors it there is nothing to fall back from.
  EXPECT_FALSE(cs::fall_back_to_pivoting(ksp.get(), prefix, cs::JacobianSymmetry::general));
}

}  // namespace

#include "catena/assembly/compact_matrix.hpp"

#include <vector>

#include "catena/assembly/petsc_call.hpp"

namespace catena::assembly {

MatHandle compact_copy(Mat A) {
  MPI_Comm comm = PETSC_COMM_SELF;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(A), &comm));
  PetscInt m = 0, n = 0, M = 0, N = 0, row_lo = 0, row_hi = 0, col_lo = 0, col_hi = 0;
  CATENA_PETSC(MatGetLocalSize(A, &m, &n));
  CATENA_PETSC(MatGetSize(A, &M, &N));
  CATENA_PETSC(MatGetOwnershipRange(A, &row_lo, &row_hi));
  CATENA_PETSC(MatGetOwnershipRangeColumn(A, &col_lo, &col_hi));

  // Two passes over the owned rows: count the nonzeros (diagonal and off-diagonal
  // blocks, for the exact preallocation), then insert them.
  std::vector<PetscInt> d_nnz(static_cast<size_t>(m), 0), o_nnz(static_cast<size_t>(m), 0);
  for (PetscInt row = row_lo; row < row_hi; ++row) {
    PetscInt n_cols = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* values = nullptr;
    CATENA_PETSC(MatGetRow(A, row, &n_cols, &cols, &values));
    const auto local = static_cast<size_t>(row - row_lo);
    for (PetscInt k = 0; k < n_cols; ++k)
      if (values[k] != 0.0) ++(cols[k] >= col_lo && cols[k] < col_hi ? d_nnz : o_nnz)[local];
    CATENA_PETSC(MatRestoreRow(A, row, &n_cols, &cols, &values));
  }
  MatHandle B;
  CATENA_PETSC(MatCreate(comm, B.out()));
  CATENA_PETSC(MatSetSizes(B.get(), m, n, M, N));
  CATENA_PETSC(MatSetType(B.get(), MATAIJ));
  CATENA_PETSC(MatSeqAIJSetPreallocation(B.get(), 0, d_nnz.data()));
  CATENA_PETSC(MatMPIAIJSetPreallocation(B.get(), 0, d_nnz.data(), 0, o_nnz.data()));
  CATENA_PETSC(MatSetOption(B.get(), MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  std::vector<PetscInt> kept_cols;
  std::vector<PetscScalar> kept_values;
  for (PetscInt row = row_lo; row < row_hi; ++row) {
    PetscInt n_cols = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* values = nullptr;
    CATENA_PETSC(MatGetRow(A, row, &n_cols, &cols, &values));
    kept_cols.clear();
    kept_values.clear();
    for (PetscInt k = 0; k < n_cols; ++k)
      if (values[k] != 0.0) {
        kept_cols.push_back(cols[k]);
        kept_values.push_back(values[k]);
      }
    CATENA_PETSC(MatSetValues(B.get(), 1, &row, static_cast<PetscInt>(kept_cols.size()),
                              kept_cols.data(), kept_values.data(), INSERT_VALUES));
    CATENA_PETSC(MatRestoreRow(A, row, &n_cols, &cols, &values));
  }
  CATENA_PETSC(MatAssemblyBegin(B.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(B.get(), MAT_FINAL_ASSEMBLY));
  return B;
}

}  // namespace catena::assembly

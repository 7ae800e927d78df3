#include "catena/solvers/time/irk/block_matrix.hpp"

#include <array>
#include <memory>
#include <stdexcept>

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers {

BlockCoefficients::BlockCoefficients(int blocks)
    : s(blocks),
      k(static_cast<size_t>(blocks * blocks), 0.0),
      c(static_cast<size_t>(blocks * blocks), 0.0),
      m(static_cast<size_t>(blocks * blocks), 0.0),
      d(static_cast<size_t>(blocks * blocks), 0.0) {}

namespace {

// Owned rows of an MPIAIJ matrix, restored on scope exit. MPIAIJ allows one active row
// at a time: copy what is needed (CopiedRow) before viewing the next.
class RowView {
 public:
  RowView(Mat A, PetscInt row) : A_(A), row_(row) {
    CATENA_PETSC(MatGetRow(A_, row_, &n, &cols, &values));
  }
  ~RowView() { MatRestoreRow(A_, row_, &n, &cols, &values); }
  RowView(const RowView&) = delete;
  RowView& operator=(const RowView&) = delete;
  PetscInt n = 0;
  const PetscInt* cols = nullptr;
  const PetscScalar* values = nullptr;

 private:
  Mat A_;
  PetscInt row_;
};

struct CopiedRow {
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> values;
  void read(Mat A, PetscInt row) {
    const RowView view(A, row);
    cols.assign(view.cols, view.cols + view.n);
    values.assign(view.values, view.values + view.n);
  }
};

}  // namespace

BlockMatrix::BlockMatrix(Mat pattern, int blocks) : s_(blocks) {
  if (blocks < 1) throw std::invalid_argument("BlockMatrix: blocks must be >= 1");
  MPI_Comm comm = PETSC_COMM_SELF;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(pattern), &comm));
  PetscInt last = 0;
  CATENA_PETSC(MatGetOwnershipRange(pattern, &first_, &last));
  n_owned_ = last - first_;
  // Exact preallocation: each block row i of DOF g has s entries per nonzero of row g.
  std::vector<PetscInt> d_nnz(static_cast<size_t>(n_owned_ * s_)),
      o_nnz(static_cast<size_t>(n_owned_ * s_));
  for (PetscInt g = first_; g < last; ++g) {
    const RowView row(pattern, g);
    PetscInt diag = 0;
    for (PetscInt k = 0; k < row.n; ++k) diag += (row.cols[k] >= first_ && row.cols[k] < last);
    for (int i = 0; i < s_; ++i) {
      d_nnz[static_cast<size_t>((g - first_) * s_ + i)] = diag * s_;
      o_nnz[static_cast<size_t>((g - first_) * s_ + i)] = (row.n - diag) * s_;
    }
  }
  const PetscInt n_local = n_owned_ * s_;
  CATENA_PETSC(MatCreate(comm, B_.out()));
  CATENA_PETSC(MatSetSizes(B_.get(), n_local, n_local, PETSC_DETERMINE, PETSC_DETERMINE));
  CATENA_PETSC(MatSetType(B_.get(), MATAIJ));
  CATENA_PETSC(MatSeqAIJSetPreallocation(B_.get(), 0, d_nnz.data()));
  CATENA_PETSC(MatMPIAIJSetPreallocation(B_.get(), 0, d_nnz.data(), 0, o_nnz.data()));
  CATENA_PETSC(MatSetOption(B_.get(), MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
}

void BlockMatrix::assemble(Mat K, Mat C, Mat M, const BlockCoefficients& coefficients) {
  assemble_rows(std::vector<Mat>(static_cast<size_t>(s_), K),
                std::vector<Mat>(static_cast<size_t>(s_), C), M, coefficients);
}

void BlockMatrix::assemble_rows(const std::vector<Mat>& K_rows, const std::vector<Mat>& C_rows,
                                Mat M, const BlockCoefficients& coefficients) {
  const int s = s_;
  if (coefficients.s != s || static_cast<int>(K_rows.size()) != s ||
      static_cast<int>(C_rows.size()) != s)
    throw std::invalid_argument("BlockMatrix: block count mismatch");
  // Which of K, C, M block row i needs.
  auto row_uses = [&](const std::vector<double>& x, int i) {
    for (int j = 0; j < s; ++j)
      if (x[static_cast<size_t>(i * s + j)] != 0.0) return true;
    return false;
  };
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> values;
  std::array<CopiedRow, 4> rows;  // K, C, M, pattern
  for (PetscInt g = first_; g < first_ + n_owned_; ++g) {
    for (int i = 0; i < s; ++i) {
      const bool use_K = row_uses(coefficients.k, i), use_C = row_uses(coefficients.c, i),
                 use_M = row_uses(coefficients.m, i);
      Mat Ki = K_rows[static_cast<size_t>(i)], Ci = C_rows[static_cast<size_t>(i)];
      if ((use_K && !Ki) || (use_C && !Ci) || (use_M && !M))
        throw std::invalid_argument("BlockMatrix: a matrix with nonzero coefficients is missing");
      Mat shape = Ki ? Ki : (Ci ? Ci : M);
      CopiedRow& pattern_row = rows[3];
      pattern_row.read(shape, g);
      if (use_K) rows[0].read(Ki, g);
      if (use_C) rows[1].read(Ci, g);
      if (use_M) rows[2].read(M, g);
      for (int r = 0; r < 3; ++r)
        if (((r == 0 && use_K) || (r == 1 && use_C) || (r == 2 && use_M)) &&
            rows[static_cast<size_t>(r)].cols != pattern_row.cols)
          throw std::logic_error("BlockMatrix: K, C and M must share one sparsity pattern");
      const CopiedRow *kr = &rows[0], *cr = &rows[1], *mr = &rows[2];
      const auto n = static_cast<PetscInt>(pattern_row.cols.size());
      cols.resize(static_cast<size_t>(n * s));
      values.resize(static_cast<size_t>(n * s));
      for (PetscInt k = 0; k < n; ++k) {
        const bool diagonal = pattern_row.cols[k] == g;
        for (int j = 0; j < s; ++j) {
          const size_t ij = static_cast<size_t>(i * s + j);
          double value = 0.0;
          if (use_K) value += coefficients.k[ij] * kr->values[k];
          if (use_C) value += coefficients.c[ij] * cr->values[k];
          if (use_M) value += coefficients.m[ij] * mr->values[k];
          if (diagonal) value += coefficients.d[ij];
          cols[static_cast<size_t>(k * s + j)] = pattern_row.cols[k] * s + j;
          values[static_cast<size_t>(k * s + j)] = value;
        }
      }
      const PetscInt row = g * s + i;
      CATENA_PETSC(
          MatSetValues(B_.get(), 1, &row, n * s, cols.data(), values.data(), INSERT_VALUES));
    }
  }
  CATENA_PETSC(MatAssemblyBegin(B_.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(B_.get(), MAT_FINAL_ASSEMBLY));
}

VecHandle BlockMatrix::create_vector() const {
  VecHandle v;
  CATENA_PETSC(MatCreateVecs(B_.get(), v.out(), nullptr));
  return v;
}

}  // namespace catena::solvers

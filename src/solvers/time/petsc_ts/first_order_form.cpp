#include "catena/solvers/time/petsc_ts/first_order_form.hpp"

#include <algorithm>
#include <stdexcept>

#include "catena/assembly/petsc_call.hpp"

namespace catena::solvers {
namespace {

// Copies of one owned row of an assembled MPIAIJ matrix (global columns). MPIAIJ allows a
// single active MatGetRow, so rows of K, C and M are copied one after the other.
struct RowCopy {
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> values;

  void read(Mat A, PetscInt row) {
    PetscInt n = 0;
    const PetscInt* c = nullptr;
    const PetscScalar* v = nullptr;
    CATENA_PETSC(MatGetRow(A, row, &n, &c, &v));
    cols.assign(c, c + n);
    values.assign(v, v + n);
    CATENA_PETSC(MatRestoreRow(A, row, &n, &c, &v));
  }
};

// Adds `scale`·row into `out`, whose columns `merged` contain every column of the row.
void scatter_row(const RowCopy& row, double scale, const std::vector<PetscInt>& merged,
                 std::vector<double>& out) {
  for (size_t k = 0; k < row.cols.size(); ++k) {
    const auto at = std::lower_bound(merged.begin(), merged.end(), row.cols[k]);
    out[static_cast<size_t>(at - merged.begin())] += scale * row.values[k];
  }
}

}  // namespace

FirstOrderForm::FirstOrderForm(Mat K, Mat C, Mat M) {
  MPI_Comm comm = PETSC_COMM_SELF;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(K), &comm));
  PetscInt last = 0;
  CATENA_PETSC(MatGetOwnershipRange(K, &first_, &last));
  n_owned_ = last - first_;
  columns_.resize(static_cast<size_t>(n_owned_));
  RowCopy row;
  for (PetscInt g = first_; g < last; ++g) {
    std::vector<PetscInt>& cols = columns_[static_cast<size_t>(g - first_)];
    cols.push_back(g);  // the v row's diagonal C + σM must exist for the factorisation
    for (Mat A : {K, C, M}) {
      row.read(A, g);
      cols.insert(cols.end(), row.cols.begin(), row.cols.end());
    }
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
  }
  // Exact preallocation: a q row holds (2g, 2g + 1); a v row two entries per column c.
  std::vector<PetscInt> d_nnz(static_cast<size_t>(2 * n_owned_)),
      o_nnz(static_cast<size_t>(2 * n_owned_));
  for (PetscInt l = 0; l < n_owned_; ++l) {
    const auto& cols = columns_[static_cast<size_t>(l)];
    const auto diag = std::count_if(cols.begin(), cols.end(),
                                    [&](PetscInt c) { return c >= first_ && c < last; });
    d_nnz[static_cast<size_t>(2 * l)] = 2;
    o_nnz[static_cast<size_t>(2 * l)] = 0;
    d_nnz[static_cast<size_t>(2 * l + 1)] = static_cast<PetscInt>(2 * diag);
    o_nnz[static_cast<size_t>(2 * l + 1)] = static_cast<PetscInt>(2 * (cols.size() - diag));
  }
  CATENA_PETSC(MatCreate(comm, B_.out()));
  CATENA_PETSC(MatSetSizes(B_.get(), 2 * n_owned_, 2 * n_owned_, PETSC_DETERMINE, PETSC_DETERMINE));
  CATENA_PETSC(MatSetType(B_.get(), MATAIJ));
  CATENA_PETSC(MatSeqAIJSetPreallocation(B_.get(), 0, d_nnz.data()));
  CATENA_PETSC(MatMPIAIJSetPreallocation(B_.get(), 0, d_nnz.data(), 0, o_nnz.data()));
  CATENA_PETSC(MatSetOption(B_.get(), MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
}

void FirstOrderForm::assemble(double sigma, Mat K, Mat C, Mat M) {
  RowCopy row;
  std::vector<double> k_values, cm_values;
  std::vector<PetscInt> cols;
  std::vector<PetscScalar> values;
  for (PetscInt l = 0; l < n_owned_; ++l) {
    const PetscInt g = first_ + l;
    const auto& merged = columns_[static_cast<size_t>(l)];
    // q row: σ q̇ − v.
    const PetscInt q_row = 2 * g, q_cols[2] = {2 * g, 2 * g + 1};
    const PetscScalar q_values[2] = {sigma, -1.0};
    CATENA_PETSC(MatSetValues(B_.get(), 1, &q_row, 2, q_cols, q_values, INSERT_VALUES));
    // v row: K in the q columns, C + σM in the v columns.
    k_values.assign(merged.size(), 0.0);
    cm_values.assign(merged.size(), 0.0);
    row.read(K, g);
    scatter_row(row, 1.0, merged, k_values);
    row.read(C, g);
    scatter_row(row, 1.0, merged, cm_values);
    row.read(M, g);
    scatter_row(row, sigma, merged, cm_values);
    cols.resize(2 * merged.size());
    values.resize(2 * merged.size());
    for (size_t k = 0; k < merged.size(); ++k) {
      cols[2 * k] = 2 * merged[k];
      cols[2 * k + 1] = 2 * merged[k] + 1;
      values[2 * k] = k_values[k];
      values[2 * k + 1] = cm_values[k];
    }
    const PetscInt v_row = 2 * g + 1;
    CATENA_PETSC(MatSetValues(B_.get(), 1, &v_row, static_cast<PetscInt>(cols.size()), cols.data(),
                              values.data(), INSERT_VALUES));
  }
  CATENA_PETSC(MatAssemblyBegin(B_.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(B_.get(), MAT_FINAL_ASSEMBLY));
}

VecHandle FirstOrderForm::create_vector() const {
  VecHandle v;
  CATENA_PETSC(MatCreateVecs(B_.get(), v.out(), nullptr));
  return v;
}

void FirstOrderForm::split(Vec U, Vec q, Vec v) const {
  const PetscScalar* u = nullptr;
  CATENA_PETSC(VecGetArrayRead(U, &u));
  for (int part = 0; part < 2; ++part) {
    Vec out = part == 0 ? q : v;
    if (!out) continue;
    PetscScalar* x = nullptr;
    CATENA_PETSC(VecGetArrayWrite(out, &x));
    for (PetscInt l = 0; l < n_owned_; ++l) x[l] = u[2 * l + part];
    CATENA_PETSC(VecRestoreArrayWrite(out, &x));
  }
  CATENA_PETSC(VecRestoreArrayRead(U, &u));
}

void FirstOrderForm::join(Vec q, Vec v, Vec U) const {
  PetscScalar* u = nullptr;
  CATENA_PETSC(VecGetArrayWrite(U, &u));
  for (int part = 0; part < 2; ++part) {
    const PetscScalar* x = nullptr;
    Vec in = part == 0 ? q : v;
    CATENA_PETSC(VecGetArrayRead(in, &x));
    for (PetscInt l = 0; l < n_owned_; ++l) u[2 * l + part] = x[l];
    CATENA_PETSC(VecRestoreArrayRead(in, &x));
  }
  CATENA_PETSC(VecRestoreArrayWrite(U, &u));
}

}  // namespace catena::solvers

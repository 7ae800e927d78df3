#pragma once
// A few long rows (the modal model's dropper rows: droppers × modes) kept a second time in
// single precision for the one product a step makes with all of them, with a bound on what
// the rounding can change. Stored as floats the EN 50318 rows (90 × 1831) take 0.66 MB
// instead of 1.3 MB and stay in a core's L2 cache, and the product runs at the vector width
// of the machine it runs on (its kernel is compiled for AVX2 and AVX-512 as well, chosen at
// load time);
// the caller keeps the exact rows and re-forms in double any entry whose use the bound says
// the rounding could change (ModalStepper: a dropper in the iteration, or one whose
// slack/taut test lies within the bound). The modal model's mode shapes (DOFs × modes) are
// held this way alone, column by column as the eigen-solve's vectors come (set_column):
// streaming them is a field sample's whole cost, and floats halve it.
#include <Eigen/Dense>
#include <vector>

namespace catena::solvers {

class SinglePrecisionRows {
 public:
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  SinglePrecisionRows() = default;
  explicit SinglePrecisionRows(const RowMajorMatrix& rows);
  // rows × cols of zeros, to be filled by set_column (each column once, checked); the bounds
  // hold once every column is set.
  SinglePrecisionRows(Eigen::Index rows, Eigen::Index cols);
  // Column c from `values` (rows() of them), rounded; its share of the bounds added.
  void set_column(Eigen::Index c, const double* values);

  Eigen::Index rows() const { return rows_; }
  Eigen::Index cols() const { return cols_; }
  // y = Ã x, Ã the rows rounded to single precision, the sums in double.
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& y) const;
  // y1 = Ã x1 and y2 = Ã x2 in one pass over Ã.
  void multiply_pair(const Eigen::Ref<const Eigen::VectorXd>& x1,
                     const Eigen::Ref<const Eigen::VectorXd>& x2, Eigen::VectorXd& y1,
                     Eigen::VectorXd& y2) const;
  // ã_j · x, summed in double (within bound(j) ‖x‖₂ of a_j · x).
  double row_dot(Eigen::Index j, const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // Ãᵀ w, summed in double.
  Eigen::VectorXd multiply_transposed(const double* w) const;
  // |(A x)_j − y_j| ≤ bound(j) ‖x‖₂ for y from multiply (A the exact rows): the rounding of
  // row j, ‖a_j − ã_j‖₂, plus the double sums' own error, γ_n ‖ã_j‖₂ (Higham, Accuracy and
  // Stability of Numerical Algorithms, 2nd ed., SIAM 2002, §3.1), by Cauchy–Schwarz.
  double bound(Eigen::Index j) const { return bound_(j); }

 private:
  Eigen::Index rows_ = 0, cols_ = 0;
  std::vector<float> values_;  // row-major
  Eigen::VectorXd bound_;
  // While columns are set: per row, Σ (a − ã)² and Σ ã² so far; which columns are in.
  Eigen::VectorXd rounding_squares_, norm_squares_;
  std::vector<char> column_is_set_;
};

}  // namespace catena::solvers

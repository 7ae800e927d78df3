#pragma once
// A few long rows (the modal model's dropper rows: droppers × modes) kept a second time in
// single precision for the one product a step makes with all of them, with a bound on what
// the rounding can change. Stored as floats the EN 50318 rows (90 × 1831) take 0.66 MB
// instead of 1.3 MB and stay in a core's L2 cache, and the product runs at the vector width
// of the machine it runs on (its kernel is compiled for AVX2 and AVX-512 as well, chosen at
// load time);
// the caller keeps the exact rows and re-forms in double any entry whose use the bound says
// the rounding could change (ModalStepper: a dropper in the iteration, or one whose
// slack/taut test lies within the bound).
#include <Eigen/Dense>
#include <vector>

namespace catena::solvers {

class SinglePrecisionRows {
 public:
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  SinglePrecisionRows() = default;
  explicit SinglePrecisionRows(const RowMajorMatrix& rows);

  Eigen::Index rows() const { return rows_; }
  Eigen::Index cols() const { return cols_; }
  // y = Ã x, Ã the rows rounded to single precision, the sums in double.
  void multiply(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::VectorXd& y) const;
  // |(A x)_j − y_j| ≤ bound(j) ‖x‖₂ for y from multiply (A the exact rows): the rounding of
  // row j, ‖a_j − ã_j‖₂, plus the double sums' own error, γ_n ‖ã_j‖₂ (Higham, Accuracy and
  // Stability of Numerical Algorithms, 2nd ed., SIAM 2002, §3.1), by Cauchy–Schwarz.
  double bound(Eigen::Index j) const { return bound_(j); }

 private:
  Eigen::Index rows_ = 0, cols_ = 0;
  std::vector<float> values_;  // row-major
  Eigen::VectorXd bound_;
};

}  // namespace catena::solvers

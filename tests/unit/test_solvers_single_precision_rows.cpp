// SinglePrecisionRows (the modal step's product with the dropper rows in single precision)
// against the double product: on rows whose entries span twelve orders of magnitude and
// on vectors of either sign, every entry of the product lies within its stated bound
// (bound(j) ‖x‖₂) of the exact one, the rounding shows (the bound is not met by chance of
// an exact product), and the bound is of single precision's size (‖a_j‖₂ 2⁻²⁴ and a little
// more), not a vacuous one; rows of floats lose nothing (bound ≈ 0, product exact to the
// sums' round-off). Built column by column (the modal model's mode shapes), the rows and
// bounds are the same, and the pair product, a row's dot product and the transposed product
// keep to the same bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "catena/solvers/modal/single_precision_rows.hpp"

namespace {

using catena::solvers::SinglePrecisionRows;
using Rows = SinglePrecisionRows::RowMajorMatrix;

TEST(SinglePrecisionRows, ProductIsWithinItsBoundOfTheExactOne) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-6.0, 6.0);
  const Eigen::Index rows = 37, cols = 1831;  // odd: the loops' remainders (4 rows, vector)
  Rows A(rows, cols);
  for (Eigen::Index j = 0; j < rows; ++j)
    for (Eigen::Index i = 0; i < cols; ++i)
      A(j, i) = unit(random) * std::pow(10.0, exponent(random));
  const SinglePrecisionRows single(A);
  ASSERT_EQ(single.rows(), rows);
  ASSERT_EQ(single.cols(), cols);
  const double unit_roundoff = std::ldexp(1.0, -24);
  double largest_error = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd x(cols);
    for (Eigen::Index i = 0; i < cols; ++i) x(i) = unit(random) * std::pow(10.0, exponent(random));
    Eigen::VectorXd y;
    single.multiply(x, y);
    const Eigen::VectorXd exact = A * x;
    ASSERT_EQ(y.size(), rows);
    for (Eigen::Index j = 0; j < rows; ++j) {
      const double error = std::abs(y(j) - exact(j));
      EXPECT_LE(error, single.bound(j) * x.norm()) << "row " << j << ", trial " << trial;
      largest_error = std::max(largest_error, error / (A.row(j).norm() * x.norm()));
    }
  }
  EXPECT_GT(largest_error, 1e-12);  // the rows were rounded
  for (Eigen::Index j = 0; j < rows; ++j) {
    EXPECT_LE(single.bound(j), 1.02 * unit_roundoff * A.row(j).norm()) << "row " << j;
    EXPECT_GT(single.bound(j), 0.0);
  }
}

TEST(SinglePrecisionRows, RowsOfFloatsLoseNothing) {
  Rows A(2, 5);
  A << 0.5, -1.25, 3.0, 1024.0, 0.0, 1.0 / 8.0, 7.0, -2.0, 0.75, 5.5;
  const SinglePrecisionRows single(A);
  const Eigen::VectorXd x = (Eigen::VectorXd(5) << 0.1, 0.2, -0.3, 1e-3, 42.0).finished();
  Eigen::VectorXd y;
  single.multiply(x, y);
  const Eigen::VectorXd exact = A * x;
  for (Eigen::Index j = 0; j < 2; ++j) {
    EXPECT_NEAR(y(j), exact(j), 1e-14 * A.row(j).norm() * x.norm());
    EXPECT_LT(single.bound(j), 1e-14 * A.row(j).norm());
  }
}

TEST(SinglePrecisionRows, ColumnByColumnGivesTheSameRowsAndEveryProductKeepsItsBound) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-4.0, 4.0);
  const Eigen::Index rows = 23, cols = 301;
  Rows A(rows, cols);
  for (Eigen::Index j = 0; j < rows; ++j)
    for (Eigen::Index i = 0; i < cols; ++i)
      A(j, i) = unit(random) * std::pow(10.0, exponent(random));
  const SinglePrecisionRows whole(A);
  SinglePrecisionRows by_column(rows, cols);
  for (Eigen::Index i = cols - 1; i >= 0; --i) {  // any order
    const Eigen::VectorXd column = A.col(i);
    by_column.set_column(i, column.data());
  }
  Eigen::VectorXd x1(cols), x2(cols), w(rows);
  for (Eigen::Index i = 0; i < cols; ++i) {
    x1(i) = unit(random) * std::pow(10.0, exponent(random));
    x2(i) = unit(random);
  }
  for (Eigen::Index j = 0; j < rows; ++j) w(j) = unit(random) * std::pow(10.0, exponent(random));
  Eigen::VectorXd y_whole, y1, y2;
  whole.multiply(x1, y_whole);
  by_column.multiply_pair(x1, x2, y1, y2);
  const Eigen::VectorXd exact1 = A * x1, exact2 = A * x2;
  for (Eigen::Index j = 0; j < rows; ++j) {
    EXPECT_NEAR(by_column.bound(j), whole.bound(j), 1e-12 * whole.bound(j)) << j;
    EXPECT_LE(std::abs(y1(j) - exact1(j)), by_column.bound(j) * x1.norm()) << j;
    EXPECT_LE(std::abs(y2(j) - exact2(j)), by_column.bound(j) * x2.norm()) << j;
    EXPECT_NEAR(y1(j), y_whole(j), 1e-13 * A.row(j).norm() * x1.norm()) << j;  // same rows
    EXPECT_LE(std::abs(by_column.row_dot(j, x1) - exact1(j)), by_column.bound(j) * x1.norm());
  }
  // Ãᵀ w: entry i is off by at most Σ_j |w_j| |a_ji − ã_ji| ≤ 2⁻²⁴ Σ_j |w_j a_ji|, plus the
  // sums' round-off.
  const Eigen::VectorXd transposed = by_column.multiply_transposed(w.data());
  const Eigen::VectorXd exact_t = A.transpose() * w;
  const Eigen::VectorXd scale = A.cwiseAbs().transpose() * w.cwiseAbs();
  double largest = 0.0;
  for (Eigen::Index i = 0; i < cols; ++i) {
    const double error = std::abs(transposed(i) - exact_t(i));
    EXPECT_LE(error, (std::ldexp(1.0, -24) + 1e-14) * scale(i)) << i;
    largest = std::max(largest, error / scale(i));
  }
  EXPECT_GT(largest, 1e-12);  // rounded, and the test sees it
}

TEST(SinglePrecisionRows, NoRowsGiveAnEmptyProduct) {
  const SinglePrecisionRows single(Rows(0, 12));
  Eigen::VectorXd y = Eigen::VectorXd::Ones(3);
  single.multiply(Eigen::VectorXd::Ones(12), y);
  EXPECT_EQ(y.size(), 0);
}

}  // namespace

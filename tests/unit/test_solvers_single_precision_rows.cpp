// SinglePrecisionRows (the modal step's product with the dropper rows in single precision)
// against the double product: on rows whose entries span twelve orders of magnitude and
// on vectors of either sign, every entry of the product lies within its stated bound
// (bound(j) ‖x‖₂) of the exact one, the rounding shows (the bound is not met by chance of
// an exact product), and the bound is of single precision's size (‖a_j‖₂ 2⁻²⁴ and a little
// more), not a vacuous one; rows of floats lose nothing (bound ≈ 0, product exact to the
// sums' round-off).
#include <gtest/gtest.h>

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

TEST(SinglePrecisionRows, NoRowsGiveAnEmptyProduct) {
  const SinglePrecisionRows single(Rows(0, 12));
  Eigen::VectorXd y = Eigen::VectorXd::Ones(3);
  single.multiply(Eigen::VectorXd::Ones(12), y);
  EXPECT_EQ(y.size(), 0);
}

}  // namespace

#include "catena/solvers/modal/single_precision_rows.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

#include "catena/core/error.hpp"

namespace catena::solvers {
namespace {

// Compiled three times on x86-64 — for AVX-512, for AVX2 with FMA, and for the baseline
// (SSE2, two numbers at a time) — the loader picks the clone the processor runs.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define CATENA_VECTOR_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define CATENA_VECTOR_CLONES
#endif

// y = Ã x (CATENA_VECTOR_CLONES). Four rows at a time: four independent sums (one sum's chain of
// additions is latency-bound) sharing each load of x; the reductions' order is the compiler's
// (-fopenmp-simd), which the bound allows. On EN 50318's rows (90 × 1831) 8.4 µs a product
// against Eigen's 17.7 µs in double (a throwaway loop, AVX-512 machine).
CATENA_VECTOR_CLONES
void multiply_rows(const float* values, const double* x, double* y, std::ptrdiff_t rows,
                   std::ptrdiff_t cols) {
  std::ptrdiff_t j = 0;
  for (; j + 4 <= rows; j += 4) {
    const float* r0 = values + j * cols;
    const float *r1 = r0 + cols, *r2 = r1 + cols, *r3 = r2 + cols;
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
#pragma omp simd reduction(+ : s0, s1, s2, s3)
    for (std::ptrdiff_t i = 0; i < cols; ++i) {
      const double xi = x[i];
      s0 += static_cast<double>(r0[i]) * xi;
      s1 += static_cast<double>(r1[i]) * xi;
      s2 += static_cast<double>(r2[i]) * xi;
      s3 += static_cast<double>(r3[i]) * xi;
    }
    y[j] = s0;
    y[j + 1] = s1;
    y[j + 2] = s2;
    y[j + 3] = s3;
  }
  for (; j < rows; ++j) {
    const float* row = values + j * cols;
    double sum = 0.0;
#pragma omp simd reduction(+ : sum)
    for (std::ptrdiff_t i = 0; i < cols; ++i) sum += static_cast<double>(row[i]) * x[i];
    y[j] = sum;
  }
}

// y1 = Ã x1, y2 = Ã x2: one row at a time, both sums sharing its loads (the rows are the
// stream; x1 and x2 stay in cache).
CATENA_VECTOR_CLONES
void multiply_rows_pair(const float* values, const double* x1, const double* x2, double* y1,
                        double* y2, std::ptrdiff_t rows, std::ptrdiff_t cols) {
  for (std::ptrdiff_t j = 0; j < rows; ++j) {
    const float* row = values + j * cols;
    double s1 = 0.0, s2 = 0.0;
#pragma omp simd reduction(+ : s1, s2)
    for (std::ptrdiff_t i = 0; i < cols; ++i) {
      const double a = static_cast<double>(row[i]);
      s1 += a * x1[i];
      s2 += a * x2[i];
    }
    y1[j] = s1;
    y2[j] = s2;
  }
}

// x += w_j ã_j over the rows (no reduction: vectorised along the row).
CATENA_VECTOR_CLONES
void add_weighted_rows(const float* values, const double* w, double* x, std::ptrdiff_t rows,
                       std::ptrdiff_t cols) {
  for (std::ptrdiff_t j = 0; j < rows; ++j) {
    if (w[j] == 0.0) continue;
    const float* row = values + j * cols;
    const double wj = w[j];
#pragma omp simd
    for (std::ptrdiff_t i = 0; i < cols; ++i) x[i] += wj * static_cast<double>(row[i]);
  }
}

// γ_n = n u / (1 − n u), u = 2⁻⁵³: the double sums' own relative error over n terms.
double sum_error_factor(Eigen::Index n_terms) {
  const double u = std::numeric_limits<double>::epsilon() / 2.0;
  const double n = static_cast<double>(n_terms);
  return n * u / (1.0 - n * u);
}

}  // namespace

SinglePrecisionRows::SinglePrecisionRows(Eigen::Index rows, Eigen::Index cols)
    : rows_(rows),
      cols_(cols),
      values_(static_cast<std::size_t>(rows * cols), 0.0f),
      bound_(Eigen::VectorXd::Zero(rows)),
      rounding_squares_(Eigen::VectorXd::Zero(rows)),
      norm_squares_(Eigen::VectorXd::Zero(rows)),
      column_is_set_(static_cast<std::size_t>(cols), 0) {}

void SinglePrecisionRows::set_column(Eigen::Index c, const double* values) {
  CATENA_ASSERT(c >= 0 && c < cols_ && column_is_set_.size() == static_cast<std::size_t>(cols_),
                "SinglePrecisionRows::set_column: a column of a matrix built by (rows, cols)");
  CATENA_ASSERT(!column_is_set_[static_cast<std::size_t>(c)],
                "SinglePrecisionRows::set_column: each column once (its rounding enters the "
                "bounds)");
  column_is_set_[static_cast<std::size_t>(c)] = 1;
  for (Eigen::Index j = 0; j < rows_; ++j) {
    const float rounded = static_cast<float>(values[j]);
    values_[static_cast<std::size_t>(j * cols_ + c)] = rounded;
    const double back = static_cast<double>(rounded);
    rounding_squares_(j) += (values[j] - back) * (values[j] - back);
    norm_squares_(j) += back * back;
  }
  // The bounds once the last column is in (a margin of 1 % for their own rounding); the
  // sums behind them are not needed after that.
  if (std::find(column_is_set_.begin(), column_is_set_.end(), 0) != column_is_set_.end()) return;
  bound_ =
      1.01 * (rounding_squares_.cwiseSqrt() + sum_error_factor(cols_) * norm_squares_.cwiseSqrt());
  rounding_squares_ = Eigen::VectorXd();
  norm_squares_ = Eigen::VectorXd();
}

SinglePrecisionRows::SinglePrecisionRows(const RowMajorMatrix& rows)
    : rows_(rows.rows()), cols_(rows.cols()), values_(static_cast<std::size_t>(rows.size())) {
  const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rounded =
      rows.cast<float>();
  std::copy(rounded.data(), rounded.data() + rounded.size(), values_.begin());
  // A margin of 1 % for the rounding of the bound itself.
  const RowMajorMatrix back = rounded.cast<double>();
  bound_ =
      1.01 * ((rows - back).rowwise().norm() + sum_error_factor(cols_) * back.rowwise().norm());
}

void SinglePrecisionRows::multiply(const Eigen::Ref<const Eigen::VectorXd>& x,
                                   Eigen::VectorXd& y) const {
  y.resize(rows_);
  if (rows_ == 0) return;
  multiply_rows(values_.data(), x.data(), y.data(), rows_, cols_);
}

void SinglePrecisionRows::multiply_pair(const Eigen::Ref<const Eigen::VectorXd>& x1,
                                        const Eigen::Ref<const Eigen::VectorXd>& x2,
                                        Eigen::VectorXd& y1, Eigen::VectorXd& y2) const {
  y1.resize(rows_);
  y2.resize(rows_);
  if (rows_ == 0) return;
  multiply_rows_pair(values_.data(), x1.data(), x2.data(), y1.data(), y2.data(), rows_, cols_);
}

double SinglePrecisionRows::row_dot(Eigen::Index j,
                                    const Eigen::Ref<const Eigen::VectorXd>& x) const {
  double y = 0.0;
  multiply_rows(values_.data() + j * cols_, x.data(), &y, 1, cols_);
  return y;
}

Eigen::VectorXd SinglePrecisionRows::multiply_transposed(const double* w) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(cols_);
  if (rows_ > 0) add_weighted_rows(values_.data(), w, x.data(), rows_, cols_);
  return x;
}

}  // namespace catena::solvers

#undef CATENA_VECTOR_CLONES

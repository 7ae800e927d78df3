#include "catena/solvers/modal/single_precision_rows.hpp"

#include <cstddef>
#include <limits>

namespace catena::solvers {
namespace {

// y = Ã x. Compiled three times on x86-64 — for AVX-512, for AVX2 with FMA, and for the
// baseline (SSE2, two numbers at a time) — the loader picks the clone the processor runs.
// Four rows at a time: four independent sums (one sum's chain of additions is
// latency-bound) sharing each load of x; the reductions' order is the compiler's
// (-fopenmp-simd), which the bound allows. On EN 50318's rows (90 × 1831) 8.4 µs a product
// against Eigen's 17.7 µs in double (a throwaway loop, AVX-512 machine).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
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

}  // namespace

SinglePrecisionRows::SinglePrecisionRows(const RowMajorMatrix& rows)
    : rows_(rows.rows()), cols_(rows.cols()), values_(static_cast<std::size_t>(rows.size())) {
  const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rounded =
      rows.cast<float>();
  std::copy(rounded.data(), rounded.data() + rounded.size(), values_.begin());
  // γ_n = n u / (1 − n u), u = 2⁻⁵³; and a margin of 1 % for the rounding of the bound itself.
  const double u = std::numeric_limits<double>::epsilon() / 2.0;
  const double n = static_cast<double>(cols_);
  const double gamma = n * u / (1.0 - n * u);
  const RowMajorMatrix back = rounded.cast<double>();
  bound_ = 1.01 * ((rows - back).rowwise().norm() + gamma * back.rowwise().norm());
}

void SinglePrecisionRows::multiply(const Eigen::Ref<const Eigen::VectorXd>& x,
                                   Eigen::VectorXd& y) const {
  y.resize(rows_);
  if (rows_ == 0) return;
  multiply_rows(values_.data(), x.data(), y.data(), rows_, cols_);
}

}  // namespace catena::solvers

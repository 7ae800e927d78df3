#pragma once
// Cubic Hermite shape functions in ANCF form and Gauss–Legendre rules, shared by the ANCF
// cable and beam kernels. Header-only, allocation-free, constexpr-friendly.
//
// Shape functions on x ∈ [0, L] (ξ = x/L), ANCF ordering of the coefficients
//   r(x) = S1 r_A + S2 r_A,x + S3 r_B + S4 r_B,x
//   S1 = 1 − 3ξ² + 2ξ³        S2 = L (ξ − 2ξ² + ξ³)
//   S3 = 3ξ² − 2ξ³            S4 = L (−ξ² + ξ³)
// (node-A position, node-A slope, node-B position, node-B slope). Derivatives are taken
// with respect to x [m], so ds has units 1/m (S1, S3) or 1 (S2, S4), and dds 1/m², 1/m.
//
// Gauss–Legendre rules on the reference interval ξ ∈ [−1, 1], n = 1..6 points, weights
// summing to 2; the n-point rule integrates polynomials of degree ≤ 2n − 1 exactly.
// Map to an element [0, L]:  x = L (1 + ξ)/2,  weight_x = L w/2.
#include <array>
#include <span>

#include "catena/core/error.hpp"

namespace catena::elements {

// Values (s), first (ds) and second (dds) x-derivatives of S1..S4 at one point.
struct HermiteAt {
  double s[4];
  double ds[4];
  double dds[4];
};

// Cubic Hermite shape functions at x ∈ [0, L] (m) of an element of length L (m).
constexpr HermiteAt hermite_at(double x, double L) {
  const double xi = x / L, xi2 = xi * xi, xi3 = xi2 * xi;
  const double inv_L = 1.0 / L;
  return HermiteAt{{1.0 - 3.0 * xi2 + 2.0 * xi3, L * (xi - 2.0 * xi2 + xi3), 3.0 * xi2 - 2.0 * xi3,
                    L * (xi3 - xi2)},
                   {6.0 * (xi2 - xi) * inv_L, 1.0 - 4.0 * xi + 3.0 * xi2, 6.0 * (xi - xi2) * inv_L,
                    3.0 * xi2 - 2.0 * xi},
                   {(12.0 * xi - 6.0) * inv_L * inv_L, (6.0 * xi - 4.0) * inv_L,
                    (6.0 - 12.0 * xi) * inv_L * inv_L, (6.0 * xi - 2.0) * inv_L}};
}

namespace detail {
// Abscissae and weights of the n-point Gauss–Legendre rule on [−1, 1], ascending,
// stored for n = 1..6 back to back (offset of rule n: n(n−1)/2). 19 significant digits.
inline constexpr std::array<double, 21> kGaussPoints = {
    // n = 1
    0.0,
    // n = 2
    -0.5773502691896257645, 0.5773502691896257645,
    // n = 3
    -0.7745966692414833770, 0.0, 0.7745966692414833770,
    // n = 4
    -0.8611363115940525752, -0.3399810435848562648, 0.3399810435848562648, 0.8611363115940525752,
    // n = 5
    -0.9061798459386639928, -0.5384693101056830910, 0.0, 0.5384693101056830910,
    0.9061798459386639928,
    // n = 6
    -0.9324695142031520279, -0.6612093864662645137, -0.2386191860831969086, 0.2386191860831969086,
    0.6612093864662645137, 0.9324695142031520279};

inline constexpr std::array<double, 21> kGaussWeights = {
    // n = 1
    2.0,
    // n = 2
    1.0, 1.0,
    // n = 3
    0.5555555555555555556, 0.8888888888888888889, 0.5555555555555555556,
    // n = 4
    0.3478548451374538574, 0.6521451548625461427, 0.6521451548625461427, 0.3478548451374538574,
    // n = 5
    0.2369268850561890875, 0.4786286704993664680, 0.5688888888888888889, 0.4786286704993664680,
    0.2369268850561890875,
    // n = 6
    0.1713244923791703450, 0.3607615730481386076, 0.4679139345726910473, 0.4679139345726910473,
    0.3607615730481386076, 0.1713244923791703450};
}  // namespace detail

inline constexpr int kMaxGaussPoints = 6;

// Abscissae ξ_i ∈ (−1, 1) of the n-point Gauss–Legendre rule, 1 ≤ n ≤ 6.
constexpr std::span<const double> gauss_points(int n) {
  CATENA_ASSERT(n >= 1 && n <= kMaxGaussPoints, "Gauss rule: 1 <= n <= 6");
  return std::span<const double>(detail::kGaussPoints)
      .subspan(static_cast<std::size_t>(n * (n - 1) / 2), static_cast<std::size_t>(n));
}

// Weights w_i of the n-point Gauss–Legendre rule on [−1, 1] (Σ w_i = 2), 1 ≤ n ≤ 6.
constexpr std::span<const double> gauss_weights(int n) {
  CATENA_ASSERT(n >= 1 && n <= kMaxGaussPoints, "Gauss rule: 1 <= n <= 6");
  return std::span<const double>(detail::kGaussWeights)
      .subspan(static_cast<std::size_t>(n * (n - 1) / 2), static_cast<std::size_t>(n));
}

}  // namespace catena::elements

// Cubic Hermite shape functions (ANCF ordering) and Gauss–Legendre rules.
// Tolerances: these are exact identities, so only round-off (a few ulps times the size of
// the terms) separates the two sides.
#include <gtest/gtest.h>

#include <cmath>

#include "catena/elements/hermite.hpp"

using catena::elements::gauss_points;
using catena::elements::gauss_weights;
using catena::elements::hermite_at;
using catena::elements::HermiteAt;

namespace {

constexpr double kLengths[] = {1.0, 0.37, 12.5};

// Σ S_i c_i and its x-derivatives for nodal coefficients c = (p_A, p'_A, p_B, p'_B).
struct Field {
  double value, slope, curvature;
};
Field interpolate(const HermiteAt& h, const double c[4]) {
  Field f{0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    f.value += h.s[i] * c[i];
    f.slope += h.ds[i] * c[i];
    f.curvature += h.dds[i] * c[i];
  }
  return f;
}

}  // namespace

TEST(Hermite, NodalInterpolationProperties) {
  for (double L : kLengths) {
    const HermiteAt a = hermite_at(0.0, L), b = hermite_at(L, L);
    const double sa[4] = {1, 0, 0, 0}, dsa[4] = {0, 1, 0, 0};
    const double sb[4] = {0, 0, 1, 0}, dsb[4] = {0, 0, 0, 1};
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(a.s[i], sa[i], 1e-15);
      EXPECT_NEAR(a.ds[i], dsa[i], 1e-14);
      EXPECT_NEAR(b.s[i], sb[i], 1e-14);
      EXPECT_NEAR(b.ds[i], dsb[i], 1e-14);
    }
  }
}

TEST(Hermite, PartitionOfUnity) {
  for (double L : kLengths)
    for (int k = 0; k <= 20; ++k) {
      const HermiteAt h = hermite_at(L * k / 20.0, L);
      EXPECT_NEAR(h.s[0] + h.s[2], 1.0, 1e-15);
      EXPECT_NEAR(h.ds[0] + h.ds[2], 0.0, 1e-14 / L);
      EXPECT_NEAR(h.dds[0] + h.dds[2], 0.0, 1e-13 / (L * L));
    }
}

TEST(Hermite, ReproducesLinearAndCubicFields) {
  for (double L : kLengths) {
    // p(x) = a + b x + c x² + d x³ from its nodal values and slopes.
    const double a = 0.3, b = -1.7, c = 0.9, d = 2.2;
    const auto p = [&](double x) { return a + b * x + c * x * x + d * x * x * x; };
    const auto dp = [&](double x) { return b + 2 * c * x + 3 * d * x * x; };
    const auto ddp = [&](double x) { return 2 * c + 6 * d * x; };
    const double cubic[4] = {p(0), dp(0), p(L), dp(L)};
    const double linear[4] = {a, b, a + b * L, b};
    for (int k = 0; k <= 20; ++k) {
      const double x = L * k / 20.0;
      const HermiteAt h = hermite_at(x, L);
      const Field fc = interpolate(h, cubic), fl = interpolate(h, linear);
      const double scale = 1.0 + std::abs(d) * L * L * L;
      EXPECT_NEAR(fc.value, p(x), 1e-13 * scale);
      EXPECT_NEAR(fc.slope, dp(x), 1e-13 * scale / L);
      EXPECT_NEAR(fc.curvature, ddp(x), 1e-12 * scale / (L * L));
      EXPECT_NEAR(fl.value, a + b * x, 1e-13 * (1 + std::abs(b) * L));
      EXPECT_NEAR(fl.slope, b, 1e-13 * (1 + std::abs(b)));
      EXPECT_NEAR(fl.curvature, 0.0, 1e-12 * (1 + std::abs(b)) / L);
    }
  }
}

TEST(Hermite, DerivativesMatchFiniteDifferencesOfValues) {
  const double L = 0.8, h = 1e-6;
  for (int k = 1; k < 10; ++k) {
    const double x = L * k / 10.0;
    const HermiteAt c = hermite_at(x, L), p = hermite_at(x + h, L), m = hermite_at(x - h, L);
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(c.ds[i], (p.s[i] - m.s[i]) / (2 * h), 1e-8);
      EXPECT_NEAR(c.dds[i], (p.ds[i] - m.ds[i]) / (2 * h), 1e-7);
    }
  }
}

TEST(Gauss, IntegratesPolynomialsOfDegree2nMinus1Exactly) {
  for (int n = 1; n <= catena::elements::kMaxGaussPoints; ++n) {
    const auto x = gauss_points(n);
    const auto w = gauss_weights(n);
    ASSERT_EQ(static_cast<int>(x.size()), n);
    ASSERT_EQ(static_cast<int>(w.size()), n);
    for (int degree = 0; degree <= 2 * n; ++degree) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += w[i] * std::pow(x[i], degree);
      const double exact = degree % 2 == 1 ? 0.0 : 2.0 / (degree + 1);
      if (degree <= 2 * n - 1) {
        EXPECT_NEAR(sum, exact, 4e-16) << "n = " << n << ", degree = " << degree;
      } else {
        // Degree 2n is not integrated exactly: the rule has exactly degree 2n − 1.
        EXPECT_GT(std::abs(sum - exact), 1e-4) << "n = " << n;
      }
    }
  }
}

TEST(Gauss, PointsAreSymmetricAndAscending) {
  for (int n = 1; n <= catena::elements::kMaxGaussPoints; ++n) {
    const auto x = gauss_points(n);
    const auto w = gauss_weights(n);
    for (int i = 0; i < n; ++i) {
      EXPECT_DOUBLE_EQ(x[i], -x[n - 1 - i]);
      EXPECT_DOUBLE_EQ(w[i], w[n - 1 - i]);
      EXPECT_GT(w[i], 0.0);
      if (i > 0) {
        EXPECT_LT(x[i - 1], x[i]);
      }
    }
  }
}

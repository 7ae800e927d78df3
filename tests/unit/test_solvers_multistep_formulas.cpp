// The multistep formulas (solvers/time/multistep/multistep_formulas.hpp) against
// independent truth: at constant steps BDF-k's weights are the published table
// (Hairer & Wanner II, V.1, Table 1.1: Σ_{j=1..k} (1/j) ∇^j y), Park's are
// (10, −15, 6, −1)/(6h) (Park 1975); on an irregular grid every formula is exact for the
// polynomials of its degree and the predictor's error has the leading term of Hermite
// interpolation, which the integrator's error estimate rests on.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <complex>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "catena/solvers/time/multistep/multistep_formulas.hpp"

namespace solvers = catena::solvers;

namespace {

// t₀ = t_new, then past times with the given steps back from it.
std::vector<double> grid(double t_new, const std::vector<double>& steps) {
  std::vector<double> t{t_new};
  for (double h : steps) t.push_back(t.back() - h);
  return t;
}

double power(double t, int m) { return std::pow(t, m); }
double power_derivative(double t, int m) { return m == 0 ? 0.0 : m * std::pow(t, m - 1); }

}  // namespace

TEST(MultistepFormulas, BdfWeightsAtConstantStepsAreTheTable) {
  const double h = 0.01;
  const std::vector<double> t = grid(2.0, {h, h, h, h, h});
  // h·w_j for k = 1 ... 5.
  const std::vector<std::vector<double>> table{{1.0, -1.0},
                                               {1.5, -2.0, 0.5},
                                               {11.0 / 6, -3.0, 1.5, -1.0 / 3},
                                               {25.0 / 12, -4.0, 3.0, -4.0 / 3, 0.25},
                                               {137.0 / 60, -5.0, 5.0, -10.0 / 3, 1.25, -0.2}};
  for (int k = 1; k <= 5; ++k) {
    const std::vector<double> w = solvers::bdf_weights(t, k);
    ASSERT_EQ(w.size(), static_cast<std::size_t>(k + 1));
    for (int j = 0; j <= k; ++j)
      EXPECT_NEAR(h * w[static_cast<std::size_t>(j)],
                  table[static_cast<std::size_t>(k - 1)][static_cast<std::size_t>(j)], 1e-11)
          << "k = " << k << ", j = " << j;
  }
}

TEST(MultistepFormulas, ParkWeightsAtConstantStepsArePark1975) {
  const double h = 2.5e-4;
  const std::vector<double> w = solvers::park_weights(grid(1.0, {h, h, h}));
  const double expected[] = {10.0, -15.0, 6.0, -1.0};
  ASSERT_EQ(w.size(), 4u);
  for (std::size_t j = 0; j < 4; ++j) EXPECT_NEAR(6.0 * h * w[j], expected[j], 1e-10) << j;
}

TEST(MultistepFormulas, VariableStepFormulasAreExactForTheirDegree) {
  // An irregular grid (ratios 0.5 to 3) in microseconds and in seconds: the scaling inside
  // interpolation_weights keeps both accurate.
  for (const double unit : {1e-6, 1.0}) {
    const std::vector<double> steps{1.0 * unit, 3.0 * unit, 0.5 * unit, 2.0 * unit, 1.5 * unit};
    const double t_new = 10.0 * unit;
    const std::vector<double> t = grid(t_new, steps);
    // Polynomials in (t − c)/unit, centred off the grid.
    const double c = 3.0 * unit;
    for (int k = 1; k <= 5; ++k) {
      const std::vector<double> w = solvers::bdf_weights(t, k);
      for (int m = 0; m <= k; ++m) {
        double d = 0.0;
        for (int j = 0; j <= k; ++j)
          d += w[static_cast<std::size_t>(j)] *
               power((t[static_cast<std::size_t>(j)] - c) / unit, m);
        const double exact = power_derivative((t_new - c) / unit, m) / unit;
        EXPECT_NEAR(d * unit, exact * unit, 1e-9 * (1 + std::abs(exact * unit)))
            << "BDF-" << k << " on degree " << m << ", unit " << unit;
      }
    }
    // The predictor: s y'(t₁) + Σ c_j y(t_j) = y(t₀) for degree ≤ p.
    for (int p = 1; p <= 5; ++p) {
      const std::vector<double> s = solvers::hermite_predictor_weights(t, p);
      ASSERT_EQ(s.size(), static_cast<std::size_t>(p + 1));
      for (int m = 0; m <= p; ++m) {
        double y = s[0] * power_derivative((t[1] - c) / unit, m) / unit;
        for (int j = 1; j <= p; ++j)
          y += s[static_cast<std::size_t>(j)] *
               power((t[static_cast<std::size_t>(j)] - c) / unit, m);
        const double exact = power((t_new - c) / unit, m);
        EXPECT_NEAR(y, exact, 1e-9 * (1 + std::abs(exact)))
            << "predictor p = " << p << ", m = " << m;
      }
    }
  }
}

// The integrator's error estimate takes y(t₀) − ŷ = y^(p+1)/(p+1)! · (t₀ − t₁)² Π_{j=2..p}
// (t₀ − t_j) (Hermite's remainder, t₁ a double node); checked on y = t^(p+1), whose
// (p+1)-th derivative is (p+1)!, so the remainder is exactly the product.
TEST(MultistepFormulas, PredictorErrorIsHermitesRemainder) {
  const std::vector<double> t = grid(1.0, {0.1, 0.25, 0.05, 0.2, 0.15});
  for (int p = 1; p <= 5; ++p) {
    const std::vector<double> s = solvers::hermite_predictor_weights(t, p);
    double y = s[0] * power_derivative(t[1], p + 1);
    for (int j = 1; j <= p; ++j)
      y += s[static_cast<std::size_t>(j)] * power(t[static_cast<std::size_t>(j)], p + 1);
    double product = (t[0] - t[1]) * (t[0] - t[1]);
    for (int j = 2; j <= p; ++j) product *= t[0] - t[static_cast<std::size_t>(j)];
    EXPECT_NEAR(power(t[0], p + 1) - y, product, 1e-12) << "p = " << p;
  }
}

TEST(MultistepFormulas, RefusesDataThatDoNotDetermineThePolynomial) {
  const std::vector<solvers::InterpolationDatum> repeated{{1.0, 0}, {1.0, 0}};
  EXPECT_THROW(solvers::interpolation_weights(repeated, 2.0, 1), std::invalid_argument);
  const std::vector<double> t{1.0, 0.9};
  EXPECT_THROW(solvers::bdf_weights(t, 2), std::invalid_argument);
  EXPECT_THROW(solvers::bdf_weights(t, 0), std::invalid_argument);
}

// The Adams weights: at constant steps AB-2 (3/2, −1/2)h and the trapezoidal rule (½, ½)h
// (Hairer, Nørsett & Wanner I, III.1); on an irregular grid exact for the integral of
// every polynomial of the data's degree.
TEST(MultistepFormulas, AdamsWeightsIntegrateTheirDegreeExactly) {
  const double h = 0.02;
  const std::vector<double> bashforth =
      solvers::integration_weights(std::vector<double>{1.0, 1.0 - h}, 1.0, 1.0 + h);
  EXPECT_NEAR(bashforth[0] / h, 1.5, 1e-12);
  EXPECT_NEAR(bashforth[1] / h, -0.5, 1e-12);
  const std::vector<double> moulton =
      solvers::integration_weights(std::vector<double>{1.0 + h, 1.0}, 1.0, 1.0 + h);
  EXPECT_NEAR(moulton[0] / h, 0.5, 1e-12);
  EXPECT_NEAR(moulton[1] / h, 0.5, 1e-12);
  const std::vector<double> t{0.3, 0.1, -0.25, -0.3};
  const std::vector<double> w = solvers::integration_weights(t, 0.1, 0.4);
  for (int m = 0; m < 4; ++m) {
    double sum = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) sum += w[i] * power(t[i], m);
    const double exact = (power(0.4, m + 1) - power(0.1, m + 1)) / (m + 1);
    EXPECT_NEAR(sum, exact, 1e-13) << "degree " << m;
  }
}

namespace {

// The largest root, other than 1, of the recurrence Σ_j w_j y_{n+1−j} = 0 of a formula
// applied on a grid whose steps grow by `ratio` each step: on such a grid the weights,
// times the newest step, are the same at every step, so its zero-stability is that of a
// constant-coefficient recurrence.
double parasitic_root(bool park, int k, double ratio) {
  std::vector<double> t{0.0};
  double h = 1.0;
  for (int j = 0; j < 6; ++j) {
    t.push_back(t.back() - h);
    h /= ratio;
  }
  const std::vector<double> w = park ? solvers::park_weights(t) : solvers::bdf_weights(t, k);
  const int n = static_cast<int>(w.size()) - 1;
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) companion(0, j) = -w[static_cast<std::size_t>(j + 1)] / w[0];
  for (int i = 1; i < n; ++i) companion(i, i - 1) = 1.0;
  double largest = 0.0;
  bool skipped_one = false;
  for (const std::complex<double>& z : companion.eigenvalues()) {
    if (!skipped_one && std::abs(z - 1.0) < 1e-8) {
      skipped_one = true;  // consistency: constants are reproduced
      continue;
    }
    largest = std::max(largest, std::abs(z));
  }
  return largest;
}

}  // namespace

// The step-growth caps of MultistepIntegrator (2, 1.5, 1.2, 1.1 for BDF-2 to 5, 1.8 for
// Park) lie below each formula's zero-stability limit on steadily growing steps, and the
// limits quoted in docs/integrators.md (1 + √2, 1.618, 1.281, 1.127, 1.909) are where a
// root reaches the unit circle: stable at the cap, unstable 2 % past the limit.
TEST(MultistepFormulas, StepGrowthCapsAreBelowTheZeroStabilityLimits) {
  struct Case {
    bool park;
    int k;
    double cap, limit;
  };
  for (const Case& c :
       {Case{false, 2, 2.0, 1.0 + std::sqrt(2.0)}, Case{false, 3, 1.5, 1.618},
        Case{false, 4, 1.2, 1.281}, Case{false, 5, 1.1, 1.127}, Case{true, 3, 1.8, 1.909}}) {
    const char* name = c.park ? "park" : "bdf";
    EXPECT_LT(parasitic_root(c.park, c.k, c.cap), 1.0) << name << c.k;
    EXPECT_LT(parasitic_root(c.park, c.k, 0.995 * c.limit), 1.0) << name << c.k;
    EXPECT_GT(parasitic_root(c.park, c.k, 1.02 * c.limit), 1.0) << name << c.k;
  }
}

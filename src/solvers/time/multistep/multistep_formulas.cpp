#include "catena/solvers/time/multistep/multistep_formulas.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace catena::solvers {
namespace {

// r-th derivative of s^m at s, for the monomial basis of interpolation_weights.
double monomial_derivative(int m, int r, double s) {
  if (r > m) return 0.0;
  double factor = 1.0;
  for (int i = 0; i < r; ++i) factor *= static_cast<double>(m - i);
  return factor * std::pow(s, m - r);
}

}  // namespace

std::vector<double> interpolation_weights(std::span<const InterpolationDatum> data, double target,
                                          int derivative) {
  const int n = static_cast<int>(data.size());
  if (n == 0) throw std::invalid_argument("interpolation_weights: no data");
  // The basis s^m, s = (t − target)/L, exact for every polynomial of degree < n; the scale L
  // keeps the small system well conditioned whatever the step (seconds or microseconds).
  double scale = 0.0;
  for (const InterpolationDatum& d : data) scale = std::max(scale, std::abs(d.time - target));
  if (!(scale > 0.0)) scale = 1.0;
  // Row m: the data functionals applied to s^m; the weights reproduce the target's.
  Eigen::MatrixXd basis(n, n);
  Eigen::VectorXd wanted = Eigen::VectorXd::Zero(n);
  for (int m = 0; m < n; ++m) {
    for (int i = 0; i < n; ++i) {
      const InterpolationDatum& d = data[static_cast<std::size_t>(i)];
      basis(m, i) = monomial_derivative(m, d.derivative, (d.time - target) / scale) /
                    std::pow(scale, d.derivative);
    }
    if (m == derivative) wanted(m) = monomial_derivative(m, derivative, 0.0) / std::pow(scale, m);
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(basis);
  if (lu.rank() < n)
    throw std::invalid_argument("interpolation_weights: the data do not determine the polynomial");
  const Eigen::VectorXd c = lu.solve(wanted);
  return {c.data(), c.data() + n};
}

std::vector<double> integration_weights(std::span<const double> times, double from, double to) {
  const int n = static_cast<int>(times.size());
  if (n == 0) throw std::invalid_argument("integration_weights: no data");
  // As interpolation_weights, with the functional ∫ s^m dt = L (s_to^{m+1} − s_from^{m+1})/(m+1).
  double scale = std::abs(to - from);
  for (double t : times) scale = std::max(scale, std::abs(t - from));
  if (!(scale > 0.0)) scale = 1.0;
  const double a = 0.0, b = (to - from) / scale;
  Eigen::MatrixXd basis(n, n);
  Eigen::VectorXd wanted(n);
  for (int m = 0; m < n; ++m) {
    for (int i = 0; i < n; ++i)
      basis(m, i) = std::pow((times[static_cast<std::size_t>(i)] - from) / scale, m);
    wanted(m) = scale * (std::pow(b, m + 1) - std::pow(a, m + 1)) / (m + 1);
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(basis);
  if (lu.rank() < n)
    throw std::invalid_argument("integration_weights: the data do not determine the polynomial");
  const Eigen::VectorXd c = lu.solve(wanted);
  return {c.data(), c.data() + n};
}

std::vector<double> bdf_weights(std::span<const double> times, int k) {
  if (k < 1 || static_cast<int>(times.size()) < k + 1)
    throw std::invalid_argument("bdf_weights: order below 1 or too few times");
  std::vector<InterpolationDatum> data;
  for (int j = 0; j <= k; ++j) data.push_back({times[static_cast<std::size_t>(j)], 0});
  return interpolation_weights(data, times[0], 1);
}

std::vector<double> park_weights(std::span<const double> times) {
  std::vector<double> w = bdf_weights(times, 3);
  const std::vector<double> two = bdf_weights(times, 2);
  for (std::size_t j = 0; j < w.size(); ++j) w[j] = 0.5 * (w[j] + (j < two.size() ? two[j] : 0.0));
  return w;
}

std::vector<double> hermite_predictor_weights(std::span<const double> times, int p) {
  if (p < 1 || static_cast<int>(times.size()) < p + 1)
    throw std::invalid_argument("hermite_predictor_weights: degree below 1 or too few times");
  std::vector<InterpolationDatum> data{{times[1], 1}};
  for (int j = 1; j <= p; ++j) data.push_back({times[static_cast<std::size_t>(j)], 0});
  return interpolation_weights(data, times[0], 0);
}

}  // namespace catena::solvers

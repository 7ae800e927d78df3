#include "extensible_elastica.hpp"

#include <cmath>

namespace catena::test {
namespace {

struct State {
  double theta, m, x, y;
};

State derivative(const Cantilever& c, const State& z, CurvatureMeasure law) {
  const double N = c.load * std::sin(z.theta);
  double lambda = 1.0 + N / c.EA, dtheta = z.m / c.EI;
  if (law == CurvatureMeasure::deformed_length) {
    lambda = (c.EA + N) / (c.EA - z.m * z.m / c.EI);
    dtheta = z.m * lambda * lambda / c.EI;
  }
  const double cs = std::cos(z.theta), sn = std::sin(z.theta);
  return {dtheta, -lambda * c.load * cs, lambda * cs, lambda * sn};
}

State axpy(const State& a, double t, const State& d) {
  return {a.theta + t * d.theta, a.m + t * d.m, a.x + t * d.x, a.y + t * d.y};
}

State integrate(const Cantilever& c, double m0, CurvatureMeasure law) {
  const int n = 4000;
  const double h = c.length / n;
  State z{0.0, m0, 0.0, 0.0};
  for (int i = 0; i < n; ++i) {
    const State k1 = derivative(c, z, law);
    const State k2 = derivative(c, axpy(z, 0.5 * h, k1), law);
    const State k3 = derivative(c, axpy(z, 0.5 * h, k2), law);
    const State k4 = derivative(c, axpy(z, h, k3), law);
    z = {z.theta + h / 6 * (k1.theta + 2 * k2.theta + 2 * k3.theta + k4.theta),
         z.m + h / 6 * (k1.m + 2 * k2.m + 2 * k3.m + k4.m),
         z.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
         z.y + h / 6 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y)};
  }
  return z;
}

}  // namespace

CantileverTip elastica_tip(const Cantilever& c, CurvatureMeasure law) {
  // m(L) grows with m(0).
  double lo = 0.5 * c.load * c.length, hi = 1.5 * c.load * c.length;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (integrate(c, mid, law).m > 0.0 ? hi : lo) = mid;
  }
  const State end = integrate(c, 0.5 * (lo + hi), law);
  return {c.length - end.x, end.y};
}

}  // namespace catena::test

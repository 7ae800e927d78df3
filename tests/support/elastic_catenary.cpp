#include "elastic_catenary.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

namespace catena::test {

ElasticCatenary::ElasticCatenary(const Vec3& p_a, const Vec3& p_b, double unstretched_length,
                                 double EA, double q, const Vec3& load_direction)
    : p_a_(p_a), L0_(unstretched_length), EA_(EA), q_(q), u_(load_direction.normalized()) {
  // Initial guess: at s = 0 the tension points along the cable, down the load direction
  // (dt/ds = −q u), carrying about half the weight, plus a horizontal pull towards B.
  const Vec3 chord = p_b - p_a;
  t0_ = 0.5 * q_ * L0_ * u_ + q_ * L0_ * (chord - chord.dot(u_) * u_).normalized();
  for (int it = 0; it < 100; ++it) {
    const Vec3 r = position_with(t0_, L0_) - p_b;
    if (r.norm() < 1e-13 * L0_) return;
    Mat3 J;
    for (int j = 0; j < 3; ++j) {
      const double h = 1e-7 * (1.0 + t0_.norm());
      Vec3 tp = t0_, tm = t0_;
      tp[j] += h;
      tm[j] -= h;
      J.col(j) = (position_with(tp, L0_) - position_with(tm, L0_)) / (2 * h);
    }
    // Damped Newton: halve the step until the end-point miss decreases.
    const Vec3 step = J.fullPivLu().solve(r);
    double alpha = 1.0;
    while (alpha > 1e-4 && !((position_with(t0_ - alpha * step, L0_) - p_b).norm() < r.norm()))
      alpha *= 0.5;
    t0_ -= alpha * step;
  }
  throw std::runtime_error("ElasticCatenary: end condition did not converge");
}

Vec3 ElasticCatenary::position_with(const Vec3& t0, double s) const {
  const Vec3 a = t0 / q_;
  const Vec3 ts = t0 - s * q_ * u_;
  const double rho_s = ts.norm() - u_.dot(ts), rho_0 = t0.norm() - u_.dot(t0);
  const Mat3 P = Mat3::Identity() - u_ * u_.transpose();
  return p_a_ + P * a * std::log(rho_s / rho_0) - u_ * ((a - s * u_).norm() - a.norm()) +
         (q_ * s / EA_) * (a - 0.5 * s * u_);
}

Vec3 ElasticCatenary::position(double s) const { return position_with(t0_, s); }

}  // namespace catena::test

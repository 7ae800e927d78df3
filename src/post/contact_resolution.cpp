#include "catena/post/contact_resolution.hpp"

#include <cmath>

namespace catena::post {

void ContactResolution::add(double force) {
  if (n_ >= 2) {
    const double d = force - 2.0 * previous_ + before_;
    d2_sum_ += d * d;
  }
  before_ = previous_;
  previous_ = force;
  ++n_;
  const double delta = force - mean_;
  mean_ += delta / static_cast<double>(n_);
  m2_ += delta * (force - mean_);
}

double ContactResolution::roughness() const {
  if (n_ < 3 || m2_ <= 0.0) return 0.0;
  const double variance = m2_ / static_cast<double>(n_);
  const double d2_mean = d2_sum_ / static_cast<double>(n_ - 2);
  return std::sqrt(d2_mean / variance);
}

}  // namespace catena::post

#include "catena/elements/surface_contact.hpp"

#include <cmath>

namespace catena::elements {
namespace {

Vec3 load3(std::span<const double> x) { return {x[0], x[1], x[2]}; }

}  // namespace

SurfaceContact::SurfaceContact(const SurfaceContactLaw& law) : law_(law) {
  law_.normal.normalize();
}

double SurfaceContact::normal_force(std::span<const double> x, std::span<const double> v) const {
  const Vec3& n = law_.normal;
  const double gap = (load3(x) - law_.point).dot(n);
  if (gap >= 0.0) return 0.0;
  const double rate = v.empty() ? 0.0 : load3(v).dot(n);
  return std::max(0.0, -law_.stiffness * gap - law_.damping * rate);
}

void SurfaceContact::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  if (r.force)
    for (int k = 0; k < 3; ++k) out.f[k] = 0.0;
  if (r.stiffness)
    for (int k = 0; k < 9; ++k) out.K[k] = 0.0;
  if (r.damping)
    for (int k = 0; k < 9; ++k) out.C[k] = 0.0;
  const double N = normal_force(s.q, s.v);
  if (N <= 0.0) return;
  const Vec3& n = law_.normal;
  const Vec3 v = s.v.empty() ? Vec3::Zero() : load3(s.v);
  const Vec3 slide = v - v.dot(n) * n;  // v_t
  const double speed = std::sqrt(slide.squaredNorm() + law_.stick_speed * law_.stick_speed);
  const Vec3 phi = law_.friction > 0.0 ? Vec3(slide / speed) : Vec3::Zero();
  const double mu = law_.friction;
  if (r.force) {
    const Vec3 f = -N * n + mu * N * phi;
    for (int k = 0; k < 3; ++k) out.f[k] = f[k];
  }
  const Vec3 direction = n - mu * phi;  // ∂f/∂N, up to the sign of ∂N
  if (r.stiffness) {
    const Mat3 K = law_.stiffness * direction * n.transpose();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.K[3 * i + j] = K(i, j);
  }
  if (r.damping) {
    Mat3 C = law_.damping * direction * n.transpose();
    if (mu > 0.0) {
      const Mat3 projection = Mat3::Identity() - n * n.transpose();
      const Mat3 dphi = (Mat3::Identity() - slide * slide.transpose() / (speed * speed)) / speed;
      C += mu * N * dphi * projection;
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.C[3 * i + j] = C(i, j);
  }
}

void SurfaceContact::mass(double* M) const {
  for (int k = 0; k < 9; ++k) M[k] = 0.0;
}

SectionResult SurfaceContact::section_result(const LocalState&) const { return {}; }

}  // namespace catena::elements

#include "catena/elements/linear_spring.hpp"

namespace catena::elements {
namespace {

// Force of the spring–damper on its far end for relative motion (d, dv).
Vec3 spring_force(const SpringSection& s, const Vec3& d, const Vec3& dv) {
  return s.stiffness.cwiseProduct(d) + s.damping.cwiseProduct(dv);
}

Vec3 load3(std::span<const double> x, int offset) {
  return Vec3(x[offset], x[offset + 1], x[offset + 2]);
}

}  // namespace

LinearSpring::LinearSpring(const Vec3& reference_a, const Vec3& reference_b,
                           const SpringSection& section)
    : reference_offset_(reference_b - reference_a), section_(section) {}

void LinearSpring::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  if (r.force) {
    const Vec3 d = load3(s.q, 3) - load3(s.q, 0) - reference_offset_;
    const Vec3 dv = s.v.empty() ? Vec3::Zero() : Vec3(load3(s.v, 3) - load3(s.v, 0));
    const Vec3 f = spring_force(section_, d, dv);
    for (int k = 0; k < 3; ++k) {
      out.f[k] = -f[k];
      out.f[3 + k] = f[k];
    }
  }
  auto scatter = [](const Vec3& diag, double* dst) {
    for (int k = 0; k < 36; ++k) dst[k] = 0.0;
    for (int k = 0; k < 3; ++k) {
      dst[k * 6 + k] = diag[k];
      dst[(3 + k) * 6 + 3 + k] = diag[k];
      dst[k * 6 + 3 + k] = -diag[k];
      dst[(3 + k) * 6 + k] = -diag[k];
    }
  };
  if (r.stiffness) scatter(section_.stiffness, out.K);
  if (r.damping) scatter(section_.damping, out.C);
}

void LinearSpring::mass(double* M) const {
  for (int k = 0; k < 36; ++k) M[k] = 0.0;
}

SectionResult LinearSpring::section_result(const LocalState& s) const {
  // Axial force: the spring force projected on the current spring axis (tension positive).
  const Vec3 axis = load3(s.q, 3) - load3(s.q, 0);
  const Vec3 f = spring_force(section_, axis - reference_offset_, Vec3::Zero());
  const double l = axis.norm(), l0 = reference_offset_.norm();
  if (l == 0.0) return {};
  return {f.dot(axis) / l, l0 > 0.0 ? l / l0 - 1.0 : 0.0};
}

GroundSpring::GroundSpring(const Vec3& reference, const SpringSection& section)
    : reference_(reference), section_(section) {}

void GroundSpring::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  if (r.force) {
    const Vec3 dv = s.v.empty() ? Vec3::Zero() : load3(s.v, 0);
    const Vec3 f = spring_force(section_, load3(s.q, 0) - reference_, dv);
    for (int k = 0; k < 3; ++k) out.f[k] = f[k];
  }
  auto scatter = [](const Vec3& diag, double* dst) {
    for (int k = 0; k < 9; ++k) dst[k] = 0.0;
    for (int k = 0; k < 3; ++k) dst[k * 3 + k] = diag[k];
  };
  if (r.stiffness) scatter(section_.stiffness, out.K);
  if (r.damping) scatter(section_.damping, out.C);
}

void GroundSpring::mass(double* M) const {
  for (int k = 0; k < 9; ++k) M[k] = 0.0;
}

SectionResult GroundSpring::section_result(const LocalState&) const { return {}; }

}  // namespace catena::elements

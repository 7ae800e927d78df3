#include "catena/elements/tension_bar.hpp"

#include "catena/core/error.hpp"

#include <cmath>

namespace catena::elements {

TensionBar::TensionBar(double unstretched_length, const BarSection& section, const Vec3& gravity,
                       double mesh_length)
    : l0_(unstretched_length),
      mesh_length_(mesh_length),
      section_(section),
      node_weight_(0.5 * section.mass_per_length * unstretched_length * gravity) {
  CATENA_ASSERT(l0_ > 0.0, "TensionBar: unstretched length must be positive");
  CATENA_ASSERT(mesh_length_ >= 0.0, "TensionBar: mesh length must not be negative");
}

double TensionBar::unstretched_length(const LoadPath& path) const {
  if (mesh_length_ <= 0.0) return l0_;
  return mesh_length_ + path.loads * (l0_ - mesh_length_);
}

void TensionBar::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  const Vec3 d(s.q[3] - s.q[0], s.q[4] - s.q[1], s.q[5] - s.q[2]);
  const double l = d.norm();
  const Vec3 e = d / l;
  const double l0 = unstretched_length(s.path);
  const double eps = l / l0 - 1.0;
  const bool slack = section_.tension_only && eps < 0.0;
  const double EA = slack ? 0.0 : section_.EA;
  const double c = slack ? 0.0 : section_.damping;
  Vec3 dv = Vec3::Zero();
  if (!s.v.empty()) dv = Vec3(s.v[3] - s.v[0], s.v[4] - s.v[1], s.v[5] - s.v[2]);
  const double l_rate = e.dot(dv);
  const double N = EA * eps + c * l_rate;

  if (r.force) {
    const Vec3 fB = N * e - s.path.loads * node_weight_;
    const Vec3 fA = -N * e - s.path.loads * node_weight_;
    for (int k = 0; k < 3; ++k) {
      out.f[k] = fA[k];
      out.f[3 + k] = fB[k];
    }
  }
  auto scatter = [](const Mat3& B, double* dst) {
    // [[B, −B], [−B, B]] in a 6×6 row-major matrix.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        dst[i * 6 + j] = B(i, j);
        dst[i * 6 + 3 + j] = -B(i, j);
        dst[(3 + i) * 6 + j] = -B(i, j);
        dst[(3 + i) * 6 + 3 + j] = B(i, j);
      }
  };
  const Mat3 P = (Mat3::Identity() - e * e.transpose()) / l;  // ∂e/∂d
  if (r.stiffness) {
    // ∂(N e)/∂d = e ∂N/∂dᵀ + N ∂e/∂d, ∂N/∂d = (EA/l0) e + c Pᵀ Δv.
    const Mat3 Kb = e * ((EA / l0) * e + c * (P * dv)).transpose() + N * P;
    scatter(Kb, out.K);
  }
  if (r.damping) scatter(c * e * e.transpose(), out.C);
}

void TensionBar::mass(double* M) const {
  const double m = 0.5 * section_.mass_per_length * l0_;
  for (int k = 0; k < 36; ++k) M[k] = 0.0;
  for (int k = 0; k < 6; ++k) M[k * 6 + k] = m;
}

SectionResult TensionBar::section_result(const LocalState& s) const {
  const Vec3 d(s.q[3] - s.q[0], s.q[4] - s.q[1], s.q[5] - s.q[2]);
  const double eps = d.norm() / unstretched_length(s.path) - 1.0;
  const bool slack = section_.tension_only && eps < 0.0;
  return {slack ? 0.0 : section_.EA * eps, eps};
}

}  // namespace catena::elements

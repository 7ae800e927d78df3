#include "catena/elements/absorbing_end.hpp"

#include <cmath>

namespace catena::elements {

AbsorbingEndLaw cable_end_law(const Vec3& end_force, double EA, double mass_per_length) {
  const double T = end_force.norm();
  const Vec3 t = end_force / T;
  const double stretch = 1.0 + T / EA;
  const double axial = std::sqrt(EA * mass_per_length);
  const double transverse = std::sqrt(T * mass_per_length / stretch);
  const Mat3 along = t * t.transpose();
  return {end_force, axial * along + transverse * (Mat3::Identity() - along)};
}

void AbsorbingEnd::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  constexpr int n = 6;  // [r, r_x]
  if (r.force) {
    Vec3 f = -law_.force;
    if (!s.v.empty()) f += law_.damping * Vec3(s.v[0], s.v[1], s.v[2]);
    for (int k = 0; k < 3; ++k) {
      out.f[k] = f[k];
      out.f[3 + k] = -law_.slope_force[k];
    }
  }
  if (r.stiffness)
    for (int k = 0; k < n * n; ++k) out.K[k] = 0.0;
  if (r.damping) {
    for (int k = 0; k < n * n; ++k) out.C[k] = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.C[i * n + j] = law_.damping(i, j);
  }
}

void AbsorbingEnd::mass(double* M) const {
  for (int k = 0; k < 36; ++k) M[k] = 0.0;
}

}  // namespace catena::elements

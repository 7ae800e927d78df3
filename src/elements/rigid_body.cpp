#include "catena/elements/rigid_body.hpp"

#include <algorithm>

namespace catena::elements {

RigidBodyInertia::RigidBodyInertia(double mass, const Vec3& centre_of_mass, const Mat3& inertia,
                                   const Vec3& gravity)
    : gravity_(gravity) {
  // J = ∫ρ ξ ξᵀ dV about r: about the centre of mass ½ tr(I_c) 1 − I_c, moved by Steiner.
  const Mat3 second_moment = 0.5 * inertia.trace() * Mat3::Identity() - inertia +
                             mass * centre_of_mass * centre_of_mass.transpose();
  coefficients_(0, 0) = mass;
  coefficients_.block<1, 3>(0, 1) = mass * centre_of_mass.transpose();
  coefficients_.block<3, 1>(1, 0) = mass * centre_of_mass;
  coefficients_.block<3, 3>(1, 1) = second_moment;
}

void RigidBodyInertia::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  if (r.force)  // −λ_path (m g, m ξc_k g): the first column of M̂ times g
    for (int b = 0; b < 4; ++b)
      for (int d = 0; d < 3; ++d)
        out.f[3 * b + d] = -s.path.loads * coefficients_(b, 0) * gravity_[d];
  if (r.stiffness) std::fill(out.K, out.K + 144, 0.0);
  if (r.damping) std::fill(out.C, out.C + 144, 0.0);
}

void RigidBodyInertia::mass(double* M) const {
  std::fill(M, M + 144, 0.0);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int d = 0; d < 3; ++d) M[(3 * a + d) * 12 + 3 * b + d] = coefficients_(a, b);
}

}  // namespace catena::elements

#include "catena/elements/point_mass.hpp"

namespace catena::elements {
namespace {
void zero(double* a, int n) {
  for (int k = 0; k < n; ++k) a[k] = 0.0;
}
}  // namespace

void PointMass::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  if (r.force)
    for (int k = 0; k < 3; ++k) out.f[k] = -s.path.loads * mass_ * gravity_[k];
  if (r.stiffness) zero(out.K, 9);
  if (r.damping) zero(out.C, 9);
}

void PointMass::mass(double* M) const {
  zero(M, 9);
  for (int k = 0; k < 3; ++k) M[4 * k] = mass_;
}

void NodalForce::evaluate(const LocalState& s, Request r, LocalOutput out) const {
  if (r.force)
    for (int k = 0; k < 3; ++k) out.f[k] = -s.path.loads * force_[k];
  if (r.stiffness) zero(out.K, 9);
  if (r.damping) zero(out.C, 9);
}

void NodalForce::mass(double* M) const { zero(M, 9); }

}  // namespace catena::elements

#pragma once
// The elastic catenary in closed form (Irvine, "Cable Structures", 1981; vector form of
// Greco, Impollonia & Cuomo, IJSS 2014), the independent truth for the cable statics tests.
// A cable of unstretched length L0, axial stiffness EA, under a uniform load q·u per unit
// unstretched length, hangs between p_A and p_B. With t0 the tension vector at s = 0:
//   t(s) = t0 − s q u,  ρ(s) = |t(s)| − uᵀ t(s),
//   p(s) = p_A + (I − uuᵀ)(t0/q) ln(ρ(s)/ρ(0)) − u(|t0/q − s u| − |t0/q|)
//              + (q s/EA)(t0/q − (s/2) u).
#include "catena/core/vec3.hpp"

namespace catena::test {

class ElasticCatenary {
 public:
  // Solves the end condition p(L0) = p_B for t0 by Newton's method.
  ElasticCatenary(const Vec3& p_a, const Vec3& p_b, double unstretched_length, double EA, double q,
                  const Vec3& load_direction);
  Vec3 position(double s) const;  // at unstretched arc length s ∈ [0, L0]
  Vec3 tension(double s) const { return t0_ - s * q_ * u_; }
  // Forces of the supports on the cable: −t(0) at A, t(L0) at B.
  Vec3 reaction_a() const { return -t0_; }
  Vec3 reaction_b() const { return tension(L0_); }

 private:
  Vec3 position_with(const Vec3& t0, double s) const;
  Vec3 p_a_;
  double L0_, EA_, q_;
  Vec3 u_, t0_;
};

}  // namespace catena::test

#pragma once
// Strain measures of the ANCF beam (ancf_beam.hpp) as functions of their local arguments,
// templated on the scalar so one definition serves plain doubles (reference strains,
// energies, output) and dual numbers (exact gradients and Hessians, dual.hpp).
// Private to src/elements.
#include <array>
#include <cmath>

namespace catena::elements::beam_strains {

template <class S>
using V3 = std::array<S, 3>;

template <class S>
S dot(const V3<S>& a, const V3<S>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class S>
V3<S> cross(const V3<S>& a, const V3<S>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class S>
V3<S> scale(const V3<S>& a, const S& s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
template <class S>
V3<S> add(const V3<S>& a, const V3<S>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
template <class S, std::size_t N>
V3<S> block(const std::array<S, N>& x, int first) {
  return {x[first], x[first + 1], x[first + 2]};
}

// Axial strain, argument [u = r_c'] (3): ε = |u| − 1 (Biot, against the mesh length).
template <class S>
std::array<S, 1> axial_strain(const std::array<S, 3>& u) {
  using std::sqrt;
  return {sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) - 1.0};
}

// Bending, arguments [u = r_c', w = r_c'', d_y, d_z] (12). Returns {κ_y, κ_z}:
//   k = u × w / |u|² (per reference length: the rate of turn of the tangent, dθ/ds₀) or
//   k = u × w / |u|³ (per deformed length: the curve's curvature), ⊥ t̂ = u/|u|
//   (core/curvature_measure.hpp),
//   κ_y = k·ê_y, κ_z = k·ê_z, with the section frame ê_y = a⊥/|a⊥|, ê_z = t̂ × ê_y built
//   from a = d_y + d_z × t̂ (both terms ≈ ê_y; symmetric in the two directors), a⊥ its
//   part ⊥ t̂. Since k ⊥ t̂: κ_y = k·a/|a⊥|, κ_z = k·(t̂ × a)/|a⊥|, κ_y² + κ_z² = |k|²,
//   so an isotropic section (EI_y = EI_z) sees the centreline curvature only.
// Bending ABOUT y curves the centreline in the x–z plane: k ∥ d_y, so κ_y pairs with EI_y.
template <class S>
struct BendingFrame {
  V3<S> t, a;    // unit tangent; a = d_y + d_z × t
  S inv_a_perp;  // 1/|a⊥|, a⊥ = a − (a·t) t
};

template <class S>
BendingFrame<S> bending_frame(const V3<S>& u, const V3<S>& d_y, const V3<S>& d_z) {
  using std::sqrt;
  const V3<S> t = scale(u, 1.0 / sqrt(dot(u, u)));
  const V3<S> a = add(d_y, cross(d_z, t));
  const S a_t = dot(a, t);
  return {t, a, 1.0 / sqrt(dot(a, a) - a_t * a_t)};
}

template <class S>
std::array<S, 2> bending_strains(const std::array<S, 12>& x, bool per_deformed_length) {
  using std::sqrt;
  const V3<S> u = block(x, 0), w = block(x, 3), d_y = block(x, 6), d_z = block(x, 9);
  const S uu = dot(u, u);
  const V3<S> k = scale(cross(u, w), per_deformed_length ? 1.0 / (uu * sqrt(uu)) : 1.0 / uu);
  const BendingFrame<S> f = bending_frame(u, d_y, d_z);
  return {dot(k, f.a) * f.inv_a_perp, dot(k, cross(f.t, f.a)) * f.inv_a_perp};
}

// Twist angle of the element, arguments [d_y,A, d_z,A, d_y,B, d_z,B] (12):
//   φ = atan2(S, C),  S = ½ (d_y,B·d_z,A − d_z,B·d_y,A),  C = ½ (d_y,A·d_y,B + d_z,A·d_z,B),
// and κ_x = φ/L, constant along the element. For orthonormal nodal frames related by a
// rotation Θ about n̂: S = sin Θ (n̂·t̂) — which equals L·½(d_y'·d_z − d_z'·d_y) at every x
// of the linearly interpolated directors — and C = cos Θ for a pure twist (n̂ = t̂), so the
// angle is exact for uniform twist of any size, and a pure bending rotation (n̂ ⊥ t̂)
// gives S = 0: no spurious twist.
template <class S>
std::array<S, 1> twist_angle(const std::array<S, 12>& x) {
  using std::atan2;
  const V3<S> d_ya = block(x, 0), d_za = block(x, 3), d_yb = block(x, 6), d_zb = block(x, 9);
  return {
      atan2(0.5 * (dot(d_yb, d_za) - dot(d_zb, d_ya)), 0.5 * (dot(d_ya, d_yb) + dot(d_za, d_zb)))};
}

// Nodal constraints, arguments [u = r_x, d_y, d_z] (9). Returns {γ_y, γ_z, s_1, s_2, s_3}:
//   γ_y = t̂·d_y, γ_z = t̂·d_z (directors ⊥ tangent),
//   s_1 = (|d_y|² − 1)/2, s_2 = (|d_z|² − 1)/2, s_3 = d_y·d_z (rigid cross-section).
template <class S>
std::array<S, 5> node_strains(const std::array<S, 9>& x) {
  using std::sqrt;
  const V3<S> u = block(x, 0), d_y = block(x, 3), d_z = block(x, 6);
  const S inv_norm_u = 1.0 / sqrt(dot(u, u));
  return {dot(u, d_y) * inv_norm_u, dot(u, d_z) * inv_norm_u, 0.5 * (dot(d_y, d_y) - 1.0),
          0.5 * (dot(d_z, d_z) - 1.0), dot(d_y, d_z)};
}

}  // namespace catena::elements::beam_strains

#pragma once
// The Lagrange top (a symmetric heavy top on a fixed point) for the rigid-body tests: its
// data and scene, its state read from the system's vectors, and its invariants (energy,
// angular momentum about the vertical, the frame's orthonormality).
#include <petscvec.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "catena/assembly/second_order_system.hpp"
#include "catena/core/vec3.hpp"

namespace catena::test {

// The top: mass m, centre of mass at l along its axis e3 from the fixed point, moments I1
// (transverse) and I3 (axial) about the centre of mass.
struct Top {
  double m = 1.0, l = 0.1, I1 = 0.003, I3 = 0.005, g = 9.81;
  double theta = 30.0 * M_PI / 180.0;  // nutation: e3 from the vertical
  double spin = 60.0;                  // ω₃, rad/s
  // The precession rate at the start: NaN for the closed form's Ω (steady precession);
  // another value (0: released without precession) makes the top nutate.
  double start_precession = std::numeric_limits<double>::quiet_NaN();

  double transverse_at_pivot() const { return I1 + m * l * l; }
  // The slow root Ω of I₁' cos θ Ω² − I₃ ω₃ Ω + m g l = 0.
  double precession() const {
    const double a = transverse_at_pivot() * std::cos(theta), b = I3 * spin;
    return (b - std::sqrt(b * b - 4.0 * a * m * g * l)) / (2.0 * a);
  }
  Vec3 e1() const { return {std::cos(theta), 0.0, -std::sin(theta)}; }
  Vec3 e3() const { return {std::sin(theta), 0.0, std::cos(theta)}; }
  double initial_precession() const {
    return std::isnan(start_precession) ? precession() : start_precession;
  }
  // ψ̇ = ω₃ − Ω cos θ at the start: the rate of the body's revolutions about its axis.
  double axial_rate() const { return spin - initial_precession() * std::cos(theta); }
  // ω = Ω ẑ + ψ̇ e3.
  Vec3 angular_velocity() const {
    return initial_precession() * Vec3::UnitZ() + axial_rate() * e3();
  }

  std::string scene() const {
    char text[2048];
    const Vec3 a = e1(), w = angular_velocity();
    std::snprintf(text, sizeof text,
                  "name: heavy top\n"
                  "gravity: [0, 0, %.17g]\n"
                  "nodes: [{id: 1, position: [0, 0, 0]}]\n"
                  "bodies:\n"
                  "  - {name: top, node: 1, mass: %.17g, inertia: [%.17g, %.17g, %.17g],\n"
                  "     centre_of_mass: [0, 0, %.17g], axes: [[%.17g, %.17g, %.17g], [0, 1, 0]],\n"
                  "     angular_velocity: [%.17g, %.17g, %.17g]}\n"
                  "supports: [{node: 1, fix: [x, y, z]}]\n"
                  "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n",
                  -g, m, I1, I1, I3, l, a[0], a[1], a[2], w[0], w[1], w[2]);
    return text;
  }
};

// The body's state from the system's vectors (one rank owns the node: gathered).
struct BodyState {
  Vec3 r, e[3], r_dot, e_dot[3];
};
// Collective.
BodyState body_state(const assembly::SecondOrderSystem& system, Vec q, Vec v);

// Energy and vertical angular momentum of the top about its fixed point, from the axes:
// ω = ½ Σ e_k × ė_k, L = R I_pivot Rᵀ ω; the nutation and precession angles of e3; the
// frame's orthonormality error max |RᵀR − I|.
struct Invariants {
  double energy, vertical_momentum, nutation, precession_angle, frame_error;
};
Invariants invariants(const Top& top, const BodyState& s);

// Collective. v ← the top's initial velocity: ė_k = ω × e_k (the fixed point at rest).
void set_top_velocity(const assembly::SecondOrderSystem& system, const Top& top, Vec v);

}  // namespace catena::test

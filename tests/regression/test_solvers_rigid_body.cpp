// Rigid bodies in natural coordinates (elements/rigid_body.hpp,
// couplings/body_frame_constraint.hpp) against closed-form truth:
//  - the Lagrange top (a symmetric heavy top on a fixed point) started in steady precession
//    keeps its nutation angle and precesses at the rate of the closed form
//      m g l = Ω (I₃ ω₃ − I₁' Ω cos θ)       (I₁' = I₁ + m l², ω₃ the spin about the axis),
//    while the energy and the angular momentum about the vertical (both conserved) hold and
//    the axes stay orthonormal to the Newton tolerance;
//  - the physical pendulum (the same body hanging, swinging in a plane) has the small-
//    amplitude period 2π √(I_pivot / (m g l));
//  - a body on a revolute joint to ground released at 60° has the large-amplitude period
//    4 √(I / (m g l)) K(sin 30°) and, at the bottom, the joint force m g + m ω² l with
//    ω² = 2 m g l (1 − cos 60°) / I;
//  - a body on a revolute (prismatic) joint with a spring, a dashpot and an actuator,
//    started at rest, follows the damped oscillator's closed form about the static offset
//    actuator / stiffness;
//  - a body turned at a constant rate by a driven revolute joint against gravity: its angle
//    is the prescribed one and the driving torque (the driver's multiplier) is
//    m g l sin(ω t); its initial velocity comes from the projection onto the constraints.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "catena/assembly/petsc_call.hpp"
#include "catena/model/scene_reader.hpp"
#include "catena/solvers/time/consistent_acceleration.hpp"
#include "dynamics_fixtures.hpp"
#include "lagrange_top.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;
namespace model = catena::model;
using catena::Mat3;
using catena::Vec3;

using catena::test::body_state;
using catena::test::BodyState;
using catena::test::Invariants;
using catena::test::invariants;
using catena::test::Top;

namespace {

// HHT at α = −0.05 or an IRK family, Newton to round-off.
std::unique_ptr<solvers::TimeIntegrator> make(catena::assembly::SecondOrderSystem& system,
                                              const std::string& type) {
  return catena::test::tight_integrator(system, type, -0.05);
}

TEST(RigidBody, LagrangeTopInSteadyPrecessionKeepsItsNutationAndPrecessionRate) {
  catena::test::ensure_petsc();
  const Top top;
  const model::Model m = model::parse_scene(top.scene(), "heavy_top.yaml");
  for (const std::string type : {"hht", "radau_iia", "rattle"}) {
    catena::assembly::SecondOrderSystem system(PETSC_COMM_WORLD, m);
    catena::VecHandle q = system.create_vector(), v = system.create_vector();
    system.reference_state(q.get());
    catena::test::set_top_velocity(system, top, v.get());
    auto integrator = make(system, type);
    integrator->set_state(0.0, q.get(), v.get(), nullptr);
    const Invariants start = invariants(top, body_state(system, integrator->q(), integrator->v()));
    const double dt = 2e-4;
    const int steps = 2500;
    double worst_nutation = 0.0, worst_energy = 0.0, worst_momentum = 0.0, worst_frame = 0.0;
    double unwrapped = start.precession_angle, last = start.precession_angle;
    for (int n = 1; n <= steps; ++n) {
      catena::test::advance_fixed(*integrator, dt, 1);
      const Invariants now = invariants(top, body_state(system, integrator->q(), integrator->v()));
      worst_nutation = std::max(worst_nutation, std::abs(now.nutation - top.theta));
      worst_energy = std::max(worst_energy, std::abs(now.energy - start.energy));
      worst_momentum =
          std::max(worst_momentum, std::abs(now.vertical_momentum - start.vertical_momentum));
      worst_frame = std::max(worst_frame, now.frame_error);
      double step = now.precession_angle - last;
      if (step > M_PI) step -= 2 * M_PI;
      if (step < -M_PI) step += 2 * M_PI;
      unwrapped += step;
      last = now.precession_angle;
    }
    const double rate = (unwrapped - start.precession_angle) / (steps * dt);
    std::printf(
        "%s: nutation error %.3g rad, precession %.8g rad/s (closed form %.8g), energy %.3g "
        "J of %.6g, L_z %.3g of %.6g, frame %.3g\n",
        type.c_str(), worst_nutation, rate, top.precession(), worst_energy, start.energy,
        worst_momentum, start.vertical_momentum, worst_frame);
    // HHT (second order, α = −0.05), Radau IIA (order 5 here) and RATTLE (second order,
    // symplectic: energy bounded, L_z a quadratic invariant it keeps to round-off): the
    // tolerances are about ten times what each showed at this step.
    const bool radau = type == "radau_iia", rattle = type == "rattle";
    EXPECT_LT(worst_nutation, radau ? 2e-10 : rattle ? 4e-5 : 1e-4) << type;
    EXPECT_NEAR(rate, top.precession(),
                (radau    ? 1e-7
                 : rattle ? 1e-4
                          : 1e-3) *
                    top.precession())
        << type;
    EXPECT_LT(worst_energy, (radau ? 2e-9 : rattle ? 1e-10 : 1e-5) * start.energy) << type;
    EXPECT_LT(worst_momentum, (radau || rattle ? 1e-9 : 1e-5) * start.vertical_momentum) << type;
    EXPECT_LT(worst_frame, 1e-12) << type;  // the frame constraints, to Newton's tolerance
  }
}

// The same body hanging from its fixed point (e3 down) and swinging in the x–z plane with
// a small amplitude: period 2π √(I₁' / (m g l)).
TEST(RigidBody, PhysicalPendulumHasTheClosedFormPeriod) {
  catena::test::ensure_petsc();
  Top top;
  const double amplitude = 1e-3;  // rad: the finite-amplitude correction θ₀²/16 ≈ 6e-8
  const double omega0 = std::sqrt(top.m * top.g * top.l / top.transverse_at_pivot());
  char text[1024];
  std::snprintf(text, sizeof text,
                "name: physical pendulum\n"
                "gravity: [0, 0, %.17g]\n"
                "nodes: [{id: 1, position: [0, 0, 0]}]\n"
                "bodies:\n"
                "  - {name: bob, node: 1, mass: %.17g, inertia: [%.17g, %.17g, %.17g],\n"
                "     centre_of_mass: [0, 0, %.17g], axes: [[1, 0, 0], [0, -1, 0]],\n"
                "     angular_velocity: [0, %.17g, 0]}\n"
                "supports: [{node: 1, fix: [x, y, z]}]\n"
                "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n",
                -top.g, top.m, top.I1, top.I1, top.I3, top.l, amplitude * omega0);
  const model::Model m = model::parse_scene(text, "physical_pendulum.yaml");
  catena::assembly::SecondOrderSystem system(PETSC_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  {
    // ė_k = ω × e_k, ω along y.
    const auto& dofs = system.dof_map();
    const Vec3 w(0.0, amplitude * omega0, 0.0);
    const Vec3 axes[3] = {Vec3::UnitX(), -Vec3::UnitY(), -Vec3::UnitZ()};
    PetscInt lo = 0, hi = 0;
    CATENA_PETSC(VecGetOwnershipRange(v.get(), &lo, &hi));
    for (int a = 0; a < 3; ++a) {
      const Vec3 rate = w.cross(axes[a]);
      for (int d = 0; d < 3; ++d)
        if (const PetscInt g = dofs.global_dof(0, 3 + 3 * a + d); g >= lo && g < hi)
          CATENA_PETSC(VecSetValue(v.get(), g, rate[d], INSERT_VALUES));
    }
    CATENA_PETSC(VecAssemblyBegin(v.get()));
    CATENA_PETSC(VecAssemblyEnd(v.get()));
  }
  auto integrator = make(system, "radau_iia");
  integrator->set_state(0.0, q.get(), v.get(), nullptr);
  // Upward zero crossings of e3_x (the swing angle's sign) by linear interpolation.
  const double dt = 1e-3, period = 2.0 * M_PI / omega0;
  std::vector<double> crossings;
  double previous = body_state(system, integrator->q(), integrator->v()).e[2][0];
  for (int n = 1; n * dt < 2.6 * period; ++n) {
    catena::test::advance_fixed(*integrator, dt, 1);
    const double now = body_state(system, integrator->q(), integrator->v()).e[2][0];
    if (previous < 0.0 && now >= 0.0)
      crossings.push_back((n - 1 + previous / (previous - now)) * dt);
    previous = now;
  }
  ASSERT_GE(crossings.size(), 2u);
  const double measured = crossings[1] - crossings[0];
  std::printf("physical pendulum: period %.9f s, closed form %.9f s\n", measured, period);
  // Linear interpolation of a sine between samples 1e-3 s apart: error O((ω dt)²/ 8) of
  // the crossing time's fraction, far below 1e-6 of the period after differencing.
  EXPECT_NEAR(measured, period, 1e-6 * period);
}

// K(k), the complete elliptic integral of the first kind, by the arithmetic–geometric mean.
double elliptic_k(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 30; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return M_PI / (2.0 * a);
}

TEST(RigidBody, RevolutePendulumHasTheEllipticPeriodAndJointForce) {
  catena::test::ensure_petsc();
  const double m = 2.0, l = 0.5, g = 9.81, theta0 = M_PI / 3.0;
  const double inertia_y = 0.03 + m * l * l;  // about the joint's axis (y)
  // The body's point r is its centre of mass, l from the pivot at the origin, swung by θ₀
  // about y: its axes are the global ones turned by θ₀ about y.
  const Vec3 r(l * std::sin(theta0), 0.0, -l * std::cos(theta0));
  const Vec3 e1(std::cos(theta0), 0.0, -std::sin(theta0));
  char text[1024];
  std::snprintf(text, sizeof text,
                "name: revolute pendulum\n"
                "gravity: [0, 0, %.17g]\n"
                "nodes: [{id: 1, position: [%.17g, 0, %.17g]}]\n"
                "bodies:\n"
                "  - {name: arm, node: 1, mass: %.17g, inertia: [0.02, 0.03, 0.04],\n"
                "     axes: [[%.17g, 0, %.17g], [0, 1, 0]]}\n"
                "joints:\n"
                "  - {type: revolute, between: [arm, ground], point: [0, 0, 0], axis: [0, 1, 0]}\n"
                "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n",
                -g, r[0], r[2], m, e1[0], e1[2]);
  const model::Model pendulum = model::parse_scene(text, "revolute_pendulum.yaml");
  catena::assembly::SecondOrderSystem system(PETSC_COMM_WORLD, pendulum);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  auto integrator = make(system, "radau_iia");
  integrator->set_state(0.0, q.get(), v.get(), nullptr);
  const double period = 4.0 * std::sqrt(inertia_y / (m * g * l)) * elliptic_k(std::sin(theta0 / 2));
  const double omega_bottom = std::sqrt(2.0 * m * g * l * (1.0 - std::cos(theta0)) / inertia_y);
  const double force_bottom = m * g + m * omega_bottom * omega_bottom * l;
  // The swing angle from the point's position; the joint's force on the body is −λ (its
  // first three multipliers, the last constraint's).
  const auto& dofs = system.dof_map();
  const int joint = dofs.n_constraints() - 1;
  auto angle_and_force = [&] {
    const BodyState s = body_state(system, integrator->q(), integrator->v());
    const double lambda_z = catena::test::global_value(PETSC_COMM_WORLD, integrator->q(),
                                                       dofs.multiplier_dof(joint, 2));
    return std::pair{std::atan2(s.r[0], -s.r[2]), -lambda_z};
  };
  const double dt = 1e-3;
  std::vector<double> crossings, forces;
  auto [previous, previous_force] = angle_and_force();
  for (int n = 1; n * dt < 1.3 * period && crossings.size() < 2; ++n) {
    catena::test::advance_fixed(*integrator, dt, 1);
    const auto [now, force] = angle_and_force();
    if ((previous > 0.0) != (now > 0.0)) {
      const double w = previous / (previous - now);
      crossings.push_back((n - 1 + w) * dt);
      forces.push_back(previous_force + w * (force - previous_force));
    }
    previous = now;
    previous_force = force;
  }
  ASSERT_EQ(crossings.size(), 2u);
  std::printf(
      "revolute pendulum: half period %.9f s (closed form %.9f), force at the bottom "
      "%.6f N and %.6f N (closed form %.6f)\n",
      crossings[1] - crossings[0], period / 2, forces[0], forces[1], force_bottom);
  EXPECT_NEAR(crossings[1] - crossings[0], period / 2, 1e-6 * period);
  for (const double f : forces) EXPECT_NEAR(f, force_bottom, 1e-4 * force_bottom);
}

// A body on a joint to ground (no gravity) with a spring k, a dashpot c and an actuator F on
// its coordinate, started at rest: ξ(t) = ξ_s + e^{−σt}(A cos ω_d t + B sin ω_d t), ξ_s = F/k,
// σ = c/(2 m_ξ), ω_d = √(k/m_ξ − σ²), A = −ξ_s, B = σ A / ω_d, m_ξ the inertia on ξ.
class SpringJoint : public testing::TestWithParam<std::string> {};

TEST_P(SpringJoint, FollowsTheDampedOscillatorAboutTheActuatorsOffset) {
  catena::test::ensure_petsc();
  const bool revolute = GetParam() == "revolute";
  const double k = revolute ? 3.0 : 400.0, c = revolute ? 0.02 : 1.0, F = revolute ? 0.3 : 8.0;
  const double inertia = revolute ? 0.05 : 2.0;  // I_zz about the centre (= the joint) or m
  char text[1024];
  std::snprintf(text, sizeof text,
                "name: spring joint\n"
                "gravity: [0, 0, 0]\n"
                "nodes: [{id: 1, position: [0, 0, 0]}]\n"
                "bodies: [{name: b, node: 1, mass: 2, inertia: [0.03, 0.04, 0.05]}]\n"
                "joints:\n"
                "  - {type: %s, between: [b, ground], point: [0, 0, 0], axis: [0, 0, 1],\n"
                "     stiffness: %.17g, damping: %.17g, actuator: %.17g}\n"
                "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n",
                GetParam().c_str(), k, c, F);
  const model::Model m = model::parse_scene(text, "spring_joint.yaml");
  catena::assembly::SecondOrderSystem system(PETSC_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  auto integrator = make(system, "radau_iia");
  integrator->set_state(0.0, q.get(), v.get(), nullptr);
  const double sigma = c / (2 * inertia), wd = std::sqrt(k / inertia - sigma * sigma);
  const double offset = F / k, A = -offset, B = sigma * A / wd;
  const double dt = 1e-3;
  double worst = 0.0;
  for (int n = 1; n <= 1500; ++n) {
    catena::test::advance_fixed(*integrator, dt, 1);
    const BodyState s = body_state(system, integrator->q(), integrator->v());
    const double xi = revolute ? std::atan2(s.e[0][1], s.e[0][0]) : s.r[2];
    const double t = n * dt;
    const double exact =
        offset + std::exp(-sigma * t) * (A * std::cos(wd * t) + B * std::sin(wd * t));
    worst = std::max(worst, std::abs(xi - exact));
  }
  std::printf("%s spring joint: largest error %.3g against an offset of %.6g\n", GetParam().c_str(),
              worst, offset);
  EXPECT_LT(worst, 1e-7 * offset);
}

INSTANTIATE_TEST_SUITE_P(RevoluteAndPrismatic, SpringJoint,
                         testing::Values("revolute", "prismatic"));

TEST(RigidBody, DrivenRevoluteNeedsTheGravityTorque) {
  catena::test::ensure_petsc();
  const double m = 2.0, l = 0.5, g = 9.81, omega = 3.0;
  char text[1024];
  std::snprintf(text, sizeof text,
                "name: driven arm\n"
                "gravity: [0, 0, %.17g]\n"
                "nodes: [{id: 1, position: [0, 0, %.17g]}]\n"
                "bodies: [{name: arm, node: 1, mass: %.17g, inertia: [0.02, 0.03, 0.04]}]\n"
                "joints:\n"
                "  - {type: revolute, between: [arm, ground], point: [0, 0, 0], axis: [0, 1, 0],\n"
                "     motion: {velocity: %.17g}}\n"
                "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n",
                -g, -l, m, omega);
  const model::Model arm = model::parse_scene(text, "driven_arm.yaml");
  catena::assembly::SecondOrderSystem system(PETSC_COMM_WORLD, arm);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  // At rest in the scene; the projection gives the driver's rate: ω about y through the
  // pivot (the centre of mass at l ω along x).
  EXPECT_GT(solvers::project_initial_velocity(system, 0.0, q.get(), v.get()), 1.0);
  const BodyState start = body_state(system, q.get(), v.get());
  EXPECT_NEAR(start.r_dot[0], -omega * l, 1e-12);  // ω ŷ × (0, 0, −l) = (−ω l, 0, 0)
  auto integrator = make(system, "radau_iia");
  integrator->set_state(0.0, q.get(), v.get(), nullptr);
  const auto& dofs = system.dof_map();
  const int joint = dofs.n_constraints() - 1, driver = dofs.n_multipliers(joint) - 1;
  double worst_angle = 0.0, worst_torque = 0.0;
  const double dt = 1e-3;
  for (int n = 1; n <= 1000; ++n) {
    catena::test::advance_fixed(*integrator, dt, 1);
    const double t = n * dt;
    const BodyState s = body_state(system, integrator->q(), integrator->v());
    // The angle about y from the hanging position: the centre at l (−sin φ, 0, −cos φ).
    const double angle = std::atan2(-s.r[0], -s.r[2]);
    worst_angle = std::max(worst_angle, std::abs(std::remainder(angle - omega * t, 2 * M_PI)));
    const double lambda = catena::test::global_value(PETSC_COMM_WORLD, integrator->q(),
                                                     dofs.multiplier_dof(joint, driver));
    // The constraint's torque on the arm is −λ: it balances gravity's −m g l sin φ.
    worst_torque = std::max(worst_torque, std::abs(-lambda - m * g * l * std::sin(omega * t)));
  }
  std::printf("driven arm: angle within %.3g rad, torque within %.3g N m of m g l = %.6g N m\n",
              worst_angle, worst_torque, m * g * l);
  EXPECT_LT(worst_angle, 1e-10);
  EXPECT_LT(worst_torque, 1e-4 * m * g * l);
}

}  // namespace

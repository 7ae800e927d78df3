// Sliders (couplings/slider_constraint.hpp) against closed-form truth:
//  - a trolley (a point mass on a slider node) released on a rigid rail inclined at θ runs
//    down it with s(t) = s₀ + ½ g sin θ t², crossing the rail's element boundaries, and its
//    energy ½ m ṡ² − m g sin θ (s − s₀) stays zero; the rail (every node fixed) pushes on
//    it across itself only: the multipliers' tangential part is zero and their normal part
//    is m g cos θ;
//  - with viscous friction c along the rail it reaches the terminal speed m g sin θ / c as
//    ṡ(t) = v∞ (1 − e^(−c t / m));
//  - on a flexible taut wire (pinned at its ends) a trolley started at rest at mid-span
//    stays there by symmetry while the wire sags under it, and a trolley given a speed
//    along a level wire keeps its momentum to the wire's small slope: the point stays on
//    the wire's curve to the Newton tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/model/scene_reader.hpp"
#include "dynamics_fixtures.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;
namespace model = catena::model;

namespace {

constexpr double kG = 9.81;

// A rail of `elements` cable elements from node 1 at the origin to node 2, `length` m down
// at `angle` from the horizontal, every node fixed; a trolley of `mass` kg on slider node 3
// at `start` m along it, with viscous friction `damping`.
std::string rail_scene(double angle, double length, int elements, double mass, double start,
                       double damping) {
  const double c = std::cos(angle), s = std::sin(angle);
  char text[4096];
  std::string supports;
  // Interior line nodes get ids 4, 5, ... (docs/scene.md, "Generated ids").
  for (int id : {1, 2})
    supports += "  - {node: " + std::to_string(id) + ", fix: [x, y, z, rx_x, rx_y, rx_z]}\n";
  for (int k = 0; k < elements - 1; ++k)
    supports += "  - {node: " + std::to_string(4 + k) + ", fix: [x, y, z, rx_x, rx_y, rx_z]}\n";
  std::snprintf(text, sizeof text,
                "name: trolley on a rail\n"
                "gravity: [0, 0, %.17g]\n"
                "sections:\n"
                "  rail: {type: cable, EA: 1.0e9, EI: 1.0e6, mass_per_length: 10,\n"
                "         damping_time: 0}\n"
                "nodes:\n"
                "  - {id: 1, position: [0, 0, 0]}\n"
                "  - {id: 2, position: [%.17g, 0, %.17g]}\n"
                "  - {id: 3, position: [%.17g, 0, %.17g]}\n"
                "lines: [{name: rail, from: 1, to: 2, elements: %d, section: rail}]\n"
                "sliders: [{name: trolley, node: 3, line: rail, damping: %.17g}]\n"
                "masses: [{node: 3, mass: %.17g}]\n"
                "supports:\n%s"
                "analysis: {type: dynamic, duration: 1, initial: {from: reference}}\n",
                -kG, length * c, -length * s, start * c, -start * s, elements, damping, mass,
                supports.c_str());
  return text;
}

// A run of a model from its reference state at rest: HHT (α = −0.1) or an IRK family.
struct RestStart {
  catena::assembly::SecondOrderSystem system;
  std::unique_ptr<solvers::TimeIntegrator> integrator;
  RestStart(const model::Model& m, const std::string& type) : system(PETSC_COMM_WORLD, m) {
    catena::VecHandle q = system.create_vector(), v = system.create_vector();
    system.reference_state(q.get());
    CATENA_PETSC(VecSet(v.get(), 0.0));
    integrator = catena::test::tight_integrator(system, type, -0.1);
    integrator->set_state(0.0, q.get(), v.get(), nullptr);
  }
};

// The value of node `node`'s component k (gathered: one rank owns it).
double node_value(const catena::assembly::SecondOrderSystem& system, Vec x, int node, int k) {
  return catena::test::global_value(system.comm(), x, system.dof_map().global_dof(node, k));
}

double multiplier(const catena::assembly::SecondOrderSystem& system, Vec x, int constraint, int k) {
  return catena::test::global_value(system.comm(), x,
                                    system.dof_map().multiplier_dof(constraint, k));
}

class RigidRail : public ::testing::TestWithParam<std::string> {};

TEST_P(RigidRail, FrictionlessTrolleyFallsAlongItAsTheClosedForm) {
  catena::test::ensure_petsc();
  const double angle = 30.0 * M_PI / 180.0, mass = 5.0, start = 1.0, length = 10.0;
  const model::Model m =
      model::parse_scene(rail_scene(angle, length, 10, mass, start, 0.0), "rail.yaml");
  ASSERT_EQ(m.sliders.size(), 1u);
  EXPECT_NEAR(m.sliders[0].start, start, 1e-12);
  RestStart run(m, GetParam());
  const catena::assembly::SecondOrderSystem& system = run.system;
  solvers::TimeIntegrator* integrator = run.integrator.get();
  const int node = m.sliders[0].node, constraint = m.sliders[0].constraint;
  const double dt = 0.01, a = kG * std::sin(angle);
  double worst_s = 0.0, worst_energy = 0.0, worst_tangential = 0.0, worst_normal = 0.0;
  const catena::Vec3 tangent(std::cos(angle), 0.0, -std::sin(angle));
  const catena::Vec3 normal(std::sin(angle), 0.0, std::cos(angle));
  for (int n = 1; n <= 100; ++n) {  // 1 s: 2.45 m, across three element boundaries
    catena::test::advance_fixed(*integrator, dt, 1);
    const double t = n * dt;
    const double s = node_value(system, integrator->q(), node, 3);
    const double rate = node_value(system, integrator->v(), node, 3);
    worst_s = std::max(worst_s, std::abs(s - (start + 0.5 * a * t * t)));
    const double energy = 0.5 * mass * rate * rate - mass * a * (s - start);
    worst_energy = std::max(worst_energy, std::abs(energy));
    catena::Vec3 lambda;
    for (int k = 0; k < 3; ++k) lambda[k] = multiplier(system, integrator->q(), constraint, k);
    // The force on the node is −λ: across the rail, m g cos θ (holding it up).
    worst_tangential = std::max(worst_tangential, std::abs(lambda.dot(tangent)));
    worst_normal =
        std::max(worst_normal, std::abs(-lambda.dot(normal) - mass * kG * std::cos(angle)));
  }
  const double s_end = node_value(system, integrator->q(), node, 3);
  std::printf(
      "%s: s(1 s) = %.12g m (closed form %.12g), |s error| %.3g m, energy %.3g J, "
      "tangential force %.3g N, normal force error %.3g N\n",
      GetParam().c_str(), s_end, start + 0.5 * a, worst_s, worst_energy, worst_tangential,
      worst_normal);
  // Constant acceleration: both methods integrate it exactly (to the Newton tolerance).
  EXPECT_LT(worst_s, 1e-9);
  EXPECT_LT(worst_energy, 1e-7);
  EXPECT_LT(worst_tangential, 1e-7);
  EXPECT_LT(worst_normal, 1e-6);
}

TEST_P(RigidRail, ViscousFrictionGivesTheTerminalSpeedClosedForm) {
  catena::test::ensure_petsc();
  const double angle = 20.0 * M_PI / 180.0, mass = 2.0, damping = 4.0, start = 0.5;
  const model::Model m =
      model::parse_scene(rail_scene(angle, 10.0, 8, mass, start, damping), "rail.yaml");
  RestStart run(m, GetParam());
  const catena::assembly::SecondOrderSystem& system = run.system;
  solvers::TimeIntegrator* integrator = run.integrator.get();
  const int node = m.sliders[0].node;
  const double terminal = mass * kG * std::sin(angle) / damping, tau = mass / damping;
  const double dt = 0.005;
  double worst_rate = 0.0, worst_s = 0.0;
  for (int n = 1; n <= 400; ++n) {  // 2 s: four time constants
    catena::test::advance_fixed(*integrator, dt, 1);
    const double t = n * dt;
    const double rate = node_value(system, integrator->v(), node, 3);
    const double s = node_value(system, integrator->q(), node, 3);
    worst_rate = std::max(worst_rate, std::abs(rate - terminal * (1.0 - std::exp(-t / tau))));
    worst_s =
        std::max(worst_s, std::abs(s - start - terminal * (t - tau * (1.0 - std::exp(-t / tau)))));
  }
  std::printf("%s: terminal speed %.6g m/s, worst speed error %.3g m/s, position %.3g m\n",
              GetParam().c_str(), terminal, worst_rate, worst_s);
  // HHT is second order (error ~ (dt/τ)² of the speed), Radau IIA fifth.
  const bool radau = GetParam() == "radau_iia";
  EXPECT_LT(worst_rate, (radau ? 1e-9 : 1e-4) * terminal);
  EXPECT_LT(worst_s, radau ? 1e-9 : 1e-4);
}

// A gantry crane: a cart of mass M on a level rigid rail (a slider) carrying a rigid
// pendulum (mass m, centre of mass l below the pivot, inertia I_c about it) on a spherical
// joint at the cart. Released at rest at a small angle θ₀, the pendulum swings at
//   ω² = m g l (M + m) / ((M + m)(I_c + m l²) − m² l²)
// (the Lagrangian of cart and pendulum linearised; the total momentum along the rail stays
// zero, so the cart swings against it).
TEST_P(RigidRail, GantryCranePendulumSwingsAtTheCoupledFrequency) {
  catena::test::ensure_petsc();
  const double M = 10.0, m = 2.0, l = 1.0, I = 0.02, theta0 = 0.01;
  std::string supports;
  for (int id : {1, 2})
    supports += "  - {node: " + std::to_string(id) + ", fix: [x, y, z, rx_x, rx_y, rx_z]}\n";
  for (int k = 0; k < 9; ++k)
    supports += "  - {node: " + std::to_string(5 + k) + ", fix: [x, y, z, rx_x, rx_y, rx_z]}\n";
  char text[4096];
  std::snprintf(text, sizeof text,
                "name: gantry crane\n"
                "gravity: [0, 0, %.17g]\n"
                "sections: {rail: {type: cable, EA: 1.0e9, EI: 1.0e6, mass_per_length: 10}}\n"
                "nodes:\n"
                "  - {id: 1, position: [-5, 0, 0]}\n"
                "  - {id: 2, position: [5, 0, 0]}\n"
                "  - {id: 3, position: [0.05, 0, 0]}\n"
                "  - {id: 4, position: [0.05, 0, 0]}\n"
                "lines: [{name: rail, from: 1, to: 2, elements: 10, section: rail}]\n"
                "sliders: [{name: cart, node: 3, line: rail}]\n"
                "masses: [{node: 3, mass: %.17g}]\n"
                "bodies:\n"
                "  - {name: load, node: 4, mass: %.17g, inertia: [%.17g, %.17g, %.17g],\n"
                "     centre_of_mass: [0, 0, %.17g],\n"
                "     axes: [[%.17g, 0, %.17g], [0, 1, 0]]}\n"
                "joints: [{type: spherical, between: [load, 3]}]\n"
                "supports:\n%s"
                "analysis: {type: dynamic, duration: 8, initial: {from: reference}}\n",
                -kG, M, m, I, I, I, -l, std::cos(theta0), -std::sin(theta0), supports.c_str());
  const model::Model model_ = model::parse_scene(text, "gantry.yaml");
  RestStart run(model_, GetParam());
  const catena::assembly::SecondOrderSystem& system = run.system;
  solvers::TimeIntegrator* integrator = run.integrator.get();
  const int body = model_.rigid_bodies[0].node, cart = model_.sliders[0].node;
  // θ from the body's e3 (its axis from the pivot away from the centre of mass).
  auto angle = [&] {
    return std::atan2(node_value(system, integrator->q(), body, 9),
                      node_value(system, integrator->q(), body, 11));
  };
  const double omega =
      std::sqrt(m * kG * l * (M + m) / ((M + m) * (I + m * l * l) - m * m * l * l));
  const double dt = 2e-3;
  double previous = angle(), first_crossing = -1.0, last_crossing = -1.0, momentum = 0.0;
  int crossings = 0;
  for (int n = 1; n <= 4000; ++n) {
    catena::test::advance_fixed(*integrator, dt, 1);
    const double now = angle();
    if (previous > 0.0 && now <= 0.0) {  // θ falls through zero once per period
      const double t = (n - 1) * dt + dt * previous / (previous - now);
      if (first_crossing < 0.0) first_crossing = t;
      last_crossing = t;
      ++crossings;
    }
    previous = now;
    // The momentum along the rail: the cart's and the load's (its centre of mass).
    const double cart_rate = node_value(system, integrator->v(), cart, 0);
    const double com_rate = node_value(system, integrator->v(), body, 0) -
                            l * node_value(system, integrator->v(), body, 9);
    momentum = std::max(momentum, std::abs(M * cart_rate + m * com_rate));
  }
  ASSERT_GE(crossings, 3);
  const double period = (last_crossing - first_crossing) / (crossings - 1);
  std::printf("%s: period %.8g s (closed form %.8g), momentum along the rail %.3g kg*m/s\n",
              GetParam().c_str(), period, 2 * M_PI / omega, momentum);
  // Small-amplitude closed form: θ₀ = 0.01 shifts the period by about θ₀²/16 ≈ 6e-6.
  EXPECT_NEAR(period, 2 * M_PI / omega, 1e-4 * 2 * M_PI / omega);
  EXPECT_LT(momentum, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(HhtAndRadau, RigidRail, ::testing::Values("hht", "radau_iia"));

}  // namespace

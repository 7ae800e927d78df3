// Static equilibrium with rigid bodies (solvers/statics/static_solver.cpp: Newton with a
// mass-matrix term that falls with the residual, because a body's rotations have no
// stiffness until its frame multipliers carry load) against closed-form truth:
//  - an arm on a revolute joint to ground with a torsion spring, horizontal in the scene:
//    under gravity it turns down to k φ = m g l cos φ, and the joint carries its weight;
//  - the same arm without the spring, released horizontal, hangs straight down (a quarter
//    turn from the scene's configuration, reached through load steps);
//  - a short pendulum (its centre 5 cm below the hinge, a small inertia), hanging or released
//    horizontal, rests hanging with the hinge carrying its weight: its first tangent, unloaded,
//    has no rotational stiffness at all, and a MUMPS scaling kept from that matrix once
//    made the loaded one look singular;
//  - a wheel on a vertical axle (its centre on the axis) has no equilibrium stiffness about
//    the axle: the solve stops naming a mechanism instead of returning an arbitrary angle.
// Bodies with the catenary: app test run_pantograph_wire_arm (the arm_en50318 pantograph's
// static start on a tensioned wire).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/core/error.hpp"
#include "catena/model/scene_reader.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "dynamics_fixtures.hpp"
#include "petsc_test_session.hpp"

namespace solvers = catena::solvers;
namespace model = catena::model;
using catena::Vec3;

namespace {

// The arm: mass m, its point r its centre of mass, l along x from a revolute joint at the
// origin about y, optionally with a torsion spring k (slack where the scene draws it).
// `hanging`: the centre of mass l below the hinge instead. `inertia`: the principal
// moments, kg m².
std::string arm_scene(double m, double l, double k, bool hanging = false,
                      const char* inertia = "[0.02, 0.03, 0.04]") {
  char text[1024];
  std::snprintf(text, sizeof text,
                "name: arm on a hinge\n"
                "gravity: [0, 0, -9.81]\n"
                "nodes: [{id: 1, position: [%.17g, 0, %.17g]}]\n"
                "bodies: [{name: arm, node: 1, mass: %.17g, inertia: %s}]\n"
                "joints:\n"
                "  - {type: revolute, between: [arm, ground], point: [0, 0, 0], axis: [0, 1, 0],\n"
                "     stiffness: %.17g}\n"
                "analysis: {type: static}\n",
                hanging ? 0.0 : l, hanging ? -l : 0.0, m, inertia, k);
  return text;
}

struct Solved {
  Vec3 r, e1;
  Vec3 joint_force;  // on the body, from the last constraint's first three multipliers
};

// Solves the scene's statics (throws what the solver throws) and reads body 0's point and
// axis e1 and the last constraint's force.
Solved solve(const std::string& text, const char* file) {
  const model::Model m = model::parse_scene(text, file);
  catena::assembly::SecondOrderSystem system(PETSC_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector();
  system.reference_state(q.get());
  solvers::StaticSolver solver(system, m.static_options);
  const solvers::StaticReport report = solver.solve(q.get());
  std::printf("%s: %d load steps (%d rejected), %d Newton iterations\n", file, report.n_load_steps,
              report.n_rejected_steps, report.n_newton_iterations);
  const auto& dofs = system.dof_map();
  const int node = m.rigid_bodies.front().node;
  auto value = [&](PetscInt g, double fixed) {
    return g >= 0 ? catena::test::global_value(PETSC_COMM_WORLD, q.get(), g) : fixed;
  };
  Solved s;
  for (int d = 0; d < 3; ++d) {
    s.r[d] = value(dofs.global_dof(node, d), m.nodes[static_cast<size_t>(node)].position[d]);
    s.e1[d] = value(dofs.global_dof(node, 3 + d), 0.0);
    s.joint_force[d] = -value(dofs.multiplier_dof(dofs.n_constraints() - 1, d), 0.0);
  }
  return s;
}

TEST(BodyStatics, SpringArmTurnsDownToTheClosedFormAngle) {
  catena::test::ensure_petsc();
  const double m = 2.0, l = 0.5, g = 9.81, k = 20.0;
  // k φ = m g l cos φ by Newton on the scalar equation.
  double phi = 0.5;
  for (int i = 0; i < 50; ++i)
    phi -= (k * phi - m * g * l * std::cos(phi)) / (k + m * g * l * std::sin(phi));
  const Solved s = solve(arm_scene(m, l, k), "spring_arm.yaml");
  std::printf("spring arm: e1 = (%.12f, %.12f, %.12f), closed form (%.12f, 0, %.12f)\n", s.e1[0],
              s.e1[1], s.e1[2], std::cos(phi), -std::sin(phi));
  EXPECT_NEAR(s.e1[0], std::cos(phi), 1e-11);
  EXPECT_NEAR(s.e1[1], 0.0, 1e-12);
  EXPECT_NEAR(s.e1[2], -std::sin(phi), 1e-11);
  EXPECT_NEAR((s.r - l * s.e1).norm(), 0.0, 1e-9);  // r stays l from the hinge along e1
  EXPECT_NEAR(s.joint_force[0], 0.0, 1e-8);
  EXPECT_NEAR(s.joint_force[2], m * g, 1e-8);  // the hinge carries the weight
}

TEST(BodyStatics, ArmWithoutSpringReleasedHorizontalHangsDown) {
  catena::test::ensure_petsc();
  const double m = 2.0, l = 0.5, g = 9.81;
  const Solved s = solve(arm_scene(m, l, 0.0), "hanging_arm.yaml");
  EXPECT_NEAR(s.e1[0], 0.0, 1e-9);
  EXPECT_NEAR(s.e1[2], -1.0, 1e-9);
  EXPECT_NEAR(s.r[0], 0.0, 1e-9);
  EXPECT_NEAR(s.r[2], -l, 1e-9);
  EXPECT_NEAR(s.joint_force[2], m * g, 1e-8);
}

TEST(BodyStatics, ShortPendulumRestsHanging) {
  catena::test::ensure_petsc();
  const double m = 1.0, l = 0.05, g = 9.81;
  for (const bool hanging : {true, false}) {
    SCOPED_TRACE(hanging ? "scene hanging" : "released horizontal");
    const Solved s = solve(arm_scene(m, l, 0.0, hanging, "[0.002, 0.002, 0.002]"),
                           hanging ? "short_pendulum.yaml" : "short_arm.yaml");
    EXPECT_NEAR(s.r[0], 0.0, 1e-10);
    EXPECT_NEAR(s.r[2], -l, 1e-10);
    EXPECT_NEAR(s.joint_force[0], 0.0, 1e-8);
    EXPECT_NEAR(s.joint_force[2], m * g, 1e-8);
  }
}

TEST(BodyStatics, WheelFreeAboutItsAxleIsAMechanism) {
  catena::test::ensure_petsc();
  const std::string text =
      "name: wheel\n"
      "gravity: [0, 0, -9.81]\n"
      "nodes: [{id: 1, position: [0, 0, 0]}]\n"
      "bodies: [{name: wheel, node: 1, mass: 3, inertia: [0.02, 0.02, 0.035]}]\n"
      "joints:\n"
      "  - {type: revolute, between: [wheel, ground], point: [0, 0, 0], axis: [0, 0, 1]}\n"
      "analysis: {type: static}\n";
  try {
    solve(text, "wheel.yaml");
    ADD_FAILURE() << "a wheel free about its axle has no unique equilibrium";
  } catch (const catena::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("mechanism"), std::string::npos) << e.what();
  }
}

}  // namespace

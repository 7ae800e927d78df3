// Numerical failures are reported, not crashed into: a mechanism (singular stiffness)
// and an impossible load path give NumericalError with a message naming the cause.
#include <gtest/gtest.h>

#include "catena/core/error.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"
#include "static_solution.hpp"

using catena::Vec3;
namespace model = catena::model;

TEST(StaticFailures, UnresistedLoadIsReportedAsMechanism) {
  // A mass on an elastic support acting along x only, loaded along y: no stiffness
  // resists the load, no equilibrium exists. (A bar pinned at one end and pushed sideways
  // is not such a case: it swings into line with the load, a stable equilibrium.)
  catena::test::ensure_petsc();
  model::Model m;
  m.gravity = Vec3::Zero();
  m.nodes.emplace_back();
  m.nodes.back().id = 1;
  m.elastic_supports.push_back({0, Vec3(1e4, 0, 0), Vec3::Zero()});
  m.point_masses.push_back({0, 1.0});
  m.nodal_loads.push_back({0, Vec3(0, 100, 0)});
  try {
    catena::test::solve_static(MPI_COMM_WORLD, m);
    FAIL() << "expected a NumericalError";
  } catch (const catena::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mechanism"), std::string::npos) << e.what();
  }
}

TEST(StaticFailures, UnloadedMechanismIsReported) {
  // No loads at all: the reference state is the equilibrium, but its tangent is singular.
  catena::test::ensure_petsc();
  model::Model m;
  m.gravity = Vec3::Zero();
  model::BarProps bar;
  bar.EA = 1e6;
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {1, 0, 0}, 1, bar);
  catena::test::pin(m, nodes.front());
  m.point_masses.push_back({nodes.back(), 1.0});
  try {
    catena::test::solve_static(MPI_COMM_WORLD, m);
    FAIL() << "expected a NumericalError";
  } catch (const catena::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("mechanism"), std::string::npos) << e.what();
  }
}

TEST(StaticStability, HangingPendulumIsStable) {
  // A bar hanging from a pin with a mass: singular before the load is on, stiffened by
  // its tension once loaded. Must succeed with the bar force m·g.
  catena::test::ensure_petsc();
  model::Model m;
  m.gravity = Vec3(0, 0, -9.81);
  model::BarProps bar;
  bar.EA = 1e6;
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {0, 0, -1}, 1, bar);
  catena::test::pin(m, nodes.front());
  m.point_masses.push_back({nodes.back(), 10.0});
  const auto sol = catena::test::solve_static(MPI_COMM_WORLD, m);
  EXPECT_NEAR(sol.axial_force[0], 98.1, 1e-6);
}

TEST(StaticStability, ColumnBeyondBucklingIsNotAccepted) {
  // A clamped beam column under 3× its Euler load π²EI/(4L²): the straight state is an
  // equilibrium but unstable (negative pivots in the tangent at it); it must not be
  // reported as the solution. The load path stops where it turns unstable, at a third of
  // the load, and says so (shorter steps cannot pass a bifurcation).
  catena::test::ensure_petsc();
  model::Model m;
  m.gravity = Vec3::Zero();
  const double L = 2.0, EI = 1e4;
  model::BeamProps b;
  b.EA = 1e9;
  b.GA_y = b.GA_z = 1e9;
  b.GJ = EI;
  b.EI_y = b.EI_z = EI;
  b.mass_per_length = 1.0;
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {L, 0, 0}, 8, b);
  catena::test::set_reference_frames(m);
  catena::test::clamp(m, nodes.front());
  const double euler = 3.14159265358979 * 3.14159265358979 * EI / (4 * L * L);
  m.nodal_loads.push_back({nodes.back(), Vec3(-3.0 * euler, 0, 0)});
  m.static_options.max_load_steps = 60;
  try {
    catena::test::solve_static(MPI_COMM_WORLD, m);
    FAIL() << "expected a NumericalError";
  } catch (const catena::NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the path turns unstable there"), std::string::npos) << what;
    const std::string reached = "reached load factor ";
    const std::size_t at = what.find(reached);
    ASSERT_NE(at, std::string::npos) << what;
    const double factor = std::stod(what.substr(at + reached.size()));
    EXPECT_NEAR(factor, 1.0 / 3.0, 0.01) << what;
  }
}

TEST(StaticFailures, SlackBarUnderCompressionIsAMechanism) {
  // A tension-only bar pushed along its axis goes slack: its free end has no stiffness.
  catena::test::ensure_petsc();
  model::Model m;
  m.gravity = Vec3::Zero();
  model::BarProps bar;
  bar.EA = 1e6;
  bar.tension_only = true;
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {0, 0, 1}, 1, bar);
  catena::test::pin(m, nodes.front());
  m.elastic_supports.push_back({nodes.back(), Vec3(1e3, 1e3, 0), Vec3::Zero()});
  m.nodal_loads.push_back({nodes.back(), Vec3(0, 0, -100)});
  EXPECT_THROW(catena::test::solve_static(MPI_COMM_WORLD, m), catena::NumericalError);
}

TEST(StaticFailures, NonConvergenceNamesLoadLevelAndNode) {
  // A strongly nonlinear hanging cable allowed one Newton iteration per load step and a
  // large minimum increment cannot reach the full load.
  catena::test::ensure_petsc();
  model::Model m;
  m.gravity = Vec3(0, 0, -9.81);
  const auto nodes = catena::test::add_line(
      m, {0, 0, 0}, {50, 0, 0}, 20, model::CableProps{1e6, 1.0, 1.0, 0.0, -0.02, {}, false, false});
  catena::test::set_reference_frames(m);
  catena::test::pin(m, nodes.front());
  catena::test::pin(m, nodes.back());
  m.static_options.max_newton_iterations = 1;
  m.static_options.min_load_step = 0.2;
  try {
    catena::test::solve_static(MPI_COMM_WORLD, m);
    FAIL() << "expected a NumericalError";
  } catch (const catena::NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("did not converge"), std::string::npos) << what;
    EXPECT_NE(what.find("largest residual is at node "), std::string::npos) << what;
    EXPECT_NE(what.find("Newton iterations"), std::string::npos) << what;
  }
}

// Numerical failures are reported, not crashed into: a mechanism (singular stiffness)
// and an impossible load path give NumericalError with a message naming the cause.
#include <gtest/gtest.h>

#include "catena/core/error.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"
#include "static_solution.hpp"

using catena::Vec3;
namespace model = catena::model;

TEST(StaticFailures, SwingingBarIsReportedAsSingular) {
  // A bar pinned at one end only, with its far end loaded along the bar: the transverse
  // directions of the free node have no stiffness at all (a mechanism).
  catena::test::ensure_petsc();
  model::Model m;
  m.gravity = Vec3::Zero();
  model::BarProps bar;
  bar.EA = 1e6;
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {1, 0, 0}, 1, bar);
  catena::test::pin(m, nodes.front());
  m.nodal_loads.push_back({nodes.back(), Vec3(100, 0, 0)});
  try {
    catena::test::solve_static(MPI_COMM_WORLD, m);
    FAIL() << "expected a NumericalError";
  } catch (const catena::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mechanism"), std::string::npos) << e.what();
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
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {50, 0, 0}, 20,
                                            model::CableProps{1e6, 1.0, 1.0, 0.0, -0.02});
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
    EXPECT_NE(what.find("largest residual is at node id"), std::string::npos) << what;
    EXPECT_NE(what.find("Newton iterations"), std::string::npos) << what;
  }
}

// The state guard of the transient driver (solvers/time/state_guard.hpp) on 1, 2 and 3
// ranks: a state at the reference and one moved within the bounds pass; a node moved beyond
// ten times the model's size, an ANCF gradient changed by more than ten, or a value that is
// not finite stop the run with a NumericalError naming the unknown — on every rank, with
// the same message; prescribed motions widen the position bound by their travel.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <limits>
#include <string>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/solvers/time/state_guard.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

namespace model = catena::model;
using catena::solvers::StateGuard;

namespace {

// Adds `delta` to component k of node `node` (its owner does; every rank assembles).
void shift(const catena::assembly::SecondOrderSystem& system, Vec x, int node, int k,
           double delta) {
  const PetscInt g = system.dof_map().global_dof(node, k);
  int owner = system.dof_map().node_owner(node), rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == owner && g >= 0) CATENA_PETSC(VecSetValue(x, g, delta, ADD_VALUES));
  CATENA_PETSC(VecAssemblyBegin(x));
  CATENA_PETSC(VecAssemblyEnd(x));
}

// The guard's message for (q, v), or "" if it passes.
std::string verdict(const StateGuard& guard, Vec q, Vec v) {
  try {
    guard.check("test", 0.5, q, v);
  } catch (const catena::NumericalError& e) {
    return e.what();
  }
  return "";
}

struct Line {
  bool petsc = (catena::test::ensure_petsc(), true);  // before the system below
  model::Model m = catena::test::cable_line_with_items({1.8e7, 195.0, 1.35, 0.0, 1e-3, {}}, 0.0);
  catena::assembly::SecondOrderSystem system{MPI_COMM_WORLD, m};
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  int middle = static_cast<int>(m.nodes.size()) / 2;
  Line() {
    system.reference_state(q.get());
    CATENA_PETSC(VecSet(v.get(), 0.0));
  }
};

}  // namespace

TEST(StateGuard, BoundsFollowTheModelsSize) {
  Line line;
  const StateGuard guard(line.system, 1.0, 1e-3);
  EXPECT_DOUBLE_EQ(guard.model_size(), 60.0);
  EXPECT_DOUBLE_EQ(guard.position_bound(), 600.0);
  EXPECT_EQ(verdict(guard, line.q.get(), line.v.get()), "");
  shift(line.system, line.q.get(), line.middle, 2, 599.0);  // z, within the bound
  EXPECT_EQ(verdict(guard, line.q.get(), line.v.get()), "");
  shift(line.system, line.q.get(), line.middle, 2, 2.0);
  const std::string message = verdict(guard, line.q.get(), line.v.get());
  EXPECT_NE(message.find("test: the motion grew without bound (energy growth) at t = 0.5 s: node " +
                         std::to_string(line.m.nodes[line.middle].id) +
                         " (z) is 601 m from its "
                         "mesh position, beyond 600 m (10 times the model's size, 60 m)"),
            std::string::npos)
      << message;
  // The same message on every rank (the verdict is reduced before anyone throws).
  int length = static_cast<int>(message.size()), shortest = 0, longest = 0;
  MPI_Allreduce(&length, &shortest, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(&length, &longest, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_EQ(shortest, longest);
}

TEST(StateGuard, GradientsAreBoundedByTen) {
  Line line;
  const StateGuard guard(line.system, 1.0, 1e-3);
  shift(line.system, line.q.get(), line.middle, 3, 9.5);  // rx_x: within
  EXPECT_EQ(verdict(guard, line.q.get(), line.v.get()), "");
  shift(line.system, line.q.get(), line.middle, 3, 1.0);
  const std::string message = verdict(guard, line.q.get(), line.v.get());
  EXPECT_NE(message.find("(rx_x) changed by 10.5, beyond 10"), std::string::npos) << message;
}

TEST(StateGuard, NotFiniteVelocityIsNamed) {
  Line line;
  const StateGuard guard(line.system, 1.0, 1e-3);
  shift(line.system, line.v.get(), line.middle, 1, std::numeric_limits<double>::quiet_NaN());
  const std::string message = verdict(guard, line.q.get(), line.v.get());
  EXPECT_NE(message.find("test: the state is not finite at t = 0.5 s (first at node " +
                         std::to_string(line.m.nodes[line.middle].id) + " (y))"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("the step (dt = 0.001 s) is unstable"), std::string::npos);
}

TEST(StateGuard, PrescribedMotionsWidenTheBound) {
  catena::test::ensure_petsc();
  const model::Model m = catena::test::cable_pendulum(8, true);
  const catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  const StateGuard guard(system, 3.0, 1e-3);
  // 1.2 m of rope (at least 1 m), the pivot driven at 2π·2·0.05 m/s for 3 s, ±0.05 m.
  EXPECT_NEAR(guard.position_bound(), 12.0 + 2.0 * M_PI * 2.0 * 0.05 * 3.0 + 0.05, 1e-12);
}

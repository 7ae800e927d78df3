// The same static equilibrium on 1, 2 and 3 ranks: every rank also solves the model alone
// (MPI_COMM_SELF) and compares with the distributed solution on MPI_COMM_WORLD, which
// CTest runs at np = 1, 2, 3. Tolerance 1e-10 relative: both solves converge to ~1e-13
// relative residual, so only round-off in assembly order separates them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "catena/assembly/second_order_system.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"
#include "static_solution.hpp"

using catena::Vec3;
namespace model = catena::model;

namespace {

// A messenger and a contact wire (two spans of 30 m), joined by droppers (tension-only
// bars), with elastic intermediate supports, clamp masses and a push-up load.
model::Model two_wire_structure() {
  model::Model m;
  m.gravity = Vec3(0, 0, -9.81);
  model::CableProps cw{1.8e7, 195.0, 1.35, 0.0, 20000.0 / 1.8e7, {}};
  model::CableProps mw{1.3e7, 131.7, 1.07, 0.0, 16000.0 / 1.3e7, {}};
  const int n = 40;
  const auto contact = catena::test::add_line(m, {0, 0, 0}, {60, 0, 0}, n, cw);
  const auto messenger = catena::test::add_line(m, {0, 0, 1.2}, {60, 0, 1.2}, n, mw);
  model::BarProps dropper;
  dropper.EA = 1e5 * 1.2;  // 100 kN/m over 1.2 m
  dropper.mass_per_length = 0.2;
  dropper.tension_only = true;
  for (int i = 4; i < n; i += 4) {
    model::ElementDesc e;
    e.id = 1000 + i;
    e.nodes = {contact[i], messenger[i]};
    e.props = dropper;
    m.elements.push_back(e);
    m.point_masses.push_back({contact[i], 0.195});
  }
  catena::test::set_reference_frames(m);
  for (int end : {0, n}) {
    catena::test::pin(m, contact[end]);
    catena::test::pin(m, messenger[end]);
  }
  m.elastic_supports.push_back({messenger[n / 2], Vec3(0, 0, 5e4), Vec3::Zero()});
  m.elastic_supports.push_back({contact[n / 2], Vec3(0, 300, 300), Vec3::Zero()});
  m.nodal_loads.push_back({contact[n / 2 + 3], Vec3(0, 0, 120)});
  return m;
}

double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0.0, scale = 1e-300;
  for (size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return diff / scale;
}

}  // namespace

TEST(ParallelEquilibrium, SameOnEveryRankCount) {
  catena::test::ensure_petsc();
  const model::Model m = two_wire_structure();
  const auto distributed = catena::test::solve_static(MPI_COMM_WORLD, m);
  const auto serial = catena::test::solve_static(MPI_COMM_SELF, m);
  EXPECT_EQ(distributed.n_dofs, serial.n_dofs);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("  positions: relative difference %.2e over %lld DOFs\n",
                relative_difference(distributed.positions, serial.positions), distributed.n_dofs);
  EXPECT_LT(relative_difference(distributed.positions, serial.positions), 1e-10);
  EXPECT_LT(relative_difference(distributed.slopes, serial.slopes), 1e-10);
  EXPECT_LT(relative_difference(distributed.axial_force, serial.axial_force), 1e-10);
  EXPECT_LT(relative_difference(distributed.reaction_force, serial.reaction_force), 1e-10);
  // Sanity of the physics: vertical reactions carry the whole weight minus the push-up.
  double weight = 0.0;
  for (const auto& e : m.elements) {
    const double L = (m.nodes[e.nodes[1]].position - m.nodes[e.nodes[0]].position).norm();
    if (const auto* c = std::get_if<model::CableProps>(&*e.props))
      weight += c->mass_per_length * L / (1 + c->prestrain) * 9.81;
    if (const auto* b = std::get_if<model::BarProps>(&*e.props))
      weight += b->mass_per_length * L * 9.81;
  }
  for (const auto& pm : m.point_masses) weight += pm.mass * 9.81;
  double vertical = 0.0;
  for (size_t i = 2; i < distributed.reaction_force.size(); i += 3)
    vertical += distributed.reaction_force[i];
  EXPECT_NEAR(vertical, weight - 120.0, 1e-8 * weight);
}

TEST(ParallelAssembly, PreallocationIsExact) {
  // The Jacobian's pattern is computed from the replicated element graph: assembly must
  // need no allocation, and no preallocated entry may stay unused.
  catena::test::ensure_petsc();
  const model::Model m = two_wire_structure();
  catena::assembly::SecondOrderSystem system(MPI_COMM_WORLD, m);
  catena::VecHandle q = system.create_vector();
  system.reference_state(q.get());
  catena::MatHandle J = system.create_matrix();
  system.jacobian({q.get(), nullptr, {}}, {1.0, 0.5, 2.0}, J.get());
  MatInfo info;
  MatGetInfo(J.get(), MAT_GLOBAL_SUM, &info);
  EXPECT_EQ(info.mallocs, 0.0);
  EXPECT_EQ(info.nz_unneeded, 0.0);
  EXPECT_GT(info.nz_used, 0.0);
}

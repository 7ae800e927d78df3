// The decoupled IRK stage solve on 1, 2 and 3 ranks (CTest runs np = 1, 2, 3): the cable
// pendulum (16 elements, pivot eliminated or driven by a constraint) is run by every rank
// alone with the coupled stage matrix (MPI_COMM_SELF) and together with the decoupled
// blocks (MPI_COMM_WORLD, the blocks and the per-DOF transforms distributed). After 40
// steps every node's position and every multiplier agree to 1e-9 relative, and the Newton
// iteration and factorisation counts are equal; Radau IIA s = 3 and Gauss s = 2.
#include <gtest/gtest.h>

#include <cmath>

#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

using catena::Vec3;
namespace model = catena::model;
namespace solvers = catena::solvers;

namespace {

model::Model pendulum(bool driven_pivot) { return catena::test::cable_pendulum(16, driven_pivot); }

struct Final {
  std::vector<double> values;  // positions of every node, then every multiplier
  long iterations = 0, factorizations = 0;
};

Final final_state(MPI_Comm comm, const model::Model& m, solvers::TableauFamily family, int stages,
                  solvers::StageLinearAlgebra algebra) {
  catena::assembly::SecondOrderSystem system(comm, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  solvers::IrkOptions o;
  o.family = family;
  o.stages = stages;
  o.atol = 1e-9;
  o.rtol = 1e-12;
  o.max_newton_iterations = 30;
  o.linear_algebra = algebra;
  solvers::IrkIntegrator irk(system, o);
  EXPECT_EQ(irk.decoupled(), algebra == solvers::StageLinearAlgebra::decoupled);
  irk.set_state(0.0, q.get(), v.get(), nullptr);
  catena::test::advance_fixed(irk, 0.2 / 40, 40);
  const auto& dofs = system.dof_map();
  Final out;
  for (int node = 0; node < static_cast<int>(m.nodes.size()); ++node)
    for (int k = 0; k < 3; ++k)
      out.values.push_back(catena::test::global_value(comm, irk.q(), dofs.global_dof(node, k)));
  for (int c = 0; c < dofs.n_constraints(); ++c)
    for (int k = 0; k < 3; ++k)
      out.values.push_back(catena::test::global_value(comm, irk.q(), dofs.multiplier_dof(c, k)));
  out.iterations = irk.counters().newton_iterations;
  out.factorizations = irk.counters().factorizations;
  return out;
}

void expect_same(bool driven_pivot, solvers::TableauFamily family, int stages) {
  catena::test::ensure_petsc();
  const model::Model m = pendulum(driven_pivot);
  const Final alone =
      final_state(MPI_COMM_SELF, m, family, stages, solvers::StageLinearAlgebra::coupled);
  const Final shared =
      final_state(MPI_COMM_WORLD, m, family, stages, solvers::StageLinearAlgebra::decoupled);
  ASSERT_EQ(alone.values.size(), shared.values.size());
  double scale = 0.0, worst = 0.0;
  for (size_t i = 0; i < alone.values.size(); ++i) {
    scale = std::max(scale, std::abs(alone.values[i]));
    worst = std::max(worst, std::abs(alone.values[i] - shared.values[i]));
  }
  EXPECT_LT(worst, 1e-9 * scale);
  EXPECT_EQ(alone.iterations, shared.iterations);
  EXPECT_EQ(alone.factorizations, shared.factorizations);
}

}  // namespace

TEST(IrkDecoupledRanks, RadauPendulum) { expect_same(false, solvers::TableauFamily::radau_iia, 3); }
TEST(IrkDecoupledRanks, RadauDrivenPendulum) {
  expect_same(true, solvers::TableauFamily::radau_iia, 3);
}
TEST(IrkDecoupledRanks, GaussDrivenPendulum) {
  expect_same(true, solvers::TableauFamily::gauss, 2);
}

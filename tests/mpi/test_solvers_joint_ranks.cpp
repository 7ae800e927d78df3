// Rigid bodies and joints on 1, 2 and 3 ranks: a taut rope carrying a block by a spherical
// joint at one of its nodes (rope node and block on different ranks once the rope is
// partitioned: bodies, having no elements, live on rank 0) and a hook hanging from the
// block by a revolute joint, started off its equilibrium so that everything swings. Every
// rank also runs the model alone (MPI_COMM_SELF) and compares with the distributed run on
// MPI_COMM_WORLD (CTest runs np = 1, 2, 3): positions, axes and every multiplier after 40
// ms of HHT and of Radau IIA (s = 3) at 1 ms steps, and of RATTLE at 25 us (below its
// stability limit of 53 us, the rope's axial waves), agree to 1e-9 relative.
#include <gtest/gtest.h>

#include <cmath>

#include "catena/model/scene_reader.hpp"
#include "catena/solvers/time/hht_integrator.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "catena/solvers/time/rattle_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "petsc_test_session.hpp"

namespace model = catena::model;
namespace solvers = catena::solvers;

namespace {

const char* kScene = R"(
gravity: [0, 0, -9.81]
sections:
  rope: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}
nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [30, 0, 0]}
  - {id: 5, position: [15, 0, 0]}
  - {id: 3, position: [15, 0, -0.5]}
  - {id: 4, position: [15.3, 0, -1.6]}
lines:
  - {name: left, from: 1, to: 5, elements: 15, section: rope, tension: 20000}
  - {name: right, from: 5, to: 2, elements: 15, section: rope, tension: 20000}
supports: [{node: 1, fix: pinned}, {node: 2, fix: pinned}]
analysis: {type: dynamic, duration: 1, initial: {from: reference}}
bodies:
  - {name: block, node: 3, mass: 20, inertia: [0.5, 0.5, 0.3]}
  - {name: hook, node: 4, mass: 5, inertia: [0.1, 0.12, 0.05], axes: [[1, 0, 0.2], [0, 1, 0]]}
joints:
  - {type: spherical, between: [block, 5]}
  - {type: revolute, between: [hook, block], point: [15, 0, -1.0], axis: [0, 1, 0]}
)";

// Every node's unknowns and every multiplier after 40 steps, on `comm`: nodal values first,
// then `multipliers` of them.
struct Final {
  std::vector<double> values;
  size_t multipliers = 0;
  double hook_z = 0.0;  // m: the hook's point
};
enum class Method { hht, radau, rattle };

Final final_state(MPI_Comm comm, const model::Model& m, Method method) {
  catena::assembly::SecondOrderSystem system(comm, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  std::unique_ptr<solvers::TimeIntegrator> integrator;
  double dt = 1e-3;
  if (method == Method::rattle) {
    integrator = std::make_unique<solvers::RattleIntegrator>(system, solvers::RattleOptions{});
    dt = 2.5e-5;
  } else if (method == Method::radau) {
    solvers::IrkOptions o;
    o.family = solvers::TableauFamily::radau_iia;
    o.stages = 3;
    integrator = std::make_unique<solvers::IrkIntegrator>(system, o);
  } else {
    integrator = std::make_unique<solvers::HhtIntegrator>(system, solvers::HhtOptions{});
  }
  integrator->set_state(0.0, q.get(), v.get(), nullptr);
  catena::test::advance_fixed(*integrator, dt, static_cast<int>(std::lround(0.04 / dt)));
  const auto& dofs = system.dof_map();
  Final out;
  out.hook_z = catena::test::global_value(comm, integrator->q(), dofs.global_dof(4, 2));
  for (int node = 0; node < static_cast<int>(m.nodes.size()); ++node)
    for (int k = 0; k < dofs.node_dofs(node); ++k)
      if (dofs.global_dof(node, k) >= 0)
        out.values.push_back(
            catena::test::global_value(comm, integrator->q(), dofs.global_dof(node, k)));
  for (int c = 0; c < dofs.n_constraints(); ++c)
    for (int k = 0; k < dofs.n_multipliers(c); ++k) {
      out.values.push_back(
          catena::test::global_value(comm, integrator->q(), dofs.multiplier_dof(c, k)));
      ++out.multipliers;
    }
  return out;
}

void expect_same_on_all_ranks(Method method) {
  catena::test::ensure_petsc();
  const model::Model m = model::parse_scene(kScene, "joints.yaml");
  ASSERT_EQ(m.joints.size(), 2u);
  const Final alone = final_state(MPI_COMM_SELF, m, method);
  const Final shared = final_state(MPI_COMM_WORLD, m, method);
  ASSERT_EQ(alone.values.size(), shared.values.size());
  const size_t nodal = alone.values.size() - alone.multipliers;
  // Positions and axes to 1e-9 of the largest coordinate; multipliers (forces, moments)
  // to 1e-9 of the model's force scale, the rope's 20 kN tension, to which Newton's
  // tolerance is relative.
  double scale = 0.0, worst_nodal = 0.0, worst_multiplier = 0.0;
  for (size_t i = 0; i < alone.values.size(); ++i) {
    const double difference = std::abs(alone.values[i] - shared.values[i]);
    if (i < nodal) {
      scale = std::max(scale, std::abs(alone.values[i]));
      worst_nodal = std::max(worst_nodal, difference);
    } else {
      worst_multiplier = std::max(worst_multiplier, difference);
    }
  }
  EXPECT_LT(worst_nodal, 1e-9 * scale);
  EXPECT_LT(worst_multiplier, 1e-9 * 20000.0);
  // The bodies moved: the hook, falling and swinging, is millimetres below where it began.
  ASSERT_EQ(m.nodes[4].id, 4);
  EXPECT_LT(alone.hook_z, m.nodes[4].position.z() - 1e-3);
}

}  // namespace

TEST(JointRanks, HhtAgreesOnEveryRankCount) { expect_same_on_all_ranks(Method::hht); }
TEST(JointRanks, RadauAgreesOnEveryRankCount) { expect_same_on_all_ranks(Method::radau); }
TEST(JointRanks, RattleAgreesOnEveryRankCount) { expect_same_on_all_ranks(Method::rattle); }

// Constraints on 1, 2 and 3 ranks: a taut rope carrying droppers clamped to it by
// coincidence constraints (clamp and rope node on different ranks once the rope is
// partitioned), one end driven along a sine by a prescribed constraint. Every rank also
// runs the model alone (MPI_COMM_SELF) and compares with the distributed run on
// MPI_COMM_WORLD (CTest runs np = 1, 2, 3): positions and every multiplier after 40 steps
// of HHT and of Radau IIA (s = 3) agree to 1e-9 relative.
#include <gtest/gtest.h>

#include <cmath>

#include "catena/solvers/time/hht_integrator.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "dynamics_fixtures.hpp"
#include "model_builders.hpp"
#include "petsc_test_session.hpp"

using catena::Vec3;
namespace model = catena::model;
namespace solvers = catena::solvers;

namespace {

model::Model clamped_droppers() {
  model::Model m;
  m.gravity = Vec3(0, 0, -9.81);
  const model::CableProps rope{1.8e7, 195.0, 1.35, 0.0, 20000.0 / 1.8e7, {}};
  const auto nodes = catena::test::add_line(m, {0, 0, 0}, {30, 0, 0}, 30, rope);
  catena::test::set_reference_frames(m);
  catena::test::pin(m, nodes.back());
  model::Constraint driven;
  driven.type = model::ConstraintType::prescribed;
  driven.node_a = nodes.front();
  driven.amplitude = Vec3(0, 0, 0.02);
  driven.frequency = 4.0;
  m.constraints.push_back(driven);
  for (int i = 5; i < 30; i += 5) {
    // Clamp node (coincident with the rope node), dropper bar, clamp mass at the bottom.
    const Vec3 at = m.nodes[static_cast<size_t>(nodes[static_cast<size_t>(i)])].position;
    m.nodes.push_back({static_cast<std::int64_t>(m.nodes.size() + 1), at});
    const int clamp = static_cast<int>(m.nodes.size()) - 1;
    m.nodes.push_back({static_cast<std::int64_t>(m.nodes.size() + 1), at - Vec3(0, 0, 0.8)});
    const int bottom = static_cast<int>(m.nodes.size()) - 1;
    model::Constraint c;
    c.type = model::ConstraintType::coincident;
    c.node_a = clamp;
    c.node_b = nodes[static_cast<size_t>(i)];
    m.constraints.push_back(c);
    model::ElementDesc bar;
    bar.id = 1000 + i;
    bar.nodes = {clamp, bottom};
    bar.props = model::BarProps{1e5, 0.2, 0.0, 0.0, false};
    m.elements.push_back(bar);
    m.point_masses.push_back({bottom, 0.5});
    m.point_masses.push_back({clamp, 0.2});
  }
  return m;
}

// Positions of every node and every multiplier after n steps, on `comm`.
std::vector<double> final_state(MPI_Comm comm, const model::Model& m, bool radau) {
  catena::assembly::SecondOrderSystem system(comm, m);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  std::unique_ptr<solvers::TimeIntegrator> integrator;
  if (radau) {
    solvers::IrkOptions o;
    o.family = solvers::TableauFamily::radau_iia;
    o.stages = 3;
    integrator = std::make_unique<solvers::IrkIntegrator>(system, o);
  } else {
    integrator = std::make_unique<solvers::HhtIntegrator>(system, solvers::HhtOptions{});
  }
  integrator->set_state(0.0, q.get(), v.get(), nullptr);
  catena::test::advance_fixed(*integrator, 1e-3, 40);
  const auto& dofs = system.dof_map();
  std::vector<double> out;
  for (int node = 0; node < static_cast<int>(m.nodes.size()); ++node)
    for (int k = 0; k < 3; ++k)
      out.push_back(catena::test::global_value(comm, integrator->q(), dofs.global_dof(node, k)));
  for (int c = 0; c < dofs.n_constraints(); ++c)
    for (int k = 0; k < 3; ++k)
      out.push_back(catena::test::global_value(comm, integrator->q(), dofs.multiplier_dof(c, k)));
  return out;
}

void expect_same_on_all_ranks(bool radau) {
  catena::test::ensure_petsc();
  const model::Model m = clamped_droppers();
  const std::vector<double> alone = final_state(MPI_COMM_SELF, m, radau);
  const std::vector<double> shared = final_state(MPI_COMM_WORLD, m, radau);
  ASSERT_EQ(alone.size(), shared.size());
  double scale = 0.0, worst = 0.0;
  for (size_t i = 0; i < alone.size(); ++i) {
    scale = std::max(scale, std::abs(alone[i]));
    worst = std::max(worst, std::abs(alone[i] - shared[i]));
  }
  EXPECT_LT(worst, 1e-9 * scale);
  // The multipliers carry real forces (the clamps hold the droppers' weight).
  EXPECT_GT(std::abs(alone[alone.size() - 1]), 1.0);
}

}  // namespace

TEST(ConstraintRanks, HhtAgreesOnEveryRankCount) { expect_same_on_all_ranks(false); }
TEST(ConstraintRanks, RadauAgreesOnEveryRankCount) { expect_same_on_all_ranks(true); }

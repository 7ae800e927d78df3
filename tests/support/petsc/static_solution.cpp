#include "static_solution.hpp"

#include "catena/assembly/second_order_system.hpp"
#include "catena/assembly/state_view.hpp"

namespace catena::test {
namespace {
// Sum-reduce a model-ordered array that each rank filled for its own rows.
void complete(MPI_Comm comm, std::vector<double>& a) {
  MPI_Allreduce(MPI_IN_PLACE, a.data(), static_cast<int>(a.size()), MPI_DOUBLE, MPI_SUM, comm);
}
}  // namespace

GatheredStatic solve_static(
    MPI_Comm comm, const model::Model& m,
    const std::function<void(const assembly::SecondOrderSystem&, Vec)>& guess) {
  assembly::SecondOrderSystem system(comm, m);
  VecHandle q = system.create_vector();
  system.reference_state(q.get());
  VecHandle start;
  if (guess) {
    start = system.create_vector();
    system.reference_state(start.get());
    guess(system, start.get());
  }
  solvers::StaticSolver solver(system, m.static_options);
  GatheredStatic g;
  g.report = solver.solve(q.get(), start.get());
  g.n_dofs = system.dof_map().n_global();

  const size_t n_nodes = m.nodes.size();
  g.positions.assign(3 * n_nodes, 0.0);
  g.slopes.assign(3 * n_nodes, 0.0);
  g.axial_force.assign(m.elements.size(), 0.0);
  g.reaction_force.assign(3 * n_nodes, 0.0);
  g.reaction_moment.assign(3 * n_nodes, 0.0);
  std::vector<double> pos, slopes;
  catena::assembly::StateView(system).owned_node_values(q.get(), pos, slopes);
  const auto& owned = system.dof_map().owned_nodes();
  for (size_t i = 0; i < owned.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      g.positions[3 * owned[i] + d] = pos[3 * i + d];
      g.slopes[3 * owned[i] + d] = slopes[3 * i + d];
    }
  std::vector<int> elements;
  std::vector<elements::SectionResult> sections;
  catena::assembly::StateView(system).section_results({q.get(), nullptr, {}}, elements, sections);
  for (size_t i = 0; i < elements.size(); ++i) g.axial_force[elements[i]] = sections[i].axial_force;
  const assembly::Reactions r =
      catena::assembly::StateView(system).reactions({q.get(), nullptr, {}});
  for (size_t i = 0; i < r.nodes.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      g.reaction_force[3 * r.nodes[i] + d] = r.force[3 * i + d];
      g.reaction_moment[3 * r.nodes[i] + d] = r.moment[3 * i + d];
    }
  complete(comm, g.positions);
  complete(comm, g.slopes);
  complete(comm, g.axial_force);
  complete(comm, g.reaction_force);
  complete(comm, g.reaction_moment);
  return g;
}

}  // namespace catena::test

#include "static_snapshot.hpp"

#include "catena/assembly/second_order_system.hpp"
#include "catena/assembly/state_view.hpp"

namespace catena::catenary::detail {
namespace {

// Completes a model-ordered array that each rank filled only where it owns the value.
void sum_over_ranks(MPI_Comm comm, std::vector<double>& values) {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm);
}

std::vector<Vec3> to_vec3(const std::vector<double>& flat) {
  std::vector<Vec3> out(flat.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
  return out;
}

}  // namespace

StaticSnapshot solve_static_snapshot(MPI_Comm comm, const model::Model& model) {
  assembly::SecondOrderSystem system(comm, model);
  VecHandle q = system.create_vector();
  system.reference_state(q.get());
  solvers::StaticSolver solver(system, model.static_options);
  StaticSnapshot snapshot;
  snapshot.report = solver.solve(q.get());

  const std::size_t n_nodes = model.nodes.size();
  std::vector<double> positions(3 * n_nodes, 0.0), reactions(3 * n_nodes, 0.0);
  std::vector<double> owned_positions, owned_slopes;
  const assembly::StateView view(system);
  view.owned_node_values(q.get(), owned_positions, owned_slopes);
  const std::vector<int>& owned = system.dof_map().owned_nodes();
  for (std::size_t i = 0; i < owned.size(); ++i)
    for (std::size_t d = 0; d < 3; ++d)
      positions[3 * static_cast<std::size_t>(owned[i]) + d] = owned_positions[3 * i + d];

  const elements::LoadPath full_load;  // the end of the load path, where solve() stops
  snapshot.axial_force.assign(model.elements.size(), 0.0);
  std::vector<int> elements;
  std::vector<elements::SectionResult> sections;
  view.section_results({q.get(), nullptr, full_load}, elements, sections);
  for (std::size_t i = 0; i < elements.size(); ++i)
    snapshot.axial_force[static_cast<std::size_t>(elements[i])] = sections[i].axial_force;

  const assembly::Reactions r = view.reactions({q.get(), nullptr, full_load});
  for (std::size_t i = 0; i < r.nodes.size(); ++i)
    for (std::size_t d = 0; d < 3; ++d)
      reactions[3 * static_cast<std::size_t>(r.nodes[i]) + d] = r.force[3 * i + d];

  sum_over_ranks(comm, positions);
  sum_over_ranks(comm, reactions);
  sum_over_ranks(comm, snapshot.axial_force);
  snapshot.positions = to_vec3(positions);
  snapshot.reactions = to_vec3(reactions);
  return snapshot;
}

double mean_axial_force(const model::Model& model, const StaticSnapshot& snapshot,
                        const std::vector<int>& elements) {
  double weighted = 0.0, length = 0.0;
  for (const int e : elements) {
    const model::ElementDesc& element = model.elements[static_cast<std::size_t>(e)];
    const double l =
        (model.nodes[element.nodes[1]].position - model.nodes[element.nodes[0]].position).norm();
    weighted += snapshot.axial_force[static_cast<std::size_t>(e)] * l;
    length += l;
  }
  return length > 0.0 ? weighted / length : 0.0;
}

}  // namespace catena::catenary::detail

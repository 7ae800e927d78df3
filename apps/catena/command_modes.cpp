// `catena modes SCENE [--set k=v ...] [--count N] [-o OUT.h5]`: the lowest vibration
// modes about the scene's static equilibrium (docs/output.md, "Modes"). The scene is
// loaded and, for a catenary, shaped as `catena run` does it; its static equilibrium is
// solved (whatever its analysis type: a dynamic scene's modes are those about its static
// state); then K φ = ω² M φ there (solvers/modes/modal_analysis.hpp).
//
//   catena modes meshes/simple_catenary.yaml --count 40
//   mpirun -n 2 catena modes meshes/en50318_250.yaml -o en50318_modes.h5
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "catena/assembly/state_view.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/core/version.hpp"
#include "catena/io/modes_result.hpp"
#include "catena/solvers/modes/modal_analysis.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "commands.hpp"
#include "log_stage.hpp"
#include "output_preflight.hpp"
#include "run_info.hpp"
#include "scene_loading.hpp"
#include "shape_report.hpp"
#include "static_phase.hpp"

namespace catena::app {
namespace {

// -o as given; else the scene's output file with "_modes" before its extension.
std::string modes_file(const CommandLine& cl, const model::Model& m) {
  if (cl.output) return *cl.output;
  std::filesystem::path path(m.output.file);
  const std::string extension = path.has_extension() ? path.extension().string() : ".h5";
  path.replace_extension();
  return path.string() + "_modes" + extension;
}

}  // namespace

void command_modes(MPI_Comm comm, const CommandLine& cl) {
  const int rank = mpi_rank(comm);
  model::Model m = load_scene(comm, cl.scene, cl.overrides, memory_budget(comm, cl));
  m.output.file = modes_file(cl, m);
  if (rank == 0) {
    std::printf("catena %s (%s): modes of scene %s '%s', %zu nodes, %zu elements, %d ranks\n",
                version(), git_version(), cl.scene.c_str(), m.name.c_str(), m.nodes.size(),
                m.elements.size(), mpi_size(comm));
    std::fflush(stdout);
  }
  check_output_path(comm, m, cl.output.has_value());
  solvers::refuse_constraints_for_modes(m);  // before the shape finding and statics it would waste
  shape_catenary(
      comm, m, stdout,
      cl.progress_seconds);  // a `catenary` scene: dropper lengths first, as `catena run`

  assembly::SecondOrderSystem system(comm, m);
  VecHandle q = system.create_vector();
  system.reference_state(q.get());
  const solvers::StaticReport equilibrium = solve_statics(system, q.get(), cl);
  if (rank == 0) {
    std::printf("static equilibrium: %d load steps, %d Newton iterations, |f| = %.3e N\n",
                equilibrium.n_load_steps, equilibrium.n_newton_iterations,
                equilibrium.residual_norm);
    std::fflush(stdout);
  }
  const double start = MPI_Wtime();
  const solvers::Modes modes = [&] {
    const LogStage stage("Modes");
    return solvers::compute_modes(system, q.get(), {cl.modes.count});
  }();
  const double seconds = MPI_Wtime() - start;

  io::ModesResult result;
  result.owned_nodes = system.dof_map().owned_nodes();
  const assembly::StateView view(system);
  std::vector<double> slopes;
  view.owned_node_values(q.get(), result.positions, slopes);
  result.frequency = modes.frequency;
  for (const VecHandle& shape : modes.shape) {
    result.shapes.emplace_back();
    view.owned_node_changes(shape.get(), result.shapes.back(), slopes);
  }
  if (rank == 0) {
    std::printf("modes: %zu, %d Krylov-Schur restarts, %.2f s\n", modes.frequency.size(),
                modes.n_iterations, seconds);
    std::printf("  %5s %14s %12s %12s\n", "mode", "frequency [Hz]", "period [s]", "residual");
    for (std::size_t k = 0; k < modes.frequency.size(); ++k)
      std::printf("  %5zu %14.6f %12.6f %12.1e\n", k + 1, modes.frequency[k],
                  1.0 / modes.frequency[k], modes.residual[k]);
    std::fflush(stdout);
  }
  {
    const LogStage stage("Output");
    io::write_modes(comm, m.output.file, m, result, run_info(cl, system));
  }
  if (rank == 0) std::printf("output: %s\n", m.output.file.c_str());
}

}  // namespace catena::app

#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/assembly/state_view.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/core/version.hpp"
#include "catena/io/hdf5_writer.hpp"
#include "catena/io/output_lock.hpp"
#include "catena/io/run_files.hpp"
#include "catena/model/catenary_ends.hpp"
#include "catena/model/model_summary.hpp"
#include "catena/solvers/statics/hanging_cable_guess.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "commands.hpp"
#include "error_bar.hpp"
#include "log_stage.hpp"
#include "memory_report.hpp"
#include "output_preflight.hpp"
#include "progress_lines.hpp"
#include "run_info.hpp"
#include "scene_loading.hpp"
#include "shape_report.hpp"
#include "static_phase.hpp"

namespace catena::app {
namespace {

io::StaticResult collect_result(assembly::SecondOrderSystem& system, Vec q,
                                const solvers::StaticReport& report) {
  io::StaticResult r;
  r.owned_nodes = system.dof_map().owned_nodes();
  const assembly::StateView view(system);
  view.owned_node_values(q, r.positions, r.slopes);
  std::vector<elements::SectionResult> sections;
  view.section_results({q, nullptr, {}}, r.owned_elements, sections);
  for (const auto& s : sections) {
    r.axial_force.push_back(s.axial_force);
    r.axial_strain.push_back(s.axial_strain);
    for (int d = 0; d < 3; ++d) {
      r.shear_force.push_back(s.shear_force[d]);
      r.bending_moment.push_back(s.bending_moment[d]);
    }
    r.torsion.push_back(s.torsion);
  }
  const assembly::Reactions reactions = view.reactions({q, nullptr, {}});
  r.support_nodes = reactions.nodes;
  r.reaction_force = reactions.force;
  r.reaction_moment = reactions.moment;
  r.load_factor = report.load_factor;
  r.n_load_steps = report.n_load_steps;
  r.n_newton_iterations = report.n_newton_iterations;
  r.residual_norm = report.residual_norm;
  return r;
}

// Global summary numbers for the console (collective).
void print_summary(MPI_Comm comm, const model::Model& m, const io::StaticResult& r,
                   const solvers::StaticReport& report, PetscInt n_dofs, double seconds) {
  double local[3] = {0.0, -1e300, 1e300};  // max |displacement|, max N, min N
  for (size_t i = 0; i < r.owned_nodes.size(); ++i) {
    const Vec3 x(r.positions[3 * i], r.positions[3 * i + 1], r.positions[3 * i + 2]);
    local[0] = std::max(local[0], (x - m.nodes[r.owned_nodes[i]].position).norm());
  }
  for (double n : r.axial_force) {
    local[1] = std::max(local[1], n);
    local[2] = std::min(local[2], n);
  }
  double reaction_local[3] = {0, 0, 0}, reaction[3];
  for (size_t i = 0; i < r.support_nodes.size(); ++i)
    for (int d = 0; d < 3; ++d) reaction_local[d] += r.reaction_force[3 * i + d];
  double global[3];
  MPI_Allreduce(&local[0], &global[0], 1, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(&local[1], &global[1], 1, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(&local[2], &global[2], 1, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(reaction_local, reaction, 3, MPI_DOUBLE, MPI_SUM, comm);
  if (mpi_rank(comm) != 0) return;
  std::printf(
      "static equilibrium: %d load steps (%d rejected), %d Newton iterations, "
      "|f| = %.3e N, %.2f s\n",
      report.n_load_steps, report.n_rejected_steps, report.n_newton_iterations,
      report.residual_norm, seconds);
  if (const std::string guess = solvers::describe_guess(report.guess); !guess.empty())
    std::printf("%s\n", guess.c_str());
  std::printf("  free DOFs %lld on %d ranks\n", static_cast<long long>(n_dofs), mpi_size(comm));
  std::printf("  max displacement %.6g m\n", global[0]);
  if (global[1] >= global[2])
    std::printf("  axial force: max %.6g N, min %.6g N\n", global[1], global[2]);
  std::printf("  sum of support reactions: [%.6g, %.6g, %.6g] N\n", reaction[0], reaction[1],
              reaction[2]);
}

}  // namespace

void command_run(MPI_Comm comm, const CommandLine& cl) {
  if (cl.error_bar_ranks > 0) return run_with_concurrent_error_bar(comm, cl);
  model::Model m = load_scene(comm, cl.scene, cl.overrides, memory_budget(comm, cl));
  const int rank = mpi_rank(comm);
  if (rank == 0) {
    std::printf("catena %s (%s): scene %s '%s', %zu nodes, %zu elements, %d ranks\n", version(),
                git_version(), cl.scene.c_str(), m.name.c_str(), m.nodes.size(), m.elements.size(),
                mpi_size(comm));
    std::fflush(stdout);
    // What `catena check` warns of (a pantograph leaving its path, an evaluation section
    // not traversed) is worth saying before a run spends its time.
    for (const std::string& warning : model::scene_warnings(m))
      std::fprintf(stderr, "catena: warning: %s\n", warning.c_str());
    std::fflush(stderr);
  }
  if (cl.realtime && m.analysis != model::AnalysisType::dynamic)
    throw InputError({cl.scene, 0, "--realtime"},
                     "--realtime measures a dynamic run against the wall clock; this scene's "
                     "analysis is static (analysis.type: static)");
  check_error_bar_request(cl, m);
  // Before any solving: a run must not end by finding that it cannot write its results.
  check_output_path(comm, m, cl.output.has_value());
  check_modal_basis_path(comm, m);
  // One run at a time per output name (and its checkpoint and partial output).
  const io::OutputLock lock(comm, m.output.file);
  if (rank == 0) io::remove_abandoned_checkpoint_temporaries(m.output.file);
  shape_catenary(comm, m, stdout,
                 cl.progress_seconds);  // a `catenary` scene: dropper lengths before any analysis
  if (m.analysis == model::AnalysisType::dynamic) {
    if (const int ends = model::absorb_catenary_ends(m); ends > 0 && rank == 0)
      std::printf("catenary: the wires' %d end supports become absorbing ends for the run\n", ends);
    run_dynamic(comm, cl, m);
    if (cl.error_bar) run_error_bar(comm, cl, m);
    return;
  }
  if (cl.restart)
    throw InputError({cl.scene, 0, "--restart"},
                     "--restart continues a dynamic run from its checkpoint; this scene's "
                     "analysis is static (analysis.type: static)");
  const double start = MPI_Wtime();
  assembly::SecondOrderSystem system(comm, m);
  VecHandle q = system.create_vector();
  system.reference_state(q.get());
  const solvers::StaticReport report = solve_statics(system, q.get(), cl);
  const double seconds = MPI_Wtime() - start;

  const io::StaticResult result = collect_result(system, q.get(), report);
  print_summary(comm, m, result, report, system.dof_map().n_global(), seconds);
  print_peak_memory(rank, peak_memory(comm), mpi_size(comm));
  {
    const LogStage stage("Output");
    io::write_static_result(comm, m.output.file, m, result, run_info(cl, system));
  }
  if (rank == 0) std::printf("output: %s\n", m.output.file.c_str());
}

}  // namespace catena::app

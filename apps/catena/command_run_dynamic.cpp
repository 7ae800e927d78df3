// `catena run` for analysis.type: dynamic — initial state (static equilibrium or the
// reference, plus the scene's offsets and velocity), the integrator and step control the
// scene asks for, time-series HDF5 output sampled at the output interval, wall-clock
// flushes, and a clean stop on SIGTERM/SIGINT (output closed with status "interrupted").
// Checkpoints and --restart are not implemented yet.
#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/transient_writer.hpp"
#include "catena/solvers/integrator_factory.hpp"
#include "catena/solvers/static_solver.hpp"
#include "catena/solvers/transient_solver.hpp"
#include "commands.hpp"
#include "initial_state.hpp"
#include "run_info.hpp"
#include "stop_signal.hpp"

namespace catena::app {
namespace {

// Streams samples and step records to the output file; flushes on the wall clock (rank
// 0's clock, broadcast, so that every rank takes the collective path).
class OutputObserver : public solvers::TransientObserver {
 public:
  OutputObserver(assembly::SecondOrderSystem& system, io::TransientWriter& writer,
                 const model::OutputOptions& output)
      : system_(system),
        writer_(writer),
        output_(output),
        last_flush_(MPI_Wtime()) {}

  void sample(double t, Vec q, Vec v) override {
    std::vector<double> positions, slopes, velocities, unused;
    system_.owned_node_values(q, positions, slopes);
    system_.owned_node_values(v, velocities, unused);
    std::vector<int> elements;
    std::vector<elements::SectionResult> sections;
    system_.section_results({q, v, {}, t}, elements, sections);
    std::vector<double> axial;
    for (const auto& s : sections) axial.push_back(s.axial_force);
    std::vector<int> constraints;
    std::vector<double> constraint_forces;
    system_.owned_constraint_forces(q, constraints, constraint_forces);
    writer_.append_sample(t, positions, velocities, slopes, axial, constraint_forces);
  }

  void step(const solvers::StepRecord& r) override {
    writer_.append_step({r.time, r.dt, r.newton_iterations, r.error, r.rejected});
    double now = MPI_Wtime();
    MPI_Bcast(&now, 1, MPI_DOUBLE, 0, system_.comm());
    if (now - last_flush_ >= output_.flush_wall_seconds) {
      writer_.flush();
      last_flush_ = now;
    }
  }

  bool stop_requested() override { return StopSignal::requested(); }


 private:
  assembly::SecondOrderSystem& system_;
  io::TransientWriter& writer_;
  const model::OutputOptions& output_;
  double last_flush_;
};

std::vector<std::pair<std::string, double>> statistics(const solvers::TransientReport& r,
                                                       const solvers::IntegratorCounters& k,
                                                       double wall) {
  return {{"t_reached", r.t_reached},
          {"steps_accepted", static_cast<double>(r.steps_accepted)},
          {"steps_rejected", static_cast<double>(r.steps_rejected)},
          {"newton_iterations", static_cast<double>(k.newton_iterations)},
          {"residual_evaluations", static_cast<double>(k.residual_evaluations)},
          {"jacobian_evaluations", static_cast<double>(k.jacobian_evaluations)},
          {"factorizations", static_cast<double>(k.factorizations)},
          {"linear_solves", static_cast<double>(k.linear_solves)},
          {"wall_seconds", wall}};
}

}  // namespace

void run_dynamic(MPI_Comm comm, const CommandLine& cl, const model::Model& m) {
  const int rank = mpi_rank(comm);
  const double start = MPI_Wtime();
  assembly::SecondOrderSystem system(comm, m);
  VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  const model::DynamicOptions& dyn = m.dynamic_options;
  if (dyn.initial.from_static) {
    solvers::StaticSolver statics(system, m.static_options);
    const solvers::StaticReport report = statics.solve(q.get());
    if (rank == 0)
      std::printf("initial static equilibrium: %d load steps, %d Newton iterations, |f| = %.3e N\n",
                  report.n_load_steps, report.n_newton_iterations, report.residual_norm);
  }
  apply_initial_conditions(system, q.get(), v.get());

  std::unique_ptr<solvers::TimeIntegrator> integrator =
      solvers::make_integrator(system, dyn.integrator);
  integrator->set_state(0.0, q.get(), v.get(), nullptr);
  solvers::TransientOptions options;
  options.t_end = dyn.duration;
  options.sample_interval = m.output.interval;
  options.step = solvers::make_step_control(dyn.integrator);
  if (rank == 0) {
    std::printf("dynamics: %s, %s step %g s, %g s simulated, %lld free DOFs on %d ranks\n",
                integrator->name().c_str(), options.step.adaptive ? "adaptive, first" : "fixed",
                options.step.dt, options.t_end,
                static_cast<long long>(system.dof_map().n_global()), mpi_size(comm));
    std::fflush(stdout);
  }

  std::vector<int> owned_elements;
  {
    std::vector<elements::SectionResult> unused;
    system.section_results({q.get(), v.get(), {}, 0.0}, owned_elements, unused);
  }
  std::vector<int> owned_constraints;
  {
    std::vector<double> unused;
    system.owned_constraint_forces(q.get(), owned_constraints, unused);
  }
  io::TransientWriter writer(comm, m.output.file, m, run_info(cl, system),
                             system.dof_map().owned_nodes(), owned_elements, owned_constraints);
  OutputObserver observer(system, writer, m.output);
  const StopSignal signals;
  solvers::TransientReport report;
  try {
    report = solvers::run_transient(system, *integrator, options, observer);
  } catch (const NumericalError& e) {
    writer.close(std::string("failed: ") + e.what(),
                 statistics(report, integrator->counters(), MPI_Wtime() - start));
    throw;
  }
  const double wall = MPI_Wtime() - start;
  const auto& k = integrator->counters();
  writer.close(report.interrupted ? "interrupted" : "complete", statistics(report, k, wall));
  if (rank == 0) {
    std::printf("%s at t = %g s: %ld steps (%ld rejected, dt %.3g..%.3g s), %ld Newton "
                "iterations, %ld factorisations, %ld residual evaluations, %.2f s wall "
                "(%.3g s per simulated second)\n",
                report.interrupted ? "interrupted" : "done", report.t_reached,
                report.steps_accepted, report.steps_rejected, report.smallest_dt,
                report.largest_dt, k.newton_iterations, k.factorizations,
                k.residual_evaluations, wall, wall / std::max(report.t_reached, 1e-300));
    std::printf("output: %s (%ld samples)\n", m.output.file.c_str(), report.samples);
  }
  if (report.interrupted) throw RunInterrupted{StopSignal::signal_number(), report.t_reached};
}

}  // namespace catena::app

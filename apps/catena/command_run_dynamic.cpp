// `catena run` for analysis.type: dynamic — initial state (static equilibrium or the
// reference, plus the scene's offsets and velocity), the integrator and step control the
// scene asks for, time-series HDF5 output sampled at the output interval, wall-clock
// flushes, checkpoints (atomic, <output>.chk: on the wall clock, at SIGTERM/SIGINT and at
// the end) and a clean stop on SIGTERM/SIGINT (output closed with status "interrupted").
// --restart continues from the checkpoint, appending to the output file.
#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/checkpoint.hpp"
#include "catena/io/transient_writer.hpp"
#include "catena/io/transient_xdmf.hpp"
#include "catena/solvers/integrator_factory.hpp"
#include "catena/solvers/static_solver.hpp"
#include "catena/solvers/transient_solver.hpp"
#include "commands.hpp"
#include "initial_state.hpp"
#include "resume_checkpoint.hpp"
#include "run_info.hpp"
#include "shape_report.hpp"
#include "stop_signal.hpp"
#include "test_hooks.hpp"

namespace catena::app {
namespace {

// Streams samples and step records to the output file; flushes on the wall clock (rank
// 0's clock, broadcast, so that every rank takes the collective path).
class OutputObserver : public solvers::TransientObserver {
 public:
  OutputObserver(assembly::SecondOrderSystem& system, io::TransientWriter& writer,
                 const model::OutputOptions& output, const solvers::TimeIntegrator& integrator)
      : system_(system),
        writer_(writer),
        output_(output),
        integrator_(integrator),
        last_flush_(MPI_Wtime()),
        last_checkpoint_(last_flush_) {}

  // Collective. Flushes the output, then writes the checkpoint of the integrator's
  // current (accepted) state, recording how many output rows belong to it.
  void checkpoint() {
    writer_.flush();
    io::CheckpointFacts facts;
    facts.time = integrator_.time();
    facts.last_dt = last_dt_;
    facts.samples = writer_.samples_written();
    facts.steps = writer_.steps_written();
    facts.integrator = integrator_.name();
    io::CheckpointShare share;
    share.nodes = system_.dof_map().owned_nodes();
    std::vector<double> unused;
    system_.owned_node_rows(integrator_.q(), share.q, share.lambda);
    system_.owned_node_rows(integrator_.v(), share.v, unused);
    system_.owned_node_rows(integrator_.a(), share.a, unused);
    std::vector<double> forces;
    system_.owned_constraint_forces(integrator_.q(), share.constraints, forces);
    share.resume = resume_rows(system_, integrator_, driver_);
    io::write_checkpoint(system_.comm(), output_.file + ".chk", system_.model(), facts, share);
  }
  void set_last_dt(double dt) { last_dt_ = dt; }
  void set_driver_state(const std::optional<solvers::DriverState>& d) { driver_ = d; }

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
    io::ContactSample contacts;
    for (const auto& c : system_.contact_states({q, v, {}, t})) {
      contacts.force.push_back(c.force);
      contacts.position.push_back(c.position);
    }
    writer_.append_sample(t, positions, velocities, slopes, axial, constraint_forces, contacts);
  }

  void step(const solvers::StepRecord& r) override {
    io::StepRecord record{r.time, r.dt, r.newton_iterations, r.error, r.rejected, {}};
    if (!system_.model().contacts.empty())
      for (const auto& c :
           system_.contact_states({integrator_.q(), integrator_.v(), {}, integrator_.time()}))
        record.contact_force.push_back(c.force);
    writer_.append_step(record);
    last_dt_ = r.dt;
    driver_ = r.driver;
    const bool hook_checkpoint = hooks_.checkpoint_due();
    double now = MPI_Wtime();
    MPI_Bcast(&now, 1, MPI_DOUBLE, 0, system_.comm());
    if (hook_checkpoint || (output_.checkpoint_wall_seconds > 0.0 &&
                            now - last_checkpoint_ >= output_.checkpoint_wall_seconds)) {
      checkpoint();  // flushes too
      last_checkpoint_ = last_flush_ = now;
    } else if (now - last_flush_ >= output_.flush_wall_seconds) {
      writer_.flush();
      last_flush_ = now;
    }
    hooks_.after_step();
  }

  bool stop_requested() override { return StopSignal::requested(); }


 private:
  assembly::SecondOrderSystem& system_;
  io::TransientWriter& writer_;
  const model::OutputOptions& output_;
  const solvers::TimeIntegrator& integrator_;
  double last_flush_, last_checkpoint_;
  double last_dt_ = 0.0;
  std::optional<solvers::DriverState> driver_;  // after the last step (none before one)
  TestHooks hooks_ = TestHooks::from_environment();
};

// Not collective (rank 0). The ParaView description of the closed output (all its samples,
// those of earlier runs a restart continued included). A failure here costs the picture,
// not the results: it is reported, not thrown.
void write_xdmf(int rank, const std::string& path, const model::Model& m) {
  if (rank != 0) return;
  try {
    const std::vector<double> times = io::read_sample_times(path);
    if (!times.empty())
      io::write_transient_xdmf(path, io::transient_xdmf_path(path),
                               static_cast<std::int64_t>(m.nodes.size()),
                               static_cast<std::int64_t>(m.elements.size()), times);
  } catch (const Error& e) {
    std::fprintf(stderr, "catena: warning: no XDMF for %s: %s\n", path.c_str(), e.what());
  }
}

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
  if (rank == 0) warn_unresolved_dropper_mode(m);
  assembly::SecondOrderSystem system(comm, m);
  VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  const model::DynamicOptions& dyn = m.dynamic_options;
  std::unique_ptr<solvers::TimeIntegrator> integrator =
      solvers::make_integrator(system, dyn.integrator);
  solvers::TransientOptions options;
  options.t_end = dyn.duration;
  options.sample_interval = m.output.interval;
  options.step = solvers::make_step_control(dyn.integrator);

  std::optional<io::Checkpoint> resumed;
  if (cl.restart) {
    try {
      resumed = io::read_checkpoint(comm, m.output.file + ".chk", m, integrator->name());
    } catch (const InputError& e) {
      // `spans: auto` sizes the line from analysis.duration: a longer restart asks for a
      // longer line than the checkpoint's, which a restart cannot add.
      if (!m.catenary || !m.catenary->auto_spans ||
          !io::checkpoint_of_another_model(comm, m.output.file + ".chk", m))
        throw;
      std::ostringstream why;
      why << e.message() << "; catenary.spans: auto sized this scene's line ("
          << m.catenary->support_x.size() - 1 << " spans) for analysis.duration = "
          << dyn.duration
          << " s: a restart continues the checkpoint's line and cannot lengthen it; run "
             "afresh with the whole duration";
      throw InputError(e.where(), why.str());
    }
    if (resumed->facts.time >= dyn.duration * (1 - 1e-12))
      throw InputError({m.source_file, 0, "analysis.duration"},
                       "analysis.duration = " + std::to_string(dyn.duration) +
                           " s is not beyond the checkpoint's t = " +
                           std::to_string(resumed->facts.time) +
                           " s: nothing to continue; raise it, e.g. --set analysis.duration=" +
                           std::to_string(2 * resumed->facts.time));
    VecHandle a = system.create_vector();
    const std::vector<double> no_multipliers(3 * m.constraints.size(), 0.0);
    system.set_from_node_rows(q.get(), resumed->q, resumed->lambda);
    system.set_from_node_rows(v.get(), resumed->v, no_multipliers);
    system.set_from_node_rows(a.get(), resumed->a, no_multipliers);
    integrator->set_state(resumed->facts.time, q.get(), v.get(), a.get());
    options.resume_driver = restore_resume_state(system, *integrator, *resumed);
    options.resume = true;
    options.sample_origin = 0.0;
    if (options.step.adaptive && resumed->facts.last_dt > 0.0)
      options.step.dt = resumed->facts.last_dt;
    if (rank == 0)
      std::printf("restart: from %s.chk at t = %g s (%lld samples, %lld steps kept)\n",
                  m.output.file.c_str(), resumed->facts.time,
                  static_cast<long long>(resumed->facts.samples),
                  static_cast<long long>(resumed->facts.steps));
    if (rank == 0) print_restart_exactness(*resumed, *integrator, mpi_size(comm));
  } else {
    if (dyn.initial.from_static) {
      solvers::StaticSolver statics(system, m.static_options);
      const solvers::StaticReport report = statics.solve(q.get());
      if (rank == 0)
        std::printf(
            "initial static equilibrium: %d load steps, %d Newton iterations, |f| = %.3e N\n",
            report.n_load_steps, report.n_newton_iterations, report.residual_norm);
    }
    apply_initial_conditions(system, q.get(), v.get());
    integrator->set_state(0.0, q.get(), v.get(), nullptr);
  }
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
  std::unique_ptr<io::TransientWriter> writer;
  if (resumed)
    writer = std::make_unique<io::TransientWriter>(
        comm, m.output.file, m, system.dof_map().owned_nodes(), owned_elements,
        owned_constraints, io::ResumePoint{resumed->facts.samples, resumed->facts.steps});
  else
    writer = std::make_unique<io::TransientWriter>(comm, m.output.file, m, run_info(cl, system),
                                                   system.dof_map().owned_nodes(),
                                                   owned_elements, owned_constraints);
  OutputObserver observer(system, *writer, m.output, *integrator);
  if (resumed) {
    observer.set_last_dt(resumed->facts.last_dt);
    observer.set_driver_state(options.resume_driver);
  }
  const StopSignal signals;
  solvers::TransientReport report;
  try {
    report = solvers::run_transient(system, *integrator, options, observer);
  } catch (const NumericalError& e) {
    // The last checkpoint (if any) stays: it holds a good state to restart from.
    writer->close(std::string("failed: ") + e.what(),
                  statistics(report, integrator->counters(), MPI_Wtime() - start));
    write_xdmf(rank, m.output.file, m);
    throw;
  }
  // A checkpoint at the stop (SIGTERM: to continue; the end: to extend the run).
  observer.checkpoint();
  const double wall = MPI_Wtime() - start;
  const auto& k = integrator->counters();
  writer->close(report.interrupted ? "interrupted" : "complete", statistics(report, k, wall));
  write_xdmf(rank, m.output.file, m);
  if (rank == 0) {
    std::printf("%s at t = %g s: %ld steps (%ld rejected, dt %.3g..%.3g s), %ld Newton "
                "iterations, %ld factorisations, %ld residual evaluations, %.2f s wall "
                "(%.3g s per simulated second)\n",
                report.interrupted ? "interrupted" : "done", report.t_reached,
                report.steps_accepted, report.steps_rejected, report.smallest_dt,
                report.largest_dt, k.newton_iterations, k.factorizations,
                k.residual_evaluations, wall, wall / std::max(report.t_reached, 1e-300));
    std::printf("output: %s (%ld samples; ParaView: %s), checkpoint %s.chk\n",
                m.output.file.c_str(), report.samples,
                io::transient_xdmf_path(m.output.file).c_str(), m.output.file.c_str());
  }
  if (report.interrupted) throw RunInterrupted{StopSignal::signal_number(), report.t_reached};
}

}  // namespace catena::app

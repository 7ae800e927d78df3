// `catena run` for analysis.type: dynamic — initial state (static equilibrium or the
// reference, plus the scene's offsets and velocity), the integrator and step control the
// scene asks for, time-series HDF5 output sampled at the output interval, wall-clock
// flushes, checkpoints (atomic, <output>.chk: on the wall clock, at SIGTERM/SIGINT and at
// the end) and a clean stop on SIGTERM/SIGINT (output closed with status "interrupted").
// --restart continues from the checkpoint, appending to the output file. A failed write of
// the output or a checkpoint (agreed on every rank: catena::OutputError) closes the output
// as "failed: ..." where it can and names the checkpoint that is kept.
#include <petscsys.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/assembly/state_view.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/checkpoint.hpp"
#include "catena/io/output_error.hpp"
#include "catena/io/run_files.hpp"
#include "catena/io/transient_writer.hpp"
#include "catena/io/transient_xdmf.hpp"
#include "catena/post/contact_resolution.hpp"
#include "catena/post/contact_strikes.hpp"
#include "catena/solvers/modal/modal_integrator.hpp"
#include "catena/solvers/statics/hanging_cable_guess.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "catena/solvers/time/consistent_acceleration.hpp"
#include "catena/solvers/time/integrator_factory.hpp"
#include "catena/solvers/time/state_guard.hpp"
#include "catena/solvers/time/transient_solver.hpp"
#include "commands.hpp"
#include "contact_summary.hpp"
#include "contact_warnings.hpp"
#include "initial_state.hpp"
#include "log_stage.hpp"
#include "memory_report.hpp"
#include "modal_setup.hpp"
#include "pantograph_travel.hpp"
#include "progress_lines.hpp"
#include "realtime_monitor.hpp"
#include "resume_checkpoint.hpp"
#include "run_info.hpp"
#include "shape_report.hpp"
#include "static_phase.hpp"
#include "stop_signal.hpp"
#include "test_hooks.hpp"
#include "wall_clock_schedule.hpp"
#include "window_mover.hpp"
#include "window_statics.hpp"

namespace catena::app {
namespace {

// The checkpoint's record of how often a catenary.window had moved.
constexpr const char* kWindowMovesKey = "window.moves";

// Streams samples and step records to the output file; flushes and checkpoints on the wall
// clock (wall_clock_schedule.hpp: one decision for all ranks).
class OutputObserver : public solvers::TransientObserver {
 public:
  OutputObserver(assembly::SecondOrderSystem& system, io::TransientWriter& writer,
                 const model::OutputOptions& output, const solvers::TimeIntegrator& integrator,
                 std::string run_id, DynamicProgress progress, RealtimeMonitor& realtime)
      : system_(system),
        view_(system),
        writer_(writer),
        output_(output),
        run_id_(std::move(run_id)),
        integrator_(integrator),
        schedule_(system.comm(), {output.flush_wall_seconds, output.checkpoint_wall_seconds}),
        progress_(progress),
        realtime_(realtime),
        registration_(view_.position_rows(system.model().registration_nodes, 2)),
        travel_(system.model(), system.dof_map().owned_nodes()),
        guard_(system, system.model().dynamic_options.duration,
               system.model().dynamic_options.integrator.dt) {}

  // Collective. Flushes the output, then writes the checkpoint of the integrator's
  // current (accepted) state, recording how many output rows belong to it.
  void checkpoint() {
    const LogStage stage("Output");
    // A checkpoint holds a state a run can continue from: never one the guard refuses (the
    // driver checks only the sampled states, and steps are taken between samples).
    guard_.check(integrator_.name(), integrator_.time(), integrator_.q(), integrator_.v());
    writer_.flush();
    io::CheckpointFacts facts;
    facts.time = integrator_.time();
    facts.last_dt = last_dt_;
    facts.samples = writer_.samples_written();
    facts.steps = writer_.steps_written();
    facts.integrator = integrator_.name();
    facts.run_id = run_id_;
    facts.code_version = code_version();
    io::CheckpointShare share;
    share.nodes = system_.dof_map().owned_nodes();
    std::vector<double> unused;
    view_.owned_node_rows(integrator_.q(), share.q, share.lambda);
    view_.owned_node_rows(integrator_.v(), share.v, unused);
    view_.owned_node_rows(integrator_.a(), share.a, unused);
    std::vector<double> forces;
    view_.owned_constraint_forces(integrator_.q(), share.constraints, forces);
    share.resume = resume_rows(system_, integrator_, driver_);
    if (window_) share.resume.integers[kWindowMovesKey] = window_->moves();
    io::write_checkpoint(system_.comm(), io::checkpoint_path(output_.file), system_.model(), facts,
                         share);
    last_checkpoint_time_ = facts.time;
  }
  void set_last_dt(double dt) { last_dt_ = dt; }
  // catenary.window: samples and steps say where the window is on the line.
  void set_window(const WindowMover* window) { window_ = window; }
  void set_driver_state(const std::optional<solvers::DriverState>& d) { driver_ = d; }
  // A restarted run: the checkpoint it started from is there until it writes its own.
  void set_last_checkpoint_time(double t) { last_checkpoint_time_ = t; }
  // The time of the newest checkpoint on disk written by this run or the one it continues.
  std::optional<double> last_checkpoint_time() const { return last_checkpoint_time_; }

  void sample(double t, Vec q, Vec v) override {
    const LogStage stage("Output");
    std::vector<double> positions, slopes, velocities, unused;
    view_.owned_node_values(q, positions, slopes);
    view_.owned_node_values(v, velocities, unused);
    std::vector<int> elements;
    std::vector<elements::SectionResult> sections;
    view_.section_results({q, v, {}, t}, elements, sections);
    std::vector<double> axial;
    for (const auto& s : sections) axial.push_back(s.axial_force);
    std::vector<int> constraints;
    std::vector<double> constraint_forces;
    view_.owned_constraint_forces(q, constraints, constraint_forces);
    io::ContactSample contacts;
    for (const auto& c : view_.contact_states({q, v, {}, t})) {
      contacts.force.push_back(c.force);
      contacts.position.push_back(c.position);
    }
    // The modal model's forces are its own (its q leaves out the static correction).
    if (std::vector<double> own; integrator_.contact_forces_at(t, own)) contacts.force = own;
    travel_.move(contacts.position, positions);
    if (window_) {  // the window's positions and contact points as the line's
      for (std::size_t i = 0; i < positions.size(); i += 3) positions[i] += window_->x_offset();
      for (double& s : contacts.position) s += window_->arc_offset();
      contacts.window_moves = window_->moves();
    }
    const assembly::Reactions reactions = view_.reactions({q, v, {}, t});
    io::BodySample bodies;
    if (!system_.model().rigid_bodies.empty()) {
      assembly::BodyPoses poses = view_.body_poses(q, v);
      bodies = {std::move(poses.orientation), std::move(poses.angular_velocity),
                view_.joint_links(q)};
    }
    io::SliderSample sliders;
    if (!system_.model().sliders.empty()) {
      assembly::SliderTravel travel = view_.slider_travel(q, v);
      sliders = {std::move(travel.position), std::move(travel.speed)};
    }
    writer_.append_sample(t, positions, velocities, slopes, axial, constraint_forces, contacts,
                          {reactions.force, reactions.moment}, bodies, sliders);
    realtime_.sampled();
  }

  void step(const solvers::StepRecord& r) override {
    io::StepRecord record{r.time, r.dt, r.newton_iterations, r.error, r.rejected, {}, {}};
    if (!integrator_.contact_forces_at(integrator_.time(), record.contact_force) &&
        !system_.model().contacts.empty())
      for (const auto& c :
           view_.contact_states({integrator_.q(), integrator_.v(), {}, integrator_.time()}))
        record.contact_force.push_back(c.force);
    registration_heights(record.registration_height);
    if (window_) record.window_moves = window_->moves();
    refuse_not_finite(r, record);
    resolution_.resize(record.contact_force.size());
    strikes_.resize(record.contact_force.size());
    for (std::size_t c = 0; c < record.contact_force.size(); ++c) {
      resolution_[c].add(record.contact_force[c]);
      strikes_[c].add(record.contact_force[c]);
    }
    {
      const LogStage stage("Output");
      writer_.append_step(record);
    }
    last_dt_ = r.dt;
    driver_ = r.driver;
    // Both decisions are the same on every rank: the schedule's is rank 0's, broadcast; the
    // testing hook counts steps.
    const WallClockSchedule::Action due = schedule_.due();
    if (hooks_.checkpoint_due() || due == WallClockSchedule::Action::checkpoint) {
      checkpoint();  // flushes too
    } else if (due == WallClockSchedule::Action::flush) {
      const LogStage stage("Output");
      writer_.flush();
    }
    progress_.step(r.time, r.newton_iterations, r.rejected);
    realtime_.step(r.time);
    hooks_.after_step();
  }

  void accepted(double) override { realtime_.stepped(); }

  bool stop_requested() override { return StopSignal::requested(); }

  // Per contact (model order), how well this run's steps resolved its force.
  const std::vector<post::ContactResolution>& contact_resolution() const { return resolution_; }
  // Per contact (model order), how often it lost contact and struck the wire again.
  const std::vector<post::ContactStrikes>& contact_strikes() const { return strikes_; }

  // Collective. Between samples the guard does not see the state: a step record whose
  // contact force or registration height is not finite stops the run before it is written.
  void refuse_not_finite(const solvers::StepRecord& r, const io::StepRecord& record) const {
    const auto finite = [](const std::vector<double>& values) {
      return std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); });
    };
    const model::Model& m = system_.model();
    if (m.contacts.empty() && m.registration_nodes.empty()) return;
    const bool contact_ok = finite(record.contact_force);
    if (!any_rank(system_.comm(), !(contact_ok && finite(record.registration_height)))) return;
    std::ostringstream why;
    why << integrator_.name() << ": the ";
    if (!contact_ok) {
      const auto bad = std::find_if(record.contact_force.begin(), record.contact_force.end(),
                                    [](double x) { return !std::isfinite(x); });
      const auto c = static_cast<std::size_t>(bad - record.contact_force.begin());
      why << "contact force of pantograph '"
          << (c < m.contacts.size() ? m.contacts[c].name : std::string("?")) << "'";
    } else {
      why << "height of a registration point";
    }
    why << " is not finite at t = " << r.time << " s" << guard_.unstable_step();
    throw NumericalError(why.str());
  }

  // Collective. z of every registration node at the current state (rank 0 writes them).
  void registration_heights(std::vector<double>& heights) const {
    const std::size_t n = system_.model().registration_nodes.size();
    if (n == 0) return;
    std::vector<double> local(n, 0.0), entries;
    if (!integrator_.current_entries(registration_.row, entries)) {
      const double* q = nullptr;
      CATENA_PETSC(VecGetArrayRead(integrator_.q(), &q));
      for (const PetscInt row : registration_.row) entries.push_back(row >= 0 ? q[row] : 0.0);
      CATENA_PETSC(VecRestoreArrayRead(integrator_.q(), &q));
    }
    for (std::size_t k = 0; k < registration_.slot.size(); ++k)
      local[static_cast<std::size_t>(registration_.slot[k])] =
          registration_.row[k] >= 0 ? registration_.coefficient[k] * entries[k]
                                    : registration_.fixed[k];
    heights.assign(n, 0.0);
    MPI_Allreduce(local.data(), heights.data(), static_cast<int>(n), MPI_DOUBLE, MPI_SUM,
                  system_.comm());
  }

  // Rank 0 warns once, at the first cut; the count follows at the end of the run
  // (warn_fixed_steps_cut).
  void fixed_step_cut(const solvers::StepCut& cut) override {
    if (warned_of_cut_ || mpi_rank(system_.comm()) != 0) return;
    warned_of_cut_ = true;
    std::fprintf(stderr,
                 "catena: warning: a fixed step of %g s failed at t = %g s (%s); it is retried "
                 "at %g s, halved until Newton converges, and dt resumes after it. Steps that "
                 "keep failing cost a failed solve each: a smaller integrator.dt would avoid "
                 "the retries (the count follows at the end)\n",
                 cut.failed_dt, cut.time,
                 cut.failure.empty() ? "Newton did not converge" : cut.failure.c_str(),
                 cut.next_dt);
    std::fflush(stderr);
  }

 private:
  assembly::SecondOrderSystem& system_;
  assembly::StateView view_;
  io::TransientWriter& writer_;
  const model::OutputOptions& output_;
  std::string run_id_;
  const solvers::TimeIntegrator& integrator_;
  WallClockSchedule schedule_;
  DynamicProgress progress_;
  RealtimeMonitor& realtime_;
  // Where the registration nodes' heights lie in q (/steps/registration_height).
  assembly::StateView::ComponentRows registration_;
  PantographTravel travel_;  // where the samples draw the pantographs
  double last_dt_ = 0.0;
  std::optional<double> last_checkpoint_time_;
  bool warned_of_cut_ = false;
  std::vector<post::ContactResolution> resolution_;
  std::vector<post::ContactStrikes> strikes_;
  solvers::StateGuard guard_;                   // on the state a checkpoint saves
  std::optional<solvers::DriverState> driver_;  // after the last step (none before one)
  const WindowMover* window_ = nullptr;
  TestHooks hooks_ = TestHooks::from_environment();
};

// Not collective (rank 0). How many fixed steps Newton failures cut, if any.
void warn_fixed_steps_cut(const solvers::TransientReport& r) {
  if (r.fixed_steps_cut == 0) return;
  std::fprintf(stderr,
               "catena: warning: %ld fixed step%s cut after Newton failures; the smallest "
               "step taken was %g s; a smaller integrator.dt would avoid the retries\n",
               r.fixed_steps_cut, r.fixed_steps_cut == 1 ? " was" : "s were", r.smallest_cut_dt);
}

// Not collective (rank 0). The ParaView description of the closed output (all its samples,
// those of earlier runs a restart continued included). A failure here costs the picture,
// not the results: it is reported, not thrown.
void write_xdmf(int rank, const std::string& path, const model::Model& m) {
  if (rank != 0) return;
  try {
    const std::vector<double> times = io::read_sample_times(path);
    if (times.empty()) return;
    const auto n_nodes = static_cast<std::int64_t>(m.nodes.size());
    const auto n_elements = static_cast<std::int64_t>(m.elements.size());
    io::write_transient_xdmf(path, io::transient_xdmf_path(path), n_nodes, n_elements, times,
                             io::XdmfReaders::xdmf3);
    io::write_transient_xdmf(path, io::transient_xdmf2_path(path), n_nodes, n_elements, times,
                             io::XdmfReaders::xdmf2);
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
          {"fixed_steps_cut", static_cast<double>(r.fixed_steps_cut)},
          {"smallest_cut_dt", r.smallest_cut_dt},
          {"wall_seconds", wall}};
}

// Collective. The time-series file a restart continues: the partial output if it belongs
// to the checkpoint's run, else (extending a completed run) a copy of the complete output
// made under the partial name, so that the complete file stays intact until the extended
// run completes. Throws InputError if neither belongs to the checkpoint.
std::string output_to_continue(MPI_Comm comm, const std::string& output,
                               const std::string& run_id) {
  const std::string partial = io::partial_output_path(output);
  std::string why;
  if (mpi_rank(comm) == 0) {
    const std::string partial_id = io::read_run_id(partial);
    if (partial_id != run_id) {
      const std::string complete_id = io::read_run_id(output);
      if (complete_id == run_id) {
        std::printf("restart: extending the completed run: copying %s to %s\n", output.c_str(),
                    partial.c_str());
        std::fflush(stdout);
        std::error_code ec;
        std::filesystem::copy_file(output, partial,
                                   std::filesystem::copy_options::overwrite_existing, ec);
        if (ec) why = "cannot copy " + output + " to " + partial + ": " + ec.message();
      } else {
        const auto described = [&](const std::string& path, const std::string& id) {
          return path +
                 (id.empty() ? " (missing, or no Catena time series)" : " (of run " + id + ")");
        };
        why = "the checkpoint belongs to run " + run_id + ", whose output is gone: neither " +
              described(partial, partial_id) + " nor " + described(output, complete_id) +
              " is its time series (a later run with the same output name replaced it); run "
              "afresh (without --restart)";
      }
    }
  }
  broadcast_string(comm, why, 0);
  if (!why.empty())
    throw InputError({io::checkpoint_path(output), 0, ""},
                     "cannot restart from this checkpoint: " + why);
  return partial;
}

// Collective. A completed run's time series takes the output's name (rank 0 renames it,
// replacing any earlier result atomically); a partial output's ParaView file goes with it.
void publish_completed_output(MPI_Comm comm, const std::string& partial,
                              const std::string& output) {
  std::string why;
  if (mpi_rank(comm) == 0) {
    if (std::rename(partial.c_str(), output.c_str()) != 0)
      why = "cannot rename " + partial + " to " + output + ": " + std::strerror(errno);
    std::error_code ignored;
    std::filesystem::remove(io::transient_xdmf_path(partial), ignored);
    std::filesystem::remove(io::transient_xdmf2_path(partial), ignored);
  }
  broadcast_string(comm, why, 0);
  if (!why.empty()) throw Error(why);
}

// Collective. The error to report after writing the output or a checkpoint failed
// (`failure`, thrown on every rank alike). Unless `failure` came from closing the output,
// the output is closed with status "failed: ..." if it still can be. The message says what
// became of the output and which checkpoint is kept.
OutputError output_failure(const OutputError& failure, bool failed_closing,
                           io::TransientWriter& writer, const std::string& written,
                           const std::string& checkpoint_file,
                           std::optional<double> checkpoint_time,
                           const std::vector<std::pair<std::string, double>>& statistics) {
  std::string message = failure.what();
  if (!failed_closing) {
    try {
      writer.close(std::string("failed: ") + failure.what(), statistics);
      message += "; " + written + " is closed with status \"failed\"";
    } catch (const OutputError& close_failure) {
      message += std::string("; ") + close_failure.what();
      failed_closing = true;
    }
  }
  if (failed_closing) message += "; its status may still say \"running\"";
  std::ostringstream checkpoint;
  if (checkpoint_time)
    checkpoint << "; the last checkpoint, " << checkpoint_file << " at t = " << *checkpoint_time
               << " s, is kept: continue with --restart once the output can be written";
  else
    checkpoint << "; no checkpoint had been written";
  return OutputError(message + checkpoint.str());
}

// Collective. The static equilibrium a dynamic run starts from (or linearises about), into
// q (the reference state on entry), with its summary line.
void solve_initial_statics(assembly::SecondOrderSystem& system, Vec q, const CommandLine& cl,
                           int rank) {
  const bool sliders = !system.model().sliders.empty();
  const bool ends = !system.model().absorbing_ends.empty();
  const solvers::StaticReport report =
      sliders || ends ? solve_statics_holding(system, q, cl) : solve_statics(system, q, cl);
  if (rank != 0) return;
  if (sliders)
    std::printf("initial static equilibrium: each slider held at its start, released at t = 0\n");
  if (ends)
    std::printf(
        "initial static equilibrium: each absorbing end held where it is, released at t = 0\n");
  std::printf("initial static equilibrium: %d load steps, %d Newton iterations, |f| = %.3e N\n",
              report.n_load_steps, report.n_newton_iterations, report.residual_norm);
  if (const std::string guess = solvers::describe_guess(report.guess); !guess.empty())
    std::printf("%s\n", guess.c_str());
}

// Collective. The absorbing ends' laws from the run's initial state q0 (before initial
// displacements and velocities), with a line saying what they are.
void calibrate_absorbing_ends(assembly::SecondOrderSystem& system, Vec q0, int rank) {
  const model::Model& m = system.model();
  if (m.absorbing_ends.empty()) return;
  system.calibrate_absorbing_ends(q0);
  if (rank == 0)
    std::printf(
        "absorbing ends: %zu line ends pulled by their force at the start, with dashpots of "
        "their lines' wave impedances\n",
        m.absorbing_ends.size());
}

// Collective. analysis.structure: linear — every cable and beam element except the
// tension-only ones (cable droppers, which must still go slack) linearised about q0.
void linearize_structure(assembly::SecondOrderSystem& system, Vec q0, int rank) {
  const model::Model& m = system.model();
  const auto linear = [&](int e) {
    const model::ElementProps& props = *m.elements[static_cast<std::size_t>(e)].props;
    if (const auto* cable = std::get_if<model::CableProps>(&props)) return !cable->tension_only;
    return std::holds_alternative<model::BeamProps>(props);
  };
  int n = system.linearize_elements(q0, linear);
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_INT, MPI_SUM, system.comm());
  if (rank == 0)
    std::printf(
        "structure: linear about the static equilibrium: %d cable and beam elements linearised "
        "(constant stiffness and damping); bars, springs, masses, tension-only cables and "
        "contacts as they are\n",
        n);
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
  const bool modal = dyn.structure == model::StructureModel::modal;
  std::unique_ptr<solvers::TimeIntegrator> integrator =
      modal ? nullptr : solvers::make_integrator(system, dyn.integrator);
  solvers::TransientOptions options;
  options.t_end = dyn.duration;
  options.sample_interval = m.output.interval;
  options.step = solvers::make_step_control(dyn.integrator);

  // The modal model is built about the static equilibrium before anything asks the
  // integrator's name (a checkpoint of another model, or of other modes, is refused).
  VecHandle modal_q0;
  if (modal) {
    modal_q0 = system.create_vector();
    system.reference_state(modal_q0.get());
    solve_initial_statics(system, modal_q0.get(), cl, rank);
    integrator = make_modal_integrator(system, modal_q0.get(), rank);
    if (rank == 0) {
      std::printf(
          "note: the modal model steps its modes and pantographs exactly; integrator.type "
          "'%s' and its method settings are not used, integrator.dt and the step control "
          "are\n",
          dyn.integrator.type.c_str());
      std::fflush(stdout);
    }
  }

  // catenary.window: the state moves back a span as the pantographs cross one.
  const bool windowed = m.catenary && m.catenary->window;
  std::unique_ptr<WindowMover> window;
  std::optional<io::Checkpoint> resumed;
  if (cl.restart) {
    try {
      resumed =
          io::read_checkpoint(comm, io::checkpoint_path(m.output.file), m, integrator->name());
    } catch (const InputError& e) {
      // `spans: auto` sizes the line from analysis.duration: a longer restart asks for a
      // longer line than the checkpoint's, which a restart cannot add.
      if (!m.catenary || !m.catenary->auto_spans ||
          !io::checkpoint_of_another_model(comm, io::checkpoint_path(m.output.file), m))
        throw;
      std::ostringstream why;
      why << e.message() << "; catenary.spans: auto sized this scene's line ("
          << m.catenary->support_x.size() - 1 << " spans) for analysis.duration = " << dyn.duration
          << " s: a restart continues the checkpoint's line and cannot lengthen it; run "
             "afresh with the whole duration";
      throw InputError(e.where(), why.str());
    }
    if (resumed->facts.time >= dyn.duration * (1 - 1e-12))
      throw InputError(
          {m.source_file, 0, "analysis.duration"},
          "analysis.duration = " + std::to_string(dyn.duration) +
              " s is not beyond the checkpoint's t = " + std::to_string(resumed->facts.time) +
              " s: nothing to continue; raise it, e.g. --set analysis.duration=" +
              std::to_string(2 * resumed->facts.time));
    const bool linear = dyn.structure == model::StructureModel::linear;
    if (linear || !m.absorbing_ends.empty()) {
      // The linearisation point, the absorbing ends' laws and the state a window's entering
      // spans take come from the run's initial state (the static equilibrium, which a
      // linear structure needs), which the checkpoint does not hold: solved again (the same
      // scene gives the same state).
      VecHandle q0 = system.create_vector();
      system.reference_state(q0.get());
      if (windowed) {
        window = start_window(system, q0.get(), cl);
        const auto moves = resumed->resume.integers.find(kWindowMovesKey);
        window->restore(moves == resumed->resume.integers.end() ? 0 : moves->second);
      } else if (dyn.initial.from_static) {
        solve_initial_statics(system, q0.get(), cl, rank);
      }
      if (linear) linearize_structure(system, q0.get(), rank);
      calibrate_absorbing_ends(system, q0.get(), rank);
    }
    VecHandle a = system.create_vector();
    const std::vector<double> no_multipliers(
        static_cast<std::size_t>(model::multiplier_width(m)) * m.constraints.size(), 0.0);
    const assembly::StateView view(system);
    view.set_from_node_rows(q.get(), resumed->q, resumed->lambda);
    view.set_from_node_rows(v.get(), resumed->v, no_multipliers);
    view.set_from_node_rows(a.get(), resumed->a, no_multipliers);
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
    if (modal_q0) {
      CATENA_PETSC(VecCopy(modal_q0.get(), q.get()));
    } else if (windowed) {
      window = start_window(system, q.get(), cl);
      if (dyn.structure == model::StructureModel::linear)
        linearize_structure(system, q.get(), rank);
    } else if (dyn.initial.from_static) {
      solve_initial_statics(system, q.get(), cl, rank);
      if (dyn.structure == model::StructureModel::linear)
        linearize_structure(system, q.get(), rank);
    }
    calibrate_absorbing_ends(system, q.get(), rank);
    apply_initial_conditions(system, q.get(), v.get());
    // Velocities that pull joined parts apart (a crank's speed given alone) would be an
    // impulse in the first step; projected here instead, and said.
    PetscReal speed = 0.0;
    CATENA_PETSC(VecNorm(v.get(), NORM_INFINITY, &speed));
    if (const double change = solvers::project_initial_velocity(system, 0.0, q.get(), v.get());
        change > 1e-9 * speed + 1e-12 && rank == 0)
      std::printf(
          "initial velocity: projected onto the constraints (largest change %g of %g): the "
          "scene's velocities broke them (joined parts moving apart, or a bilateral contact's "
          "head not following the wire's slope); they start with the least change in kinetic "
          "energy that keeps them (docs/scene.md, 'bodies')\n",
          change, speed);
    integrator->set_state(0.0, q.get(), v.get(), nullptr);
  }
  if (rank == 0) {
    std::printf("dynamics: %s, %s step %g s, %g s simulated, %lld free DOFs on %d ranks\n",
                integrator->name().c_str(), options.step.adaptive ? "adaptive, first" : "fixed",
                options.step.dt, options.t_end, static_cast<long long>(system.dof_map().n_global()),
                mpi_size(comm));
    if (const double stable = integrator->stable_step(); std::isfinite(stable))
      std::printf("stability limit: steps up to %g s (%s)\n", stable,
                  options.step.adaptive ? "adaptive steps are capped there"
                                        : "a longer fixed step is refused");
    if (options.step.adaptive && options.step.dt > options.t_end)
      std::printf(
          "note: the first step integrator.dt = %g s is longer than analysis.duration "
          "= %g s; it is cut to the duration\n",
          options.step.dt, options.t_end);
    std::fflush(stdout);
  }

  std::vector<int> owned_elements;
  {
    std::vector<elements::SectionResult> unused;
    assembly::StateView(system).section_results({q.get(), v.get(), {}, 0.0}, owned_elements,
                                                unused);
  }
  std::vector<int> owned_constraints;
  {
    std::vector<double> unused;
    assembly::StateView(system).owned_constraint_forces(q.get(), owned_constraints, unused);
  }
  // The time series is written under the partial name until the run completes
  // (run_files.hpp), so a failed or interrupted run never replaces a complete result.
  const std::string& output = m.output.file;
  std::string run_id;
  std::unique_ptr<io::TransientWriter> writer;
  if (resumed) {
    run_id = resumed->facts.run_id;
    if (rank == 0 && resumed->facts.code_version != code_version())
      std::printf(
          "restart: note: the checkpoint was written by Catena %s, this is %s; the "
          "continued run may differ from an uninterrupted one by more than round-off\n",
          resumed->facts.code_version.c_str(), code_version().c_str());
    writer = std::make_unique<io::TransientWriter>(
        comm, output_to_continue(comm, output, run_id), m, system.dof_map().owned_nodes(),
        owned_elements, owned_constraints,
        io::ResumePoint{resumed->facts.samples, resumed->facts.steps});
  } else {
    run_id = io::new_run_id(comm);
    io::RunInfo info = run_info(cl, system);
    info.run_id = run_id;
    writer = std::make_unique<io::TransientWriter>(comm, io::partial_output_path(output), m, info,
                                                   system.dof_map().owned_nodes(), owned_elements,
                                                   owned_constraints);
  }
  const std::string partial = io::partial_output_path(output);
  RealtimeMonitor realtime(rank, cl.realtime, integrator->time(), m.output.interval);
  OutputObserver observer(
      system, *writer, m.output, *integrator, run_id,
      DynamicProgress(rank, integrator->time(), options.t_end, cl.progress_seconds), realtime);
  observer.set_window(window.get());
  options.boundary = window.get();
  if (resumed) {
    observer.set_last_dt(resumed->facts.last_dt);
    observer.set_last_checkpoint_time(resumed->facts.time);
    observer.set_driver_state(options.resume_driver);
  }
  const StopSignal signals;
  solvers::TransientReport report;
  // The time stepping's own wall time (with its output), apart from the set-up before it
  // (shape finding, statics, a modal model's modes), which the time per simulated second
  // would otherwise mix in.
  const double stepping_start = MPI_Wtime(), t_begin = integrator->time();
  try {
    const LogStage stage("Dynamics");
    report = solvers::run_transient(system, *integrator, options, observer);
    // A checkpoint at the stop (SIGTERM: to continue; the end: to extend the run).
    observer.checkpoint();
  } catch (const NumericalError& e) {
    // The last checkpoint (if any) stays: it holds a good state to restart from.
    try {
      writer->close(std::string("failed: ") + e.what(),
                    statistics(report, integrator->counters(), MPI_Wtime() - start));
    } catch (const OutputError& close_failure) {
      throw output_failure(OutputError(std::string(close_failure.what()) +
                                       " (recording the numerical failure: " + e.what() + ")"),
                           true, *writer, partial, io::checkpoint_path(output),
                           observer.last_checkpoint_time(), {});
    }
    write_xdmf(rank, partial, m);
    if (rank == 0)
      std::fprintf(stderr, "catena: the failed run's output is %s%s\n", partial.c_str(),
                   std::filesystem::exists(output)
                       ? (" (" + output + " is an earlier run's, kept)").c_str()
                       : "");
    throw;
  } catch (const OutputError& e) {
    throw output_failure(e, false, *writer, partial, io::checkpoint_path(output),
                         observer.last_checkpoint_time(),
                         statistics(report, integrator->counters(), MPI_Wtime() - start));
  }
  const double wall = MPI_Wtime() - start, stepping = MPI_Wtime() - stepping_start;
  const auto& k = integrator->counters();
  const LogStage output_stage("Output");
  std::vector<std::pair<std::string, double>> run_statistics = statistics(report, k, wall);
  // The time stepping alone (wall_seconds also holds the initial state and a modal model's
  // build), over the simulated time this process stepped: what `catena study` compares.
  run_statistics.emplace_back("stepping_wall_seconds", stepping);
  run_statistics.emplace_back("t_started", t_begin);
  // Since the process started (a restart's own set-up included).
  const PeakMemory memory = peak_memory(comm);
  run_statistics.emplace_back("peak_memory_bytes_largest_rank", memory.largest_bytes);
  run_statistics.emplace_back("peak_memory_bytes_total", memory.total_bytes);
  if (!observer.contact_resolution().empty()) {
    double roughest = 0.0;
    for (const post::ContactResolution& r : observer.contact_resolution())
      roughest = std::max(roughest, r.roughness());
    run_statistics.emplace_back("contact_force_roughness", roughest);
    std::size_t most = 0;  // over the penalty contacts (a bilateral one cannot strike)
    const std::vector<post::ContactStrikes>& strikes = observer.contact_strikes();
    for (std::size_t c = 0; c < strikes.size() && c < m.contacts.size(); ++c)
      if (!m.contacts[c].bilateral) most = std::max(most, strikes[c].strikes());
    run_statistics.emplace_back("contact_strikes", static_cast<double>(most));
  }
  std::optional<RealtimeSummary> realtime_summary;
  if (realtime.enabled()) {
    realtime_summary = realtime.summary(comm);
    for (auto& entry : RealtimeMonitor::statistics(*realtime_summary))
      run_statistics.push_back(std::move(entry));
  }
  try {
    writer->close(report.interrupted ? "interrupted" : "complete", run_statistics);
  } catch (const OutputError& e) {
    throw output_failure(e, true, *writer, partial, io::checkpoint_path(output),
                         observer.last_checkpoint_time(), {});
  }
  const std::string& written = report.interrupted ? partial : output;
  if (!report.interrupted) publish_completed_output(comm, partial, output);
  write_xdmf(rank, written, m);
  if (rank == 0) {
    warn_fixed_steps_cut(report);
    warn_unresolved_contact(m, observer.contact_resolution());
    warn_repeated_strikes(m, observer.contact_strikes());
    std::printf(
        "%s at t = %g s: %ld steps (%ld rejected, dt %.3g..%.3g s), %ld Newton "
        "iterations, %ld factorisations, %ld residual evaluations, %.2f s wall, of which "
        "the time stepping and its output %.2f s (%.3g s per simulated second)\n",
        report.interrupted ? "interrupted" : "done", report.t_reached, report.steps_accepted,
        report.steps_rejected, report.smallest_dt, report.largest_dt, k.newton_iterations,
        k.factorizations, k.residual_evaluations, wall, stepping,
        stepping / std::max(report.t_reached - t_begin, 1e-300));
    print_peak_memory(rank, memory, mpi_size(comm));
    if (const auto* modal_run = dynamic_cast<const solvers::ModalIntegrator*>(integrator.get()))
      std::printf(
          "modal model: the field rebuilt from the modes %ld times (field samples, "
          "checkpoints; the steps need none)\n",
          modal_run->field_rebuilds());
    if (realtime_summary) RealtimeMonitor::print(rank, *realtime_summary, m.output.interval);
    std::printf(
        "output: %s (%ld samples; ParaView: %s, or %s with the displacements), "
        "checkpoint %s%s\n",
        written.c_str(), report.samples, io::transient_xdmf_path(written).c_str(),
        io::transient_xdmf2_path(written).c_str(), io::checkpoint_path(output).c_str(),
        report.interrupted ? "; --restart continues the run" : "");
    if (!m.contacts.empty() && !report.interrupted) print_contact_summary(written);
  }
  if (report.interrupted) {
    // The signal one rank received, on every rank (the stop itself was agreed per step).
    int signal = StopSignal::signal_number(), any = 0;
    MPI_Allreduce(&signal, &any, 1, MPI_INT, MPI_MAX, comm);
    throw RunInterrupted{any, report.t_reached};
  }
}

}  // namespace catena::app

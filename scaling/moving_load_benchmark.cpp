// Dynamics benchmark: the 10 km pre-tensioned line of static_line_benchmark (0.25 m ANCF
// cable elements, 20 kN, elastic supports every 62.5 m, gravity) as a dynamic scene with a
// moving load (120 N upward at 80 m/s, starting at the middle span's mid-point), built from
// generated scene text through the real scene reader and run as `catena run` runs it:
// static equilibrium, initial state, make_integrator, run_transient with fixed steps.
// After `-steps` steps it reports, per step, Newton iterations, residual evaluations,
// tangent assemblies, factorisations and triangular-solve pairs (IntegratorCounters), the
// time spent in each (PETSc log events CatForce, CatTangent, MatLUFactorNum, MatSolve),
// and the ratio
//     (average step time) / (t_residual + t_solve_pair)
// with t_residual one system.force and t_solve_pair one KSPSolve (forward + backward) of
// the factored n × n HHT Newton matrix M + (1+α)(γh C + βh² K), both measured separately.
// Target of the issue: ≤ 3 for HHT with Jacobian reuse. Averages leave out the first step
// (symbolic analysis and first factorisation), reported on its own.
//
//   mpirun -n 1 build/scaling/moving_load_benchmark
//   mpirun -n 2 build/scaling/moving_load_benchmark -integrator radau -steps 40 -dt 1e-3
//   mpirun -n 2 build/scaling/moving_load_benchmark -integrator hht -alpha 0 -newton full
//   mpirun -n 1 build/scaling/moving_load_benchmark -integrator radau -linear_algebra coupled
// Factorisation and solve times per step are the MatLUFactorNum and MatSolve events; "ms
// each" divides them by the counters (one stage-system factorisation or solve, which the
// decoupled IRK does as one MUMPS factorisation or solve per block).
// Options: -length m (10000) -element m (0.25) -force N (120) -speed m/s (80) -start m
// (middle span's mid-point) -load_spacing m (0: one load; else a load every so many m, the
// weak-scaling study's "one train per N km") -steps n (100) -dt s (1e-3) -integrator hht|radau
// (hht) -alpha (-0.1, hht) -newton simplified|full (simplified) -newton_rtol (1e-10) -newton_atol N
// (1e-8; the round-off floor is added, see Options) -repeat n (20, unit costs) -linear_algebra
// auto|decoupled|coupled (auto; radau's stage solve, docs/integrators.md); PETSc options with the
// integrators' prefixes (-hht_, -irk_) apply as in `catena run`. Accuracy of a setting (e.g. a
// looser -newton_rtol, or -dt halved with -steps doubled): -save_state FILE writes the final state
// (PETSc binary), -compare_state FILE prints the largest difference from a state saved by a run on
// as many ranks.
#include <petscksp.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "benchmark_errors.hpp"
#include "catena/assembly/petsc_call.hpp"
#include "catena/assembly/second_order_system.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/core/peak_memory.hpp"
#include "catena/model/scene_reader.hpp"
#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/newton/interface_schur.hpp"
#include "catena/solvers/statics/static_solver.hpp"
#include "catena/solvers/time/integrator_factory.hpp"
#include "catena/solvers/time/irk/irk_integrator.hpp"
#include "catena/solvers/time/transient_solver.hpp"

namespace {

struct Options {
  double length = 10000.0, element = 0.25, span = 62.5;  // m
  double force = 120.0, speed = 80.0, start = -1.0;      // N (upward), m/s, m (<0: default)
  // > 0: a load every `load_spacing` m instead of one (weak scaling: the line and its
  // trains grow together), the first at half the spacing.
  double load_spacing = 0.0;
  int steps = 100, repeat = 20;
  double dt = 1e-3, alpha = -0.1;  // s, HHT α
  // Newton tolerances (scene keys integrator.newton_rtol, newton_atol), the scene's
  // defaults. The integrators add the residual's round-off floor 2ε‖diag(K)∘q‖ to them
  // (round_off_floor.hpp): on this line, positions of up to 1e4 m differenced over 0.25 m
  // elements leave |f| ≈ 0.027 N, far above 1e-8 N.
  double newton_rtol = 1e-10, newton_atol = 1e-8;
  std::string integrator = "hht", newton = "simplified", linear_algebra = "auto";
  std::string save_state, compare_state;  // PETSc binary files ("" = none)
};

std::string option_text(const char* name, const std::string& fallback) {
  char value[64] = {};
  PetscBool set = PETSC_FALSE;
  CATENA_PETSC(PetscOptionsGetString(nullptr, nullptr, name, value, sizeof value, &set));
  return set ? std::string(value) : fallback;
}

Options read_options() {
  Options o;
  PetscInt steps = o.steps, repeat = o.repeat;
  for (auto [name, value] : {std::pair{"-length", &o.length},
                             {"-element", &o.element},
                             {"-force", &o.force},
                             {"-speed", &o.speed},
                             {"-start", &o.start},
                             {"-load_spacing", &o.load_spacing},
                             {"-dt", &o.dt},
                             {"-alpha", &o.alpha},
                             {"-newton_rtol", &o.newton_rtol},
                             {"-newton_atol", &o.newton_atol}})
    CATENA_PETSC(PetscOptionsGetReal(nullptr, nullptr, name, value, nullptr));
  CATENA_PETSC(PetscOptionsGetInt(nullptr, nullptr, "-steps", &steps, nullptr));
  CATENA_PETSC(PetscOptionsGetInt(nullptr, nullptr, "-repeat", &repeat, nullptr));
  o.steps = static_cast<int>(std::max<PetscInt>(steps, 2));
  o.repeat = static_cast<int>(std::max<PetscInt>(repeat, 1));
  o.integrator = option_text("-integrator", o.integrator);
  o.newton = option_text("-newton", o.newton);
  o.linear_algebra = option_text("-linear_algebra", o.linear_algebra);
  o.save_state = option_text("-save_state", "");
  o.compare_state = option_text("-compare_state", "");
  const int n_spans = static_cast<int>(o.length / o.span + 0.5);
  if (o.start < 0.0) o.start = (n_spans / 2 + 0.5) * o.span;
  return o;
}

// What is wrong with the options ("" if nothing): the scene text is generated from them, so
// a bad value would otherwise surface as an error about a line of text the user never saw.
std::string option_error(const Options& o) {
  const auto number = [](double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  };
  if (!(o.length >= o.span))
    return "-length " + number(o.length) + ": at least one span, " + number(o.span) + " m";
  if (!(o.element > 0.0 && o.element <= o.span))
    return "-element " + number(o.element) + ": a length in (0, " + number(o.span) + "] m";
  if (!(o.dt > 0.0)) return "-dt " + number(o.dt) + ": a positive time step, s";
  if (!(o.load_spacing >= 0.0))
    return "-load_spacing " + number(o.load_spacing) + ": 0 (one load) or a positive length, m";
  return "";
}

// Where the loads start: one at o.start, or one every o.load_spacing m (at least one).
std::vector<double> load_starts(const Options& o) {
  if (o.load_spacing <= 0.0) return {o.start};
  std::vector<double> starts;
  for (double x = 0.5 * o.load_spacing; x < o.length; x += o.load_spacing) starts.push_back(x);
  if (starts.empty()) starts.push_back(o.start);  // a line shorter than half the spacing
  return starts;
}

// The static benchmark's line, with named spans, a dynamic analysis, the moving load along
// every span and the integrator settings.
std::string line_scene(const Options& o) {
  const int n_spans = static_cast<int>(o.length / o.span + 0.5);
  const int per_span = static_cast<int>(o.span / o.element + 0.5);
  std::ostringstream s;
  s.precision(12);
  s << "name: moving load benchmark " << o.length << " m\n"
    << "sections:\n  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}\n"
    << "nodes:\n";
  for (int i = 0; i <= n_spans; ++i)
    s << "  - {id: " << i + 1 << ", position: [" << i * o.span << ", 0, 0]}\n";
  s << "lines:\n";
  for (int i = 0; i < n_spans; ++i)
    s << "  - {name: s" << i + 1 << ", from: " << i + 1 << ", to: " << i + 2
      << ", elements: " << per_span << ", section: cw, tension: 20000}\n";
  s << "supports:\n  - {node: 1, fix: pinned}\n  - {node: " << n_spans + 1 << ", fix: pinned}\n"
    << "elastic_supports:\n";
  for (int i = 1; i < n_spans; ++i)
    s << "  - {node: " << i + 1 << ", stiffness: [0, 1.0e5, 1.0e5]}\n";
  // run_transient stops after `steps` steps (the observer asks); the duration only bounds it.
  s << "analysis: {type: dynamic, duration: " << (o.steps + 10) * o.dt << "}\n"
    << "moving_loads:\n";
  const std::vector<double> starts = load_starts(o);
  for (std::size_t k = 0; k < starts.size(); ++k) {
    s << "  - name: load" << k + 1 << "\n    line: [";
    for (int i = 0; i < n_spans; ++i) s << (i ? ", s" : "s") << i + 1;
    s << "]\n    force: [0, 0, " << o.force << "]\n    speed: " << o.speed
      << "\n    start: " << starts[k] << "\n";
  }
  s << "integrator: {type: " << o.integrator << (o.integrator == "hht" ? ", alpha: " : ", stages: ")
    << (o.integrator == "hht" ? o.alpha : 3.0) << ", dt: " << o.dt << ", newton: " << o.newton
    << ", newton_rtol: " << o.newton_rtol << ", newton_atol: " << o.newton_atol
    << (o.integrator == "hht" ? "" : ", linear_algebra: " + o.linear_algebra) << "}\n";
  return s.str();
}

double timed(MPI_Comm comm, const std::function<void()>& fn) {
  MPI_Barrier(comm);
  const double t0 = MPI_Wtime();
  fn();
  MPI_Barrier(comm);
  return MPI_Wtime() - t0;
}

// A PETSc log event in one stage: calls and seconds (slowest rank).
struct EventTotals {
  double count = 0.0, seconds = 0.0;
};

EventTotals event_totals(MPI_Comm comm, PetscLogStage stage, const char* name) {
  PetscLogEvent event = 0;
  CATENA_PETSC(PetscLogEventGetId(name, &event));
  if (event < 0) return {0.0, 0.0};  // never registered: the run had no such event
  PetscEventPerfInfo info{};
  CATENA_PETSC(PetscLogEventGetPerfInfo(stage, event, &info));
  double local[2] = {static_cast<double>(info.count), info.time}, global[2] = {0.0, 0.0};
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, comm);
  return {global[0], global[1]};
}

// The messages, bytes and reductions one rank took part in during a log stage, as PETSc
// counts them (point-to-point sends and receives; reductions, broadcasts and gathers of
// code that includes PETSc's headers, Catena's own among them), largest over the ranks.
struct Traffic {
  double messages = 0.0, bytes = 0.0, reductions = 0.0, flops = 0.0;
};

Traffic stage_traffic(MPI_Comm comm, PetscLogStage stage) {
  PetscStageLog log = nullptr;
  CATENA_PETSC(PetscLogGetStageLog(&log));
  const PetscEventPerfInfo& info = log->stageInfo[stage].perfInfo;
  double local[4] = {info.numMessages, info.messageLength, info.numReductions, info.flops};
  double largest[4] = {};
  MPI_Allreduce(local, largest, 4, MPI_DOUBLE, MPI_MAX, comm);
  return {largest[0], largest[1], largest[2], largest[3]};
}

// Times every accepted step, moves logging to the "Steps" stage after the first one,
// keeps the counters after it, and stops the run after `steps` steps.
class StepTimer : public catena::solvers::TransientObserver {
 public:
  StepTimer(const catena::solvers::TimeIntegrator& integrator, int steps, PetscLogStage later)
      : integrator_(integrator), steps_(steps), later_(later), last_(MPI_Wtime()) {}

  void sample(double, Vec, Vec) override {}
  void step(const catena::solvers::StepRecord&) override {
    const double now = MPI_Wtime();
    seconds.push_back(now - last_);
    last_ = now;
    if (seconds.size() == 1) {
      after_first = integrator_.counters();
      CATENA_PETSC(PetscLogStagePush(later_));
    }
  }
  bool stop_requested() override { return static_cast<int>(seconds.size()) >= steps_; }

  std::vector<double> seconds;  // wall time of each accepted step
  catena::solvers::IntegratorCounters after_first;

 private:
  const catena::solvers::TimeIntegrator& integrator_;
  int steps_;
  PetscLogStage later_;
  double last_;
};

}  // namespace

int run_benchmark() {
  CATENA_PETSC(PetscLogDefaultBegin());
  const double process_start = MPI_Wtime();
  MPI_Comm comm = PETSC_COMM_WORLD;
  const int rank = catena::mpi_rank(comm), size = catena::mpi_size(comm);
  const Options o = read_options();
  if (o.integrator != "hht" && o.integrator != "radau") {
    if (rank == 0)
      std::fprintf(stderr, "-integrator %s: expected hht or radau\n", o.integrator.c_str());
    return 2;
  }
  if (const std::string error = option_error(o); !error.empty()) {
    if (rank == 0) std::fprintf(stderr, "moving_load_benchmark: %s\n", error.c_str());
    return 2;
  }
  PetscLogStage setup_stage = 0, first_stage = 0, steps_stage = 0, unit_stage = 0;
  CATENA_PETSC(PetscLogStageRegister("Setup", &setup_stage));
  CATENA_PETSC(PetscLogStageRegister("FirstStep", &first_stage));
  CATENA_PETSC(PetscLogStageRegister("Steps", &steps_stage));
  CATENA_PETSC(PetscLogStageRegister("UnitCosts", &unit_stage));

  CATENA_PETSC(PetscLogStagePush(setup_stage));
  const catena::model::Model model = catena::model::parse_scene(line_scene(o), "benchmark");
  catena::assembly::SecondOrderSystem system(comm, model);
  catena::VecHandle q = system.create_vector(), v = system.create_vector();
  system.reference_state(q.get());
  // The high-water marks by phase: which phase sets the run's peak memory per rank.
  const catena::PeakMemory memory_system = catena::peak_memory(comm);
  catena::solvers::StaticReport statics;
  const double t_static = timed(comm, [&] {
    catena::solvers::StaticSolver solver(system, model.static_options);
    statics = solver.solve(q.get());
  });
  const catena::PeakMemory memory_statics = catena::peak_memory(comm);
  CATENA_PETSC(VecSet(v.get(), 0.0));  // the scene has no initial offsets or velocity
  const catena::model::IntegratorOptions& io = model.dynamic_options.integrator;
  std::unique_ptr<catena::solvers::TimeIntegrator> integrator =
      catena::solvers::make_integrator(system, io);
  const double t_set_state =
      timed(comm, [&] { integrator->set_state(0.0, q.get(), v.get(), nullptr); });
  CATENA_PETSC(PetscLogStagePop());

  catena::solvers::TransientOptions run;
  run.t_end = model.dynamic_options.duration;
  run.sample_interval = run.t_end;
  run.step = catena::solvers::make_step_control(io);
  StepTimer timer(*integrator, o.steps, steps_stage);
  CATENA_PETSC(PetscLogStagePush(first_stage));
  const catena::solvers::TransientReport report =
      catena::solvers::run_transient(system, *integrator, run, timer);
  CATENA_PETSC(PetscLogStagePop());  // Steps
  CATENA_PETSC(PetscLogStagePop());  // FirstStep
  // The whole run as `catena run` would do it without output: scene, statics, steps.
  double whole_run = MPI_Wtime() - process_start;
  MPI_Allreduce(MPI_IN_PLACE, &whole_run, 1, MPI_DOUBLE, MPI_MAX, comm);
  const catena::PeakMemory memory = catena::peak_memory(comm);
  const Traffic traffic = stage_traffic(comm, steps_stage);
  const catena::solvers::IntegratorCounters total = integrator->counters();

  // The final state against a saved one, and against the static state (the motion's size).
  double state_difference = -1.0, motion = 0.0;
  {
    catena::VecHandle d = system.create_vector();
    CATENA_PETSC(VecWAXPY(d.get(), -1.0, q.get(), integrator->q()));
    CATENA_PETSC(VecNorm(d.get(), NORM_INFINITY, &motion));
    if (!o.save_state.empty()) {
      PetscViewer viewer = nullptr;
      CATENA_PETSC(PetscViewerBinaryOpen(comm, o.save_state.c_str(), FILE_MODE_WRITE, &viewer));
      CATENA_PETSC(VecView(integrator->q(), viewer));
      CATENA_PETSC(PetscViewerDestroy(&viewer));
    }
    if (!o.compare_state.empty()) {
      PetscViewer viewer = nullptr;
      CATENA_PETSC(PetscViewerBinaryOpen(comm, o.compare_state.c_str(), FILE_MODE_READ, &viewer));
      CATENA_PETSC(VecLoad(d.get(), viewer));
      CATENA_PETSC(PetscViewerDestroy(&viewer));
      CATENA_PETSC(VecAXPY(d.get(), -1.0, integrator->q()));
      CATENA_PETSC(VecNorm(d.get(), NORM_INFINITY, &state_difference));
    }
  }

  // Unit costs, measured apart from the run: one residual at the final state, and one
  // solve of the factored HHT Newton matrix (n × n, factored as HHT factors it: PETSc's LU
  // on one rank, the partition-interface solve on more).
  CATENA_PETSC(PetscLogStagePush(unit_stage));
  const catena::assembly::EvalPoint point{integrator->q(), integrator->v(), {}, integrator->time()};
  catena::VecHandle f = system.create_vector(), x = system.create_vector();
  system.force(point, f.get());
  const double t_residual = timed(comm,
                                  [&] {
                                    for (int i = 0; i < o.repeat; ++i) system.force(point, f.get());
                                  }) /
                            o.repeat;
  const double a = o.integrator == "hht" ? o.alpha : 0.0;
  const double beta = 0.25 * (1 - a) * (1 - a), gamma = 0.5 - a;
  catena::MatHandle J = system.create_matrix();
  system.jacobian(point, {(1 + a) * beta * o.dt * o.dt, (1 + a) * gamma * o.dt, 1.0}, J.get());
  // The factorisation HHT uses for this system (no multipliers: no pivoting needed).
  catena::KspHandle ksp =
      catena::solvers::create_direct_ksp(comm, "bench_", catena::solvers::JacobianSymmetry::general,
                                         catena::solvers::Pivoting::not_needed);
  CATENA_PETSC(KSPSetOperators(ksp.get(), J.get(), J.get()));
  long n_interface = 0;
  if (catena::solvers::use_interface_split(comm, "bench_", catena::solvers::Pivoting::not_needed))
    n_interface = catena::solvers::use_interface_schur(ksp.get(), J.get());
  const double t_factor = timed(comm, [&] { CATENA_PETSC(KSPSetUp(ksp.get())); });
  CATENA_PETSC(KSPSolve(ksp.get(), f.get(), x.get()));
  const double t_solve = timed(comm,
                               [&] {
                                 for (int i = 0; i < o.repeat; ++i)
                                   CATENA_PETSC(KSPSolve(ksp.get(), f.get(), x.get()));
                               }) /
                         o.repeat;
  CATENA_PETSC(PetscLogStagePop());

  // Steps after the first: counters, event times and wall time per step.
  const int n_rest = static_cast<int>(timer.seconds.size()) - 1;
  double rest_seconds = 0.0;
  for (std::size_t i = 1; i < timer.seconds.size(); ++i) rest_seconds += timer.seconds[i];
  MPI_Bcast(&rest_seconds, 1, MPI_DOUBLE, 0, comm);
  const auto per_step = [&](long after, long before) {
    return static_cast<double>(after - before) / n_rest;
  };
  const catena::solvers::IntegratorCounters& k1 = timer.after_first;
  const EventTotals force = event_totals(comm, steps_stage, "CatForce");
  const EventTotals tangent = event_totals(comm, steps_stage, "CatTangent");
  // The Newton matrix build around the tangent: HHT's MatCopy/MatAXPY, the IRK stage
  // matrix's row copies (SNESJacobianEval includes CatTangent).
  const EventTotals jacobian = event_totals(comm, steps_stage, "SNESJacobianEval");
  const EventTotals build{jacobian.count, jacobian.seconds - tangent.seconds};
  const EventTotals factor = event_totals(comm, steps_stage, "MatLUFactorNum");
  const EventTotals solve = event_totals(comm, steps_stage, "MatSolve");
  const EventTotals analysis = event_totals(comm, first_stage, "MatLUFactorSym");
  // HHT's local Newton corrections (solvers/newton/local_newton.hpp; 0 if none ran).
  const EventTotals local = event_totals(comm, steps_stage, "CatLocalNewton");
  const double t_step = rest_seconds / n_rest;
  const double accounted =
      force.seconds + jacobian.seconds + factor.seconds + solve.seconds + local.seconds;
  const auto each = [](const EventTotals& e) { return e.count > 0 ? e.seconds / e.count : 0.0; };
  // Per stage-system factorisation or solve (the decoupled IRK's are one per block).
  const auto per_count = [](const EventTotals& e, long count) {
    return count > 0 ? e.seconds / static_cast<double>(count) : 0.0;
  };
  const double factor_each = per_count(factor, total.factorizations - k1.factorizations);
  const double solve_each = per_count(solve, total.linear_solves - k1.linear_solves);
  const auto* irk = dynamic_cast<const catena::solvers::IrkIntegrator*>(integrator.get());
  const std::string method =
      integrator->name() + (irk ? (irk->decoupled() ? "/decoupled" : "/coupled") : "");
  const double ratio = t_step / (t_residual + t_solve);
  // The same with the unit costs seen inside the run (this method's own solve pair).
  const double ratio_in_run = t_step / (each(force) + solve_each);

  if (rank == 0) {
    const double ms = 1e3;
    std::printf(
        "moving load benchmark: %.0f m line, %.3f m elements, %zu elements, %lld free "
        "DOFs, %d ranks\n",
        o.length, o.element, model.elements.size(),
        static_cast<long long>(system.dof_map().n_global()), size);
    std::printf(
        "  %s, dt %g s, %d steps (%ld rejected); %zu load(s) of %g N upward at %g m/s, the "
        "first from x = %g m\n",
        method.c_str(), o.dt, static_cast<int>(timer.seconds.size()), report.steps_rejected,
        load_starts(o).size(), o.force, o.speed, load_starts(o).front());
    std::printf(
        "  static equilibrium %.2f s (%d load steps, %d Newton iterations); set_state "
        "%.2f s; first step %.2f s (%.0f symbolic analyses)\n",
        t_static, statics.n_load_steps, statics.n_newton_iterations, t_set_state,
        timer.seconds.front(), analysis.count);
    std::printf("  per step, steps 2..%d     count   ms each   ms per step\n", n_rest + 1);
    std::printf("    Newton iterations    %7.3f\n",
                per_step(total.newton_iterations, k1.newton_iterations));
    std::printf("    residual evaluations %7.3f  %8.2f  %10.2f   (CatForce)\n",
                per_step(total.residual_evaluations, k1.residual_evaluations), ms * each(force),
                ms * force.seconds / n_rest);
    std::printf("    tangent assemblies   %7.3f  %8.2f  %10.2f   (CatTangent)\n",
                per_step(total.jacobian_evaluations, k1.jacobian_evaluations), ms * each(tangent),
                ms * tangent.seconds / n_rest);
    std::printf("    matrix builds        %7.3f  %8.2f  %10.2f   (SNESJacobianEval - CatTangent)\n",
                build.count / n_rest, ms * each(build), ms * build.seconds / n_rest);
    std::printf("    factorisations       %7.3f  %8.2f  %10.2f   (MatLUFactorNum)\n",
                per_step(total.factorizations, k1.factorizations), ms * factor_each,
                ms * factor.seconds / n_rest);
    std::printf(
        "    triangular solves    %7.3f  %8.2f  %10.2f   (MatSolve, a forward + backward "
        "pair)\n",
        per_step(total.linear_solves, k1.linear_solves), ms * solve_each,
        ms * solve.seconds / n_rest);
    std::printf(
        "    local Newton corrections %7.3f  %8.2f  %10.2f   (CatLocalNewton; finished %.3f, "
        "%.0f window unknowns per step)\n",
        local.count / n_rest, ms * each(local), ms * local.seconds / n_rest,
        per_step(total.local_corrections, k1.local_corrections),
        per_step(total.local_unknowns, k1.local_unknowns));
    std::printf("    other (vector ops, mass products, SNES)     %10.2f\n",
                ms * (t_step - accounted / n_rest));
    std::printf("    step wall time                              %10.2f\n", ms * t_step);
    std::printf(
        "  unit costs: residual %.2f ms, HHT matrix (n x n) LU solve pair %.2f ms "
        "(factorisation %.0f ms)\n",
        ms * t_residual, ms * t_solve, ms * t_factor);
    std::printf("  ratio step / (residual + HHT solve pair) = %.2f (target <= 3 for HHT: %s)\n",
                ratio, ratio <= 3.0 ? "met" : "not met");
    std::printf("  ratio with the run's own unit costs (CatForce, MatSolve) = %.2f\n",
                ratio_in_run);
    std::printf("  final state: max |q - q_static| = %.6g (m or slope)", motion);
    if (state_difference >= 0.0)
      std::printf(", max |q - q(%s)| = %.3g", o.compare_state.c_str(), state_difference);
    std::printf("\n");
    std::printf(
        "  communication per step and rank (PETSc's count, largest rank): %.1f messages "
        "(sends + receives), %.0f bytes, %.1f reductions; interface rows %ld\n",
        traffic.messages / n_rest, traffic.bytes / n_rest, traffic.reductions / n_rest,
        n_interface);
    constexpr double mib = 1024.0 * 1024.0;
    std::printf(
        "  whole run (scene, statics, %d steps) %.2f s; peak memory per rank %.0f MiB "
        "(largest), %.0f MiB (smallest), %.0f MiB in all\n",
        n_rest + 1, whole_run, memory.largest_bytes / mib, memory.smallest_bytes / mib,
        memory.total_bytes / mib);
    std::printf(
        "  peak memory per rank (largest) by phase: scene and system %.0f MiB (rank %d), "
        "with the static solve %.0f MiB (rank %d), with the steps %.0f MiB (rank %d)\n",
        memory_system.largest_bytes / mib, memory_system.largest_rank,
        memory_statics.largest_bytes / mib, memory_statics.largest_rank, memory.largest_bytes / mib,
        memory.largest_rank);
    // One JSON object for scaling/scaling_study.py (the names are its CSV columns).
    std::printf(
        "SCALING {\"method\": \"%s\", \"ranks\": %d, \"length_m\": %.17g, "
        "\"loads\": %zu, \"dofs\": %lld, \"dt\": %.17g, \"steps\": %d, "
        "\"newton_per_step\": %.6g, \"step_s\": %.9g, \"first_step_s\": %.9g, "
        "\"whole_run_s\": %.9g, \"static_s\": %.9g, \"residual_s\": %.9g, "
        "\"solve_pair_s\": %.9g, \"factorisation_s\": %.9g, "
        "\"factorisations_per_step\": %.6g, \"residual_in_run_s\": %.9g, "
        "\"solve_in_run_s\": %.9g, \"interface_rows\": %ld, "
        "\"messages_per_step\": %.6g, \"bytes_per_step\": %.9g, "
        "\"reductions_per_step\": %.6g, \"flops_per_step\": %.9g, "
        "\"peak_memory_largest_bytes\": %.17g, \"peak_memory_total_bytes\": %.17g, "
        "\"final_motion\": %.17g, \"local_newton_s\": %.9g}\n",
        method.c_str(), size, o.length, load_starts(o).size(),
        static_cast<long long>(system.dof_map().n_global()), o.dt, n_rest + 1,
        per_step(total.newton_iterations, k1.newton_iterations), t_step, timer.seconds.front(),
        whole_run, t_static, t_residual, t_solve, t_factor,
        per_step(total.factorizations, k1.factorizations), each(force), solve_each, n_interface,
        traffic.messages / n_rest, traffic.bytes / n_rest, traffic.reductions / n_rest,
        traffic.flops / n_rest, memory.largest_bytes, memory.total_bytes, motion,
        local.seconds / n_rest);
    // CSV: method, ranks, DOFs, dt, steps, then per step after the first: Newton iterations,
    // residuals, tangents, factorisations, solve pairs, step s; first step s; unit residual
    // s, unit HHT solve pair s, in-run residual s, in-run solve pair s, both ratios.
    std::printf(
        "CSV,%s,%d,%lld,%g,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.3f,%.3f\n",
        method.c_str(), size, static_cast<long long>(system.dof_map().n_global()), o.dt, n_rest + 1,
        per_step(total.newton_iterations, k1.newton_iterations),
        per_step(total.residual_evaluations, k1.residual_evaluations),
        per_step(total.jacobian_evaluations, k1.jacobian_evaluations),
        per_step(total.factorizations, k1.factorizations),
        per_step(total.linear_solves, k1.linear_solves), t_step, timer.seconds.front(), t_residual,
        t_solve, each(force), solve_each, ratio, ratio_in_run);
  }
  return 0;
}

int main(int argc, char** argv) {
  catena::PetscSession petsc(
      &argc, &argv,
      "moving_load_benchmark [-steps n] [-dt s] [-integrator hht|radau] "
      "[-alpha a] [-newton simplified|full] [-length m] [-element m] "
      "[-force N] [-speed m/s] [-start m] [-load_spacing m] [-newton_rtol r] "
      "[-newton_atol N] [-repeat n] [-linear_algebra auto|decoupled|coupled] "
      "[-save_state FILE] [-compare_state FILE]\n");
  return catena::bench::run_reporting_errors("moving_load_benchmark", run_benchmark);
}

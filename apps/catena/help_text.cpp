// The text of `catena --help` and of `catena COMMAND --help` (cli.hpp, usage).
#include <string>

#include "cli.hpp"

namespace catena::app {
namespace {

constexpr const char* kTitle =
    "catena — parallel solver for cables, beams and overhead contact lines\n\n";

constexpr const char* kSetOption =
    R"(  --set KEY=VALUE       override a scene value, e.g. --set lines[0].elements=400
                        --set sections.cw.EA=2e7 (validated like the file; repeatable)
)";

constexpr const char* kMemoryOption =
    R"(  --memory-limit GIB    memory per host the run may use (default: the host's physical
                        memory); a scene whose estimated need exceeds it is refused
                        (docs/scene.md, "Memory"); off: no check
)";

// The evaluation options of the commands that read a run's output (stats, export, plot).
constexpr const char* kPostOptions =
    R"(  --section X0 X1       evaluation section along the path, m (default: the run's
                        evaluation_start/evaluation_end; if the run sets none, stats
                        requires one, export and plot take the whole record)
  --cutoff HZ           low-pass cutoff, Hz (default 20; zero-phase Butterworth, -6 dB
                        at the cutoff; the sampling rate must be >= 10 x the cutoff)
  --series S            samples (default): the output's samples; steps: the contact
                        force of every step (fixed steps), the uplift from the samples
                        interpolated: fine statistics from a run whose fields are written
                        at a coarse output.interval
)";

constexpr const char* kRangesOption =
    R"(  --ranges R            acceptance ranges to check: en50318 (the EN 50318 reference
                        case at 250 and 300 km/h) or none (default: the scene's
                        catenary.acceptance)
)";

struct CommandHelp {
  const char* name;
  const char* usage;    // its line(s) under "Usage:"
  const char* what;     // its line(s) under "Commands:"
  std::string options;  // "Options of NAME:" and the options
  bool petsc = false;   // takes PETSc options
};

const CommandHelp* commands() {
  static const CommandHelp all[] = {
      {"run",
       R"(  catena run   SCENE.yaml [-o OUT.h5] [--set KEY=VALUE ...] [--restart] [--progress S]
               [--quiet] [--realtime] [--error-bar] [--error-bar-ranks K]
               [--memory-limit GIB] [PETSc options]
)",
       R"(  run     solve the scene (static equilibrium or dynamics) and write OUT.h5 (+ OUT.xmf
          for ParaView)
)",
       std::string(R"(Options of run:
  -o, --output FILE     output file (default: the scene's output.file, else catena.h5)
)") + kSetOption +
           R"(  --restart             dynamics: continue from the checkpoint OUT.h5.chk, appending to
                        OUT.h5 (same scene; analysis.duration may be raised)
  --progress S          a progress line every S seconds of wall time (default 5; 0: every
                        step; off: none): simulated time, steps, Newton iterations, rate
                        and ETA of dynamics; load path point and steps of statics
  --quiet               no progress lines (as --progress off)
  --realtime            dynamics: report whether each output interval ended within the
                        wall clock (hardware in the loop) and the wall time per step:
                        mean, 99th percentile, worst (also in OUT.h5's statistics)
  --error-bar           dynamics, fixed steps: then run the scene at 2 dt and 4 dt
                        (OUT.error_bar/) and estimate this run's time-discretisation
                        error of its statistics or probe track (Richardson, observed
                        order; stored in OUT.h5 /error_bar; up to the run's cost again)
  --error-bar-ranks K   --error-bar with the runs at 2 dt and 4 dt on the last K ranks
                        of mpirun -n, at the same time as this run on the others
                        (K = 1: one after the other on that rank)
)" + kMemoryOption,
       true},
      {"check", "  catena check SCENE.yaml [--set KEY=VALUE ...] [--memory-limit GIB] [--ids]\n",
       "  check   validate the scene and print what would be modelled, without solving\n",
       std::string("Options of check:\n") + kSetOption + kMemoryOption +
           "  --ids                 also list the catenary's droppers and supports with their\n"
           "                        node and element ids (docs/catenary.md, \"Ids\")\n",
       false},
      {"stats",
       "  catena stats OUT.h5 [--json] [--section X0 X1] [--cutoff HZ] [--series "
       "samples|steps]\n"
       "               [--ranges en50318|none]\n",
       R"(  stats   EN 50318 contact-force statistics per pantograph of a dynamic run's OUT.h5,
          checked against the acceptance ranges when the scene declares them
          (catenary.acceptance); an unfinished run over the part it covered (serial:
          run it without mpirun)
)",
       std::string(R"(Options of stats:
  --json                print JSON instead of a table
)") + kPostOptions +
           kRangesOption,
       false},
      {"export",
       "  catena export OUT.h5 [--csv] [-o PREFIX] [--section X0 X1] [--cutoff HZ] [--series S]\n"
       "               [--ranges en50318|none]\n",
       R"(  export  a dynamic run's contact-force series (time, position, raw and filtered force
          per pantograph) and its statistics as CSV: PREFIX_contact.csv,
          PREFIX_statistics.csv
)",
       std::string(R"(Options of export:
  --csv                 CSV files (the one format; the default)
  -o PREFIX             the files' prefix (default: OUT.h5 without .h5)
)") + kPostOptions +
           kRangesOption,
       false},
      {"plot",
       "  catena plot  OUT.h5 [-o PREFIX] [--format png,pdf] [--section X0 X1] [--cutoff HZ]\n"
       "               [--series S]\n",
       R"(  plot    the figures of a run or a static result: contact force against position,
          its spectrum and the uplift at the supports per pantograph, the static shape
          (a run without pantographs: the node that moves most): PREFIX_NAME.png
          (needs /usr/bin/python3 with matplotlib and h5py)
)",
       std::string(R"(Options of plot:
  -o PREFIX             the files' prefix (default: OUT.h5 without .h5)
  --format F            png (default), pdf, or png,pdf
)") + kPostOptions,
       false},
      {"modes",
       R"(  catena modes SCENE.yaml [-o OUT.h5] [--set KEY=VALUE ...] [--count N] [PETSc options]
)",
       R"(  modes   the lowest vibration modes about the scene's static equilibrium (frequencies,
          mass-normalised shapes) into OUT.h5 + OUT.xmf (ParaView: one step per mode)
)",
       std::string(R"(Options of modes:
  -o, --output FILE     output file (default: the scene's output.file with _modes before
                        .h5)
  --count N             the N lowest modes (default 20)
)") + kSetOption +
           kMemoryOption,
       true},
      {"elasticity",
       R"(  catena elasticity SCENE.yaml [--set KEY=VALUE ...] [--span N] [--step DX] [--force F]
                    [--json] [PETSc options]
)",
       R"(  elasticity  static elasticity of a catenary scene along one span (EN 50119): uplift of
          the contact wire per newton of a static upward force at each point, and the
          linear (small-force) elasticity, with max, min, mean and the uniformity
          coefficient (docs/catenary.md, "Elasticity")
)",
       std::string(
           "Options of elasticity (pantographs, moving loads and dynamics are ignored):\n") +
           kSetOption +
           R"(  --span N              span, 1-based (default: the first of catenary.evaluation_spans,
                        else the middle span, (spans + 1) / 2)
  --step DX             spacing of the points along the span, m (default 1; > 0, at most
                        the span length); both supports are points
  --force F             static upward force at each point, N (default 100; > 0)
  --json                print JSON instead of a table
)",
       true},
      {"study",
       R"(  catena study SCENE.yaml (--vary KEY=V1,V2,... | --methods M1,M2 [--steps F1,F2])
               [--vary ...] [--reference KEY=VALUE ...] [--target MEASURE=LIMIT ...] [--ranks-per-case K] [--probe NODE_ID ...]
               [--cutoff HZ] [--set KEY=VALUE ...] [-o DIR] [PETSc options]
)",
       R"(  study   run a dynamic scene under several settings, measure each against a reference
          (errors of the contact force and its EN 50318 statistics, or of probe nodes)
          and its cost; DIR/study.csv, DIR/study.png, the cheapest setting within
          --target (docs/study.md)
)",
       std::string(R"(Options of study:
  --vary KEY=V1,V2,...  a scene key and its values (repeatable: every combination runs);
                        e.g. --vary integrator.dt=1e-3,5e-4 --vary integrator.type=hht,radau
  --methods M1,M2       method presets, each at its own steps: hht (HHT-alpha, 1x the
                        scene's dt), radau (Radau IIA s = 3, 4x), park (Park's
                        multistep method, 1x), bdf (BDF-2, 1x), linear (linear
                        structure, linearly implicit HHT, 1x), modal (modal model, 1x;
                        its modes solved once, DIR/modal_basis.h5); all: every one
  --steps F1,F2,...     with --methods: each method's step times these (default 2,1,0.5)
  --reference KEY=VALUE the reference's settings (repeatable); default: the scene's method
                        at the study's tightest resolution with the time step halved,
                        checked against the same unhalved
  --target M=LIMIT      the accuracy to recommend a setting for (repeatable), e.g. std=1%,
                        force_rms_filtered=2N, probe_rms=1e-4m (default with pantographs:
                        std=1%)
  --ranks-per-case K    ranks each case runs on (default 1): mpirun -n N runs N/K cases
                        at once from one queue
  --probe NODE_ID       a node whose trajectory is compared (repeatable; default without
                        pantographs: the node that moves most in the reference)
  --cutoff HZ           low-pass of the contact-force statistics (default 20)
  -o DIR                the study's directory (default: the scene's name + _study); run
                        the same command again to resume: finished cases are kept
)") + kSetOption,
       true},
      {"sweep",
       R"(  catena sweep SCENE.yaml --vary KEY=V1,V2,... [--vary ...] [--ranks-per-case K]
               [--cutoff HZ] [--set KEY=VALUE ...] [-o DIR] [PETSc options]
)",
       R"(  sweep   run a pantograph scene under several settings (speeds, static forces, ...)
          and tabulate each run's EN 50318 statistics: DIR/sweep.csv, DIR/sweep.png
          (docs/study.md, "Sweeps")
)",
       std::string(R"(Options of sweep:
  --vary KEY=V1,V2,...  a scene key and its values (repeatable: every combination runs),
                        e.g. --vary pantographs[0].speed_kmh=200,250,300
  --ranks-per-case K    ranks each case runs on (default 1): mpirun -n N runs N/K cases
                        at once from one queue
  --cutoff HZ           low-pass of the statistics (default 20)
  -o DIR                the sweep's directory (default: the scene's name + _sweep); run
                        the same command again to resume: finished cases are kept
)") + kSetOption,
       true},
      {nullptr, nullptr, nullptr, "", false},
  };
  return all;
}

constexpr const char* kPetsc =
    R"(PETSc options take the prefix of the solver they set (then snes_, ksp_, pc_,
mat_mumps_icntl_N, ...):
  -static_              static equilibrium (Newton along the load path)
  -static_stability_    its stability check (LDL' of the tangent at each equilibrium)
  -hht_                 HHT-alpha's Newton solve (dynamics, integrator.type: hht)
  -multistep_           bdf's and park's Newton solve (integrator.type: bdf, park)
  -irk_                 implicit Runge-Kutta stage Newton; -irk_block<k>_ its decoupled
                        blocks, -irk_estimate_ the embedded error estimate's solve
  -ts_                  integrator.type: petsc (e.g. -ts_type bdf)
  -mass_                the consistent initial acceleration (mass matrix solve)
  -elasticity_, -elasticity_linear_   catena elasticity: loaded solves, the tangent
e.g.:
  -static_snes_monitor -hht_snes_converged_reason -log_view -static_stability_mat_mumps_icntl_4 2
An option that no solver of the run read is reported when the command ends (a misspelling,
or a solver this run does not create).
)";

constexpr const char* kGeneral = R"(Options of every command:
  -h, --help            this text (catena COMMAND --help: that command's)
  --version             Catena's version and commit, and the libraries it runs on
)";

constexpr const char* kExamples = R"(Examples:
  catena check meshes/default.yaml
  mpirun -n 2 catena run meshes/default.yaml -o default.h5
  mpirun -n 4 catena run meshes/default.yaml --set lines[0].elements=2000 -log_view
  catena stats en50318_250.h5 --section 240 360
  catena plot en50318_250.h5 --format png,pdf
  catena export en50318_250.h5 -o results/en50318_250
  mpirun -n 2 catena elasticity meshes/simple_catenary.yaml --step 0.5 --json
  mpirun -n 2 catena study meshes/taut_string.yaml --vary integrator.dt=4e-4,2e-4,1e-4
)";

}  // namespace

std::string usage(const std::string& command) {
  std::string text = kTitle;
  text += "Usage:\n";
  bool petsc = false;
  for (const CommandHelp* c = commands(); c->name; ++c)
    if (command.empty() || command == c->name) text += c->usage;
  if (command.empty()) text += "  catena --help | --version\n";
  text += command.empty() ? "\nCommands:\n" : "\n";
  for (const CommandHelp* c = commands(); c->name; ++c)
    if (command.empty() || command == c->name) text += c->what;
  for (const CommandHelp* c = commands(); c->name; ++c)
    if (command.empty() || command == c->name) {
      text += "\n" + c->options;
      petsc = petsc || c->petsc;
    }
  text += "\n" + std::string(kGeneral);
  if (petsc) text += "\n" + std::string(kPetsc);
  if (command.empty()) text += "\n" + std::string(kExamples);
  return text;
}

}  // namespace catena::app

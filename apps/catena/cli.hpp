#pragma once
// Command-line parsing for the catena app. Arguments we do not recognise and that start
// with '-' are left to PETSc's options database (e.g. -static_snes_monitor, -log_view).
#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace catena::app {

// `catena stats OUT.h5 [--json] [--section X0 X1] [--cutoff HZ] [--series samples|steps]
// [--ranges R]`; `catena export` and `catena plot` read a run alike (cli.cpp, post_options).
struct StatsArguments {
  std::string file;                              // a dynamic run's output
  bool json = false;                             // --json: JSON instead of the table
  std::optional<std::array<double, 2>> section;  // --section X0 X1 [m]; else the file's
  double cutoff_hz = 20.0;                       // --cutoff HZ: low-pass cutoff (−6 dB point)
  bool steps = false;  // --series steps: the contact force of every step, not the samples'
  // --series given: else the samples, or every step's when the samples are too coarse for
  // the cutoff (fields written seldom)
  bool series_given = false;
  bool cutoff_given = false;  // --cutoff given (else EN 50318's 20 Hz)
  // --ranges en50318|none: the acceptance ranges (default: the run's catenary.acceptance).
  std::optional<std::string> ranges;
  std::string output;                       // export, plot: -o PREFIX (default: OUT less .h5)
  std::vector<std::string> formats{"png"};  // plot --format png,pdf
};

// `catena elasticity SCENE [--set k=v ...] [--span N] [--step DX] [--force F] [--json]`.
struct ElasticityArguments {
  std::optional<int> span;  // --span N (1-based); else the first evaluation span or the middle one
  double step = 1.0;        // --step DX [m], > 0: spacing of the points along the span
  double force = 100.0;     // --force F [N], > 0: the static upward probe force
  bool json = false;        // --json: JSON instead of the table
  std::set<std::string> given;  // the options with a value seen so far (each is taken once)
};

// `catena modes SCENE [--set k=v ...] [--count N] [-o FILE]`.
struct ModesArguments {
  int count = 20;  // --count N: the lowest N modes
};

// `catena study SCENE [--vary K=V1,V2 ...] [--reference K=V ...] [--target M=X ...]
// [--ranks-per-case K] [--probe ID ...] [--cutoff HZ] [-o DIR]` (docs/study.md).
struct StudyArguments {
  std::vector<std::string> vary;                    // --vary KEY=V1,V2,..., in order
  std::vector<std::string> methods;                 // --methods NAME,NAME (presets; "all")
  std::vector<std::string> steps{"2", "1", "0.5"};  // --steps F1,F2: of each method's step
  bool steps_given = false;
  std::vector<std::string> reference;  // --reference KEY=VALUE (none: the default reference)
  std::vector<std::string> targets;    // --target MEASURE=LIMIT, e.g. std=1%
  int ranks_per_case = 1;              // --ranks-per-case K
  std::vector<long long> probes;       // --probe NODE_ID (scene ids)
  double cutoff_hz = 20.0;             // --cutoff HZ: the statistics' low-pass
  bool cutoff_given = false;           // --cutoff given (else EN 50318's 20 Hz)
  std::string directory;               // -o DIR (default: SCENE's stem + "_study")
};

struct CommandLine {
  // run | check | stats | export | plot | elasticity | modes | study | sweep | help | version
  std::string command;
  std::string help_topic;              // help: the command asked about ("" = all)
  std::string scene;                   // scene file path
  std::vector<std::string> overrides;  // --set key=value, in order
  std::optional<std::string> output;   // -o FILE (same as --set output.file=FILE)
  bool restart = false;                // --restart: continue from OUT.h5.chk
  bool ids = false;                    // check --ids: list the catenary builder's ids
  bool realtime = false;               // run --realtime: measure against the wall clock
  bool error_bar = false;              // run --error-bar: Richardson at 2 dt and 4 dt
  // run --error-bar-ranks K (implies --error-bar): the last K ranks run the comparisons while
  // the others run the scene (0: not given; with --error-bar the comparisons then follow the
  // run on all its ranks).
  int error_bar_ranks = 0;
  // --memory-limit GIB: the memory per host a run may use (default: physical memory);
  // 0 (--memory-limit off): no memory check.
  std::optional<double> memory_limit_gib;
  // --progress SECONDS: wall time between progress lines (0: every step);
  // --progress off or --quiet: none (negative).
  double progress_seconds = 5.0;
  std::vector<std::string> petsc_options;  // the PETSc options given ("-hht_snes_rtol")
  std::string joined;                      // the whole command line, for the output file
  StatsArguments stats;                    // commands "stats", "export" and "plot"
  ElasticityArguments elasticity;          // command "elasticity" only
  ModesArguments modes;                    // command "modes" only
  StudyArguments study;                    // commands "study" and "sweep"
};

// Throws catena::InputError for malformed arguments.
CommandLine parse_command_line(int argc, char** argv);

// Not collective. The help text: of every command when `command` is empty, else of that
// one (run, check, stats, elasticity, modes).
std::string usage(const std::string& command = "");

}  // namespace catena::app

#include "cli.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "catena/core/error.hpp"

namespace catena::app {

namespace {
// run, check, stats, export, plot, elasticity, modes, study or sweep.
bool is_command(const std::string& name) {
  return name == "run" || name == "check" || name == "stats" || name == "export" ||
         name == "plot" || name == "elasticity" || name == "modes" || name == "study" ||
         name == "sweep";
}

bool is_scene_path(const std::string& token) {
  auto ends_with = [&](const std::string& suffix) {
    return token.size() >= suffix.size() &&
           token.compare(token.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return ends_with(".yaml") || ends_with(".yml");
}

// A finite real number, the whole token (no trailing characters); `accepted`, if given,
// is added to the message.
double parse_real(const std::string& token, const char* flag, const std::string& accepted = "") {
  double value = 0.0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value))
    throw InputError({"", 0, flag}, "'" + token + "' is not a finite number" +
                                        (accepted.empty() ? "" : "; accepted: " + accepted));
  return value;
}

// A whole number, the whole token.
int parse_integer(const std::string& token, const char* flag, const char* accepted) {
  int value = 0;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ec != std::errc() || ptr != end)
    throw InputError({"", 0, flag}, "'" + token + "' is not a whole number; accepted: " + accepted);
  return value;
}

// A finite number > 0, the whole token; `accepted` says what is, for the message.
double parse_positive(const std::string& token, const char* flag, const char* unit,
                      const std::string& accepted) {
  const double value = parse_real(token, flag, accepted);
  if (!(value > 0.0))
    throw InputError({"", 0, flag},
                     "must be positive (got " + token + " " + unit + "); accepted: " + accepted);
  return value;
}

// A finite number >= 0, the whole token.
double parse_non_negative(const std::string& token, const char* flag, const char* unit,
                          const std::string& accepted) {
  const double value = parse_real(token, flag, accepted);
  if (!(value >= 0.0))
    throw InputError({"", 0, flag}, "must not be negative (got " + token + " " + unit +
                                        "); accepted: " + accepted);
  return value;
}

// The options of `catena elasticity` at args[i]; returns false if args[i] is none of them.
bool parse_elasticity_option(const std::vector<std::string>& args, size_t& i,
                             ElasticityArguments& el) {
  const std::string& a = args[i];
  // Each takes one value; given twice, the last would silently win.
  if (a == "--span" || a == "--step" || a == "--force") {
    if (!el.given.insert(a).second)
      throw InputError({"", 0, a}, "'" + a + "' is given twice; accepted: once");
  }
  auto value = [&](const char* flag) -> const std::string& {
    if (i + 1 >= args.size())
      throw InputError({"", 0, flag}, std::string("missing value after ") + flag);
    return args[++i];
  };
  if (a == "--json") {
    el.json = true;
  } else if (a == "--span") {
    el.span = parse_integer(value("--span"), "--span",
                            "a span number from 1 to the catenary's number of spans");
    if (*el.span < 1)
      throw InputError({"", 0, "--span"}, "span " + args[i] +
                                              " does not exist; accepted: a span number from "
                                              "1 to the catenary's number of spans");
  } else if (a == "--step") {
    el.step = parse_positive(value("--step"), "--step", "m",
                             "a distance in m, > 0 and at most the span length");
  } else if (a == "--force") {
    // EN 50119's probe force is 100 N (up to a few hundred); below 0.01 N the uplift
    // vanishes in Newton's tolerance (1e-300 N printed NaN), above 10 kN it lifts the wire
    // off its droppers and masts, no elasticity any more (1e30 N printed an uplift of 1e27 mm).
    el.force = parse_positive(value("--force"), "--force", "N",
                              "an upward force in N, from 0.01 to 10000 (EN 50119: 100)");
    if (el.force < 0.01 || el.force > 1e4)
      throw InputError({"", 0, "--force"},
                       "--force " + args[i] +
                           " N is out of range; accepted: an upward force in N, from 0.01 to "
                           "10000 (EN 50119: 100)");
  } else if (a == "-o" || a == "--output" || a == "--restart") {
    throw InputError({"", 0, "arguments"}, "'" + a +
                                               "' is not an option of elasticity (which "
                                               "writes no output file); accepted: --set, --span N, "
                                               "--step DX, --force F, --json");
  } else {
    return false;
  }
  return true;
}

// The options of study and sweep beyond every scene command's, for the "accepted" lists.
constexpr const char* kStudyOptions =
    "--vary KEY=V1,V2,..., --methods, --steps, --reference, --target, --ranks-per-case, "
    "--probe, --cutoff, --set, -o DIR";
constexpr const char* kSweepOptions =
    "--vary KEY=V1,V2,..., --ranks-per-case, --cutoff, --set, -o DIR";

// The options of `catena study` at args[i]; returns false if args[i] is none of them.
bool parse_study_option(const std::vector<std::string>& args, size_t& i, CommandLine& cl) {
  StudyArguments& st = cl.study;
  const std::string& a = args[i];
  // The next token, unless it is an option (`--vary -o DIR` lacks the varied key).
  auto value = [&](const char* flag) -> const std::string& {
    if (i + 1 >= args.size())
      throw InputError({"", 0, flag}, std::string("missing value after ") + flag);
    const std::string& next = args[i + 1];
    if (next.rfind("--", 0) == 0 || next == "-o")
      throw InputError({"", 0, flag}, std::string("missing value after ") + flag +
                                          " (the next argument is the option '" + next + "')");
    return args[++i];
  };
  auto list = [](const std::string& text) {
    std::vector<std::string> items;
    std::size_t start = 0;
    for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
      items.push_back(text.substr(start, comma - start));
    items.push_back(text.substr(start));
    return items;
  };
  if (a == "--vary") {
    st.vary.push_back(value("--vary"));
  } else if (a == "--methods") {
    for (const std::string& m : list(value("--methods"))) st.methods.push_back(m);
  } else if (a == "--steps") {
    st.steps = list(value("--steps"));
    st.steps_given = true;
  } else if (a == "--reference") {
    st.reference.push_back(value("--reference"));
  } else if (a == "--target") {
    st.targets.push_back(value("--target"));
  } else if (a == "--ranks-per-case") {
    st.ranks_per_case = parse_integer(value("--ranks-per-case"), "--ranks-per-case",
                                      "a whole number >= 1 that divides the number of ranks");
  } else if (a == "--probe") {
    st.probes.push_back(parse_integer(value("--probe"), "--probe", "a node id of the scene"));
  } else if (a == "--cutoff") {
    st.cutoff_hz = parse_positive(value("--cutoff"), "--cutoff", "Hz", "a frequency in Hz, > 0");
    st.cutoff_given = true;
  } else if (a == "-o" || a == "--output") {
    st.directory = value("-o");
    if (st.directory.empty())
      throw InputError({"", 0, "-o"},
                       "no directory given; expected a directory name, e.g. -o runs");
  } else if (a == "--error-bar") {
    throw InputError({"", 0, a},
                     "'--error-bar' is not an option of study: study.csv sets each case's error "
                     "bar beside its true error wherever the study runs its method at 2 and 4 "
                     "times its step (the *_estimate_* columns, docs/study.md)");
  } else if (a == "--restart" || a == "--realtime" || a == "--ids") {
    throw InputError({"", 0, a}, "'" + a +
                                     "' is not an option of study (a study resumes by itself: "
                                     "run the same command again); accepted: " +
                                     kStudyOptions);
  } else {
    return false;
  }
  return true;
}

// The options of `catena sweep` at args[i] (the study's --vary, --ranks-per-case, --cutoff,
// -o; its measuring options refused); returns false if args[i] is none of them.
bool parse_sweep_option(const std::vector<std::string>& args, size_t& i, CommandLine& cl) {
  const std::string& a = args[i];
  for (const char* study_only : {"--methods", "--steps", "--reference", "--target", "--probe"})
    if (a == study_only)
      throw InputError({"", 0, a}, "'" + a +
                                       "' is an option of study, not of sweep (a sweep "
                                       "tabulates each run's statistics; a study measures "
                                       "errors against a reference); accepted: " +
                                       kSweepOptions);
  return parse_study_option(args, i, cl);
}

// The options each command that reads a run's output takes, for the "accepted" lists.
std::string post_options(const std::string& command) {
  const std::string shared = "--section X0 X1, --cutoff HZ, --series S";
  if (command == "stats") return "--json, " + shared + ", --ranges R";
  if (command == "export") return "--csv, " + shared + ", --ranges R, -o PREFIX";
  return shared + ", --format F, -o PREFIX";  // plot
}

// `catena stats|export|plot OUT.h5 [options]` (post_options); args[i] follows the command.
void parse_post(const std::vector<std::string>& args, size_t i, CommandLine& cl) {
  StatsArguments& st = cl.stats;
  const std::string& command = cl.command;
  for (; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* flag) -> const std::string& {
      if (i + 1 >= args.size())
        throw InputError({"", 0, flag}, std::string("missing value after ") + flag);
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      cl.help_topic = command;
      cl.command = "help";
      return;
    } else if (a == "--json" && command == "stats") {
      st.json = true;
    } else if (a == "--csv" && command == "export") {
      // The one export format: accepted so that the command says what it writes.
    } else if (a == "--section") {
      const double x0 = parse_real(value("--section"), "--section");
      const double x1 = parse_real(value("--section"), "--section");
      if (!(x1 > x0))
        throw InputError({"", 0, "--section"},
                         "X1 must be greater than X0 (got " + args[i - 1] + " " + args[i] +
                             "); usage: --section X0 X1, in m along the path");
      st.section = std::array<double, 2>{x0, x1};
    } else if (a == "--cutoff") {
      st.cutoff_hz = parse_real(value("--cutoff"), "--cutoff");
      st.cutoff_given = true;
      if (!(st.cutoff_hz > 0.0))
        throw InputError({"", 0, "--cutoff"},
                         "the cutoff must be positive (got " + args[i] + " Hz)");
    } else if (a == "--series") {
      const std::string& series = value("--series");
      if (series != "samples" && series != "steps")
        throw InputError({"", 0, "--series"}, "unknown series '" + series +
                                                  "'; accepted: samples (the default: "
                                                  "/samples), steps (every step's contact force)");
      st.steps = series == "steps";
      st.series_given = true;
    } else if (a == "--ranges" && command != "plot") {
      const std::string& ranges = value("--ranges");
      if (ranges != "en50318" && ranges != "none")
        throw InputError({"", 0, "--ranges"},
                         "unknown acceptance ranges '" + ranges +
                             "'; accepted: en50318 (the EN 50318 reference case at 250 and 300 "
                             "km/h), none (default: the run's catenary.acceptance)");
      st.ranges = ranges;
    } else if ((a == "-o" || a == "--output") && command != "stats") {
      st.output = value("-o");
      if (st.output.empty() || st.output.back() == '/')
        throw InputError({"", 0, "-o"}, "'" + st.output +
                                            "' is not a file name prefix: give e.g. "
                                            "-o results/run1 (writes results/run1_*)");
    } else if (a == "--format" && command == "plot") {
      st.formats.clear();
      std::string list = value("--format");
      for (std::size_t from = 0; from <= list.size();) {
        const std::size_t comma = std::min(list.find(',', from), list.size());
        const std::string format = list.substr(from, comma - from);
        if (format != "png" && format != "pdf")
          throw InputError({"", 0, "--format"}, "unknown format '" + format + "' in '" + list +
                                                    "'; accepted: png, pdf, or both: png,pdf");
        st.formats.push_back(format);
        from = comma + 1;
      }
    } else if (!a.empty() && a[0] == '-') {
      throw InputError({"", 0, "arguments"}, "unknown option '" + a + "' for " + command +
                                                 "; accepted: " + post_options(command));
    } else if (st.file.empty()) {
      st.file = a;
    } else {
      throw InputError({"", 0, "arguments"}, "unexpected argument '" + a +
                                                 "': one output file is accepted (got '" + st.file +
                                                 "' already)");
    }
  }
  if (st.file.empty())
    throw InputError({"", 0, "OUT.h5"}, "no output file given; usage: catena " + command +
                                            " OUT.h5 [" + post_options(command) + "]");
}
// The options of a command that takes a scene, for the message on an unknown one.
std::string command_options(const std::string& command) {
  const std::string common = "--progress S, --quiet, --memory-limit GIB";
  if (command == "study") return kStudyOptions + (", " + common);
  if (command == "sweep") return kSweepOptions + (", " + common);
  const std::string with_set = "--set KEY=VALUE, " + common;
  if (command == "run")
    return with_set + ", -o FILE, --restart, --realtime, --error-bar, --error-bar-ranks K";
  if (command == "check") return with_set + ", -o FILE, --ids";
  if (command == "modes") return with_set + ", -o FILE, --count N";
  if (command == "elasticity") return with_set + ", --span N, --step DX, --force F, --json";
  return with_set;
}

}  // namespace

CommandLine parse_command_line(int argc, char** argv) {
  CommandLine cl;
  for (int i = 0; i < argc; ++i) {
    if (i > 0) cl.joined += ' ';
    cl.joined += argv[i];
  }
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    // No arguments: run the shipped default scene (style.md: every app runs with none).
    cl.command = "run";
    cl.scene = "meshes/default.yaml";
    return cl;
  }
  size_t i = 0;
  if (args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    cl.command = "help";
    if (args.size() > 1 && args[1] != "--help" && args[1] != "-h") {
      cl.help_topic = args[1];
      if (!is_command(cl.help_topic))
        throw InputError({"", 0, "help"}, "no command '" + args[1] +
                                              "'; accepted: run, check, stats, export, plot, "
                                              "elasticity, modes, study, sweep");
    }
    return cl;
  }
  if (args[0] == "--version" || args[0] == "version") {
    cl.command = "version";
    return cl;
  }
  cl.command = args[i++];
  if (cl.command == "stats" || cl.command == "export" || cl.command == "plot") {
    parse_post(args, i, cl);
    return cl;
  }
  if (!is_command(cl.command))
    throw InputError({"", 0, "command"},
                     "unknown command '" + cl.command +
                         "'; accepted: run, check, stats, export, plot, elasticity, modes, study, "
                         "sweep, --help");
  for (; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const char* flag) -> std::string {
      if (i + 1 >= args.size())
        throw InputError({"", 0, flag}, std::string("missing value after ") + flag);
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      cl.help_topic = cl.command;
      cl.command = "help";
      return cl;
    } else if (cl.command == "elasticity" && parse_elasticity_option(args, i, cl.elasticity)) {
      continue;
    } else if (cl.command == "sweep" && parse_sweep_option(args, i, cl)) {
      continue;
    } else if (cl.command == "study" && parse_study_option(args, i, cl)) {
      continue;
    } else if (cl.command == "modes" && a == "--count") {
      cl.modes.count = parse_integer(value("--count"), "--count", "a number of modes, >= 1");
      if (cl.modes.count < 1)
        throw InputError({"", 0, "--count"},
                         "--count " + args[i] + ": accepted: a number of modes, >= 1");
    } else if (cl.command == "modes" && a == "--restart") {
      throw InputError({"", 0, "--restart"},
                       "'--restart' continues a dynamic run; modes are computed in one go");
    } else if (a == "--set") {
      cl.overrides.push_back(value("--set"));
    } else if (a.rfind("--set=", 0) == 0) {
      cl.overrides.push_back(a.substr(6));
    } else if (a == "--restart") {
      cl.restart = true;
    } else if (a == "--realtime" || a == "--error-bar" || a == "--ids") {
      // Flags of one command each.
      const std::string owner = a == "--ids" ? "check" : "run";
      if (cl.command != owner)
        throw InputError({"", 0, a}, "'" + a + "' is an option of " + owner + " (catena " + owner +
                                         " SCENE.yaml " + a + "), not of " + cl.command);
      (a == "--realtime" ? cl.realtime : a == "--error-bar" ? cl.error_bar : cl.ids) = true;
    } else if (a == "--error-bar-ranks") {
      if (cl.command != "run")
        throw InputError({"", 0, a}, "'" + a + "' is an option of run (catena run SCENE.yaml " + a +
                                         " K), not of " + cl.command);
      cl.error_bar_ranks =
          parse_integer(value("--error-bar-ranks"), "--error-bar-ranks",
                        "a whole number of ranks >= 1, fewer than the run's (mpirun -n)");
      if (cl.error_bar_ranks < 1)
        throw InputError({"", 0, a}, "--error-bar-ranks " + args[i] +
                                         ": accepted: a whole number of ranks >= 1, fewer "
                                         "than the run's (mpirun -n)");
      cl.error_bar = true;
    } else if (a == "-o" || a == "--output") {
      cl.output = value("-o");
      if (cl.output->empty())
        throw InputError({"", 0, "-o"},
                         "no file name given; expected an HDF5 file name, e.g. -o out.h5");
    } else if (a == "--progress") {
      const std::string& every = value("--progress");
      cl.progress_seconds =
          every == "off" ? -1.0
                         : parse_non_negative(every, "--progress", "s",
                                              "wall seconds between progress lines, >= 0 (0: "
                                              "every step), or off");
    } else if (a == "--quiet") {
      cl.progress_seconds = -1.0;
    } else if (a == "--memory-limit") {
      const std::string& limit = value("--memory-limit");
      cl.memory_limit_gib =
          limit == "off" ? 0.0
                         : parse_positive(limit, "--memory-limit", "GiB",
                                          "a memory per host in GiB, > 0, or off (no check)");
    } else if (a == "--version") {
      cl.command = "version";
      return cl;
    } else if (a.rfind("--", 0) == 0) {
      // Catena's options have two dashes, PETSc's one: a misspelt option of Catena's
      // (--restrat) would otherwise go to PETSc unnoticed and the run go on without it (a
      // fresh run over the output it was to continue).
      throw InputError({"", 0, "arguments"},
                       "unknown option '" + a + "' for " + cl.command +
                           "; accepted: " + command_options(cl.command) + " ('catena " +
                           cl.command + " --help'), and PETSc's options with one dash (-ksp_view)");
    } else if (!a.empty() && a[0] == '-') {
      // A PETSc option; skip its value if it has one: the next token, unless it starts
      // with '-' or names the scene file (a .yaml/.yml path).
      cl.petsc_options.push_back(a);
      if (i + 1 < args.size() && !args[i + 1].empty() && args[i + 1][0] != '-' &&
          !(cl.scene.empty() && is_scene_path(args[i + 1])))
        ++i;
    } else if (cl.scene.empty()) {
      cl.scene = a;
    } else {
      throw InputError({"", 0, "arguments"}, "unexpected argument '" + a +
                                                 "': one scene file is accepted (got '" + cl.scene +
                                                 "' already)");
    }
  }
  if (cl.scene.empty())
    throw InputError({"", 0, "SCENE"},
                     "no scene file given; usage: catena " + cl.command + " SCENE.yaml");
  if (cl.command == "study" && cl.study.steps_given && cl.study.methods.empty())
    throw InputError({"", 0, "--steps"},
                     "--steps sets the steps of the --methods presets; without --methods, "
                     "vary the step itself (--vary integrator.dt=V1,V2,...)");
  if (cl.command == "sweep" && cl.study.vary.empty())
    throw InputError({"", 0, "--vary"},
                     "a sweep needs at least one --vary KEY=V1,V2,... (e.g. --vary "
                     "pantographs[0].speed_kmh=200,250,300); docs/study.md");
  if (cl.command == "study" && cl.study.vary.empty() && cl.study.methods.empty())
    throw InputError({"", 0, "--vary"},
                     "a study needs at least one --vary KEY=V1,V2,... (e.g. --vary "
                     "integrator.dt=1e-3,5e-4,2.5e-4) or --methods (e.g. --methods all); "
                     "docs/study.md");
  if (cl.output) cl.overrides.push_back("output.file=" + *cl.output);
  return cl;
}

}  // namespace catena::app

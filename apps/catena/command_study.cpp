// `catena study SCENE --vary KEY=V1,V2,...`: runs a dynamic scene under every combination of
// the varied values and a reference, measures each run's errors against the reference
// and its cost, and writes DIR/study.csv (+ DIR/study.png) with a recommendation
// (docs/study.md). The cases run as `catena run` would, each on a group of
// --ranks-per-case ranks, the groups taking cases from one queue; each case's console
// output goes to DIR/cases/NAME.log (its progress lines also to the console), its results
// to DIR/cases/NAME.h5, and a record of
// its end to DIR/cases/NAME.result, so that the same command again resumes the study.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "case_console.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/output_error.hpp"
#include "catena/io/run_files.hpp"
#include "catena/model/scene_identity.hpp"
#include "catena/post/contact_statistics.hpp"
#include "catena/study/case_measures.hpp"
#include "catena/study/case_queue.hpp"
#include "catena/study/case_record.hpp"
#include "catena/study/study_plan.hpp"
#include "catena/study/study_table.hpp"
#include "commands.hpp"
#include "scene_loading.hpp"
#include "study_report.hpp"

namespace catena::app {
namespace {

namespace fs = std::filesystem;

struct StudyCase {
  study::StudyRow row;                 // name, role, method, setting (filled as it runs)
  std::vector<std::string> overrides;  // the case's own, after the study's --set ones
  std::string scene;  // what it runs: a digest of the scene after every override (records)
};

std::string default_directory(const std::string& scene) {
  return fs::path(scene).stem().string() + "_study";
}

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The overrides for people: the keys a varied integrator type removes ("key=~") are left out.
std::string list_text(const std::vector<std::string>& overrides) {
  std::string out;
  for (const std::string& o : overrides)
    if (o.size() < 2 || o.compare(o.size() - 2, 2, "=~") != 0) out += (out.empty() ? "" : " ") + o;
  return out.empty() ? "(the scene as it is)" : out;
}

// The settings and the reference of a study, before they become cases.
struct StudyPlan {
  std::vector<study::Setting> settings;
  study::ReferencePlan reference;
  std::string scene_method;  // the scene's integrator type: the method of unlabelled settings
};

// Collective over `world` (reads the scene). --vary's settings, or --methods' with the
// other variations; the reference given or the default one.
StudyPlan plan_settings(MPI_Comm world, const CommandLine& cl, const fs::path& directory) {
  const StudyArguments& args = cl.study;
  std::vector<study::Variation> variations;
  for (const std::string& v : args.vary) variations.push_back(study::parse_variation(v));
  const model::Model base = load_scene(world, cl.scene, cl.overrides);
  if (base.analysis != model::AnalysisType::dynamic)
    throw InputError({cl.scene, 0, "analysis.type"},
                     "a study compares dynamic runs; this scene's analysis is static");
  const double scene_dt = base.dynamic_options.integrator.dt;
  StudyPlan plan;
  plan.scene_method = base.dynamic_options.integrator.type;
  if (args.methods.empty()) {
    plan.settings = study::expand(variations);
  } else {
    study::MethodContext context;
    context.scene_dt = scene_dt;
    context.scene_nonlinear = base.dynamic_options.structure == model::StructureModel::nonlinear;
    context.modal_basis = (directory / "modal_basis.h5").string();
    plan.settings = study::expand_methods(args.methods, args.steps, variations, context);
    // The reference refines the smallest step any method takes.
    study::Variation steps{"integrator.dt", {}};
    for (const study::Setting& s : plan.settings)
      for (const auto& [key, value] : s.values)
        if (key == "integrator.dt" &&
            std::find(steps.values.begin(), steps.values.end(), value) == steps.values.end())
          steps.values.push_back(value);
    variations.push_back(steps);
  }
  plan.reference = args.reference.empty() ? study::default_reference(variations, scene_dt)
                                          : study::given_reference(args.reference);
  return plan;
}

// Not collective (every rank the same). What would stop the comparison after every case has
// run is refused before any runs: a probe id the scene does not have, contact forces sampled
// too coarsely for the statistics' low-pass.
void check_measurable(const CommandLine& cl, const StudyCase& c, const model::Model& m) {
  for (long long id : cl.study.probes)
    if (std::none_of(m.nodes.begin(), m.nodes.end(),
                     [&](const model::Node& n) { return n.id == id; }))
      throw InputError({cl.scene, 0, "--probe"},
                       "no node with id " + std::to_string(id) + " in the scene" +
                           (c.overrides.empty() ? "" : " under " + list_text(c.overrides)) +
                           "; catena check --ids lists a catenary's nodes");
  const double coarsest = 1.0 / (post::min_sampling_rate_per_cutoff * cl.study.cutoff_hz);
  if (!m.contacts.empty() && m.output.interval > coarsest * (1.0 + 1e-9))
    throw InputError({cl.scene, 0, "output.interval"},
                     "output.interval = " + study::number_text(m.output.interval) + " s" +
                         (c.overrides.empty() ? "" : " under " + list_text(c.overrides)) +
                         " samples the contact force too coarsely for the statistics' " +
                         study::number_text(cl.study.cutoff_hz) +
                         " Hz low-pass; accepted: at most " + study::number_text(coarsest) +
                         " s (--set output.interval=...)");
}

// Collective over `world`. The cases: the reference first (the most expensive, so it does
// not start last), its check, then the settings; every case's scene is loaded once here so
// that a typo in a value stops the study before anything runs. The check is left out when
// a setting is the same run.
std::vector<StudyCase> plan_cases(MPI_Comm world, const CommandLine& cl, const StudyPlan& plan) {
  std::vector<StudyCase> cases;
  auto add = [&](const std::string& name, const std::string& role, const std::string& method,
                 const std::string& setting, const std::vector<std::string>& overrides) {
    StudyCase c;
    c.row.name = name;
    c.row.role = role;
    c.row.method = method;
    c.row.setting = setting;
    c.overrides = overrides;
    cases.push_back(std::move(c));
  };
  const study::ReferencePlan& reference = plan.reference;
  add("reference", "reference", "reference", list_text(reference.overrides), reference.overrides);
  if (!reference.check_overrides.empty())
    add("reference_check", "reference_check", "reference", list_text(reference.check_overrides),
        reference.check_overrides);
  std::set<std::string> names = {"reference", "reference_check"};
  for (const study::Setting& s : plan.settings) {
    const std::string method = s.method().empty() ? plan.scene_method : s.method();
    const std::string stem = study::case_stem(method, s.resolution());
    std::string name = stem;
    for (int k = 2; !names.insert(name).second; ++k) name = stem + "_" + std::to_string(k);
    add(name, "setting", method, s.resolution(), s.overrides());
  }
  if (mpi_rank(world) == 0) {
    std::printf("study: checking the scene under %zu settings\n", cases.size());
    std::fflush(stdout);
  }
  std::vector<std::string> identities;
  for (const StudyCase& c : cases) {
    const model::Model m = load_scene(world, cl.scene, joined(cl.overrides, c.overrides));
    if (m.analysis != model::AnalysisType::dynamic)
      throw InputError({cl.scene, 0, "analysis.type"},
                       "the setting " + list_text(c.overrides) + " makes the analysis static");
    check_measurable(cl, c, m);
    identities.push_back(model::scene_identity(m.source_text) + "duration " +
                         study::number_text(m.dynamic_options.duration));
  }
  for (std::size_t i = 0; i < cases.size(); ++i) cases[i].scene = study::digest(identities[i]);
  if (cases.size() > 1 && cases[1].row.role == "reference_check")
    for (std::size_t i = 2; i < cases.size(); ++i)
      if (identities[i] == identities[1]) {
        cases[i].row.role = "setting+reference_check";  // one run, both roles
        cases.erase(cases.begin() + 1);
        break;
      }
  return cases;
}

// Collective over the group. Runs one case as `catena run` would; returns its record.
study::CaseRecord run_case(MPI_Comm group, const CommandLine& cl, const StudyCase& c,
                           const fs::path& cases_dir) {
  study::CaseRecord record;
  record.overrides = c.overrides;
  record.scene = c.scene;
  CommandLine run = cl;
  run.command = "run";
  run.overrides = joined(joined(cl.overrides, c.overrides),
                         {"output.file=" + (cases_dir / (c.row.name + ".h5")).string()});
  run.progress_seconds = 30.0;
  // A case stopped midway (SIGTERM, the study killed after a checkpoint) continues from its
  // checkpoint; one the run refuses (another scene's: the setting changed) is run afresh.
  const std::string output = (cases_dir / (c.row.name + ".h5")).string();
  int resume = mpi_rank(group) == 0 && fs::exists(io::checkpoint_path(output));
  MPI_Bcast(&resume, 1, MPI_INT, 0, group);
  const double start = MPI_Wtime();
  {
    const CaseConsole console(cases_dir / (c.row.name + ".log"), c.row.name);
    try {
      if (resume) {
        run.restart = true;
        try {
          command_run(group, run);
        } catch (const InputError& e) {
          if (mpi_rank(group) == 0)
            std::printf("study: not continued from %s (%s): running from the start\n",
                        io::checkpoint_path(output).c_str(), e.what());
          run.restart = false;
          command_run(group, run);
        }
      } else {
        command_run(group, run);
      }
      record.completed = true;
    } catch (const InputError& e) {
      record.exit_code = 2;
      record.message = e.what();
    } catch (const NumericalError& e) {
      record.exit_code = 3;
      record.message = e.what();
    } catch (const OutputError& e) {
      record.exit_code = 4;
      record.message = e.what();
    }
    if (!record.completed && mpi_rank(group) == 0)
      std::fprintf(stderr, "catena: study case %s stopped: %s\n", c.row.name.c_str(),
                   record.message.c_str());
  }
  record.wall_seconds = MPI_Wtime() - start;
  // A completed case is not extended: its checkpoint (the size of the state) is not kept.
  if (record.completed && mpi_rank(group) == 0) {
    std::error_code ignored;
    fs::remove(io::checkpoint_path(output), ignored);
  }
  return record;
}

// Collective over the group. Whether the case's record shows it done with these settings
// (and its output is there, if it completed): a resumed study keeps it.
bool done_before(const study::CaseGroups& groups, const StudyCase& c, const fs::path& cases_dir) {
  int done = 0;
  if (groups.leader()) {
    const auto old = study::read_record(cases_dir / (c.row.name + ".result"));
    done = old && old->overrides == c.overrides && old->scene == c.scene &&
           (!old->completed || fs::exists(cases_dir / (c.row.name + ".h5")));
  }
  MPI_Bcast(&done, 1, MPI_INT, 0, groups.group());
  return done != 0;
}

// Collective over `world`: the groups take cases from the queue until none is left, or until
// a case is interrupted (SIGTERM, or the stop testing hook): then no group takes another
// case, and the interruption is returned on every rank (signal 0: none). The errors of a
// run are every rank's of its group (run_case records them); anything else thrown here
// (a record that cannot be written, memory) is one rank's, and the ranks could not meet
// again: it aborts the study.
RunInterrupted run_cases(MPI_Comm world, const CommandLine& cl, const std::vector<StudyCase>& cases,
                         const fs::path& cases_dir) {
  const study::CaseGroups groups(world, cl.study.ranks_per_case);
  study::CaseQueue queue(world);
  if (mpi_rank(world) == 0) {
    std::printf("study: %zu cases on %d group%s of %d rank%s; logs in %s\n", cases.size(),
                groups.count(), groups.count() == 1 ? "" : "s", cl.study.ranks_per_case,
                cl.study.ranks_per_case == 1 ? "" : "s", cases_dir.c_str());
    std::fflush(stdout);
  }
  RunInterrupted interrupted;
  try {
    for (long k = queue.take(groups); k < static_cast<long>(cases.size()); k = queue.take(groups)) {
      const StudyCase& c = cases[static_cast<std::size_t>(k)];
      const fs::path record_path = cases_dir / (c.row.name + ".result");
      if (done_before(groups, c, cases_dir)) {
        if (groups.leader())
          std::printf("study: case %ld/%zu %s (%s): done before, kept\n", k + 1, cases.size(),
                      c.row.name.c_str(), list_text(c.overrides).c_str());
        std::fflush(stdout);
        continue;
      }
      if (groups.leader()) {
        std::printf("study: case %ld/%zu %s (%s) started on group %d\n", k + 1, cases.size(),
                    c.row.name.c_str(), list_text(c.overrides).c_str(), groups.index());
        std::fflush(stdout);
        std::error_code ignored;
        fs::remove(record_path, ignored);
      }
      study::CaseRecord record;
      try {
        record = run_case(groups.group(), cl, c, cases_dir);
      } catch (const RunInterrupted& stop) {
        interrupted = stop;  // no record: a study run again continues it from its checkpoint
        queue.stop(groups);
        continue;
      }
      if (groups.leader()) {
        study::write_record(record_path, record);
        std::printf("study: case %ld/%zu %s %s in %.1f s%s%s\n", k + 1, cases.size(),
                    c.row.name.c_str(), record.completed ? "completed" : "failed",
                    record.wall_seconds, record.completed ? "" : ": ",
                    record.completed ? "" : record.message.c_str());
        std::fflush(stdout);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "catena: study: %s; stopping every rank\n", e.what());
    std::fflush(stderr);
    MPI_Abort(world, 1);
  }
  MPI_Barrier(world);
  // The same interruption on every rank: the signal and the latest time reached.
  int signal = interrupted.signal;
  double time = interrupted.time;
  MPI_Allreduce(MPI_IN_PLACE, &signal, 1, MPI_INT, MPI_MAX, world);
  MPI_Allreduce(MPI_IN_PLACE, &time, 1, MPI_DOUBLE, MPI_MAX, world);
  return RunInterrupted{signal, time};
}

// Rank 0 of the study. Reads every case's record and output, measures it against the
// reference, and reports.
void report(const CommandLine& cl, std::vector<StudyCase>& cases, const fs::path& directory,
            const std::string& reference_description) {
  const fs::path cases_dir = directory / "cases";
  std::vector<study::StudyRow> rows;
  for (StudyCase& c : cases) {
    study::StudyRow& row = c.row;
    const auto record = study::read_record(cases_dir / (row.name + ".result"));
    if (!record) throw Error("study: no record of case " + row.name + " in " + cases_dir.string());
    row.completed = record->completed;
    row.exit_code = record->exit_code;
    row.message = record->message;
    row.case_seconds = record->wall_seconds;
    if (row.completed) row.work = io::read_run_work((cases_dir / (row.name + ".h5")).string());
  }
  if (!cases.front().row.completed)
    throw NumericalError("study: the reference run failed (" + cases.front().row.message +
                         "); see " + (cases_dir / "reference.log").string() +
                         ", or give another with --reference KEY=VALUE");
  std::vector<std::int64_t> probes(cl.study.probes.begin(), cl.study.probes.end());
  const study::ReferenceRun reference((cases_dir / "reference.h5").string(), probes,
                                      cl.study.cutoff_hz);
  for (StudyCase& c : cases) {
    study::StudyRow& row = c.row;
    if (row.completed && row.role != "reference") {
      try {
        row.errors = reference.errors_of((cases_dir / (row.name + ".h5")).string());
      } catch (const InputError& e) {
        row.message = std::string("not compared: ") + e.what();
      }
    }
    rows.push_back(row);
  }
  write_study_report(cl, rows, reference, directory, reference_description);
}

}  // namespace

void command_study(MPI_Comm world, const CommandLine& cl) {
  const fs::path directory = cl.study.directory.empty() ? fs::path(default_directory(cl.scene))
                                                        : fs::path(cl.study.directory);
  const fs::path cases_dir = directory / "cases";
  for (const std::string& t : cl.study.targets) study::parse_target(t);  // bad ones stop here
  study::check_ranks_per_case(world, cl.study.ranks_per_case);
  const StudyPlan plan = plan_settings(world, cl, directory);
  const std::string& reference_description = plan.reference.description;
  std::vector<StudyCase> cases = plan_cases(world, cl, plan);
  std::string why;
  if (mpi_rank(world) == 0) {
    std::error_code ec;
    fs::create_directories(cases_dir, ec);
    if (ec) why = "cannot create " + cases_dir.string() + ": " + ec.message();
    std::printf("study: %s; reference: %s\n", cl.scene.c_str(), reference_description.c_str());
    std::fflush(stdout);
  }
  broadcast_string(world, why);
  if (!why.empty()) throw InputError({cases_dir.string(), 0, "-o"}, why);
  const RunInterrupted stop = run_cases(world, cl, cases, cases_dir);
  if (stop.signal != 0) throw stop;  // the queue and the groups freed on every rank
  if (mpi_rank(world) == 0) report(cl, cases, directory, reference_description);
}

}  // namespace catena::app

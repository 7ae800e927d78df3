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

#include "case_runner.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/output_error.hpp"
#include "catena/io/run_files.hpp"
#include "catena/model/scene_identity.hpp"
#include "catena/study/case_measures.hpp"
#include "catena/study/case_queue.hpp"
#include "catena/study/case_record.hpp"
#include "catena/study/richardson.hpp"
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

std::vector<QueuedCase> queued(const std::vector<StudyCase>& cases) {
  std::vector<QueuedCase> out;
  for (const StudyCase& c : cases) out.push_back({c.row.name, c.overrides, c.scene});
  return out;
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
void check_measurable(const CommandLine& cl, const QueuedCase& c, const model::Model& m) {
  for (long long id : cl.study.probes)
    if (std::none_of(m.nodes.begin(), m.nodes.end(),
                     [&](const model::Node& n) { return n.id == id; }))
      throw InputError({cl.scene, 0, "--probe"},
                       "no node with id " + std::to_string(id) + " in the scene" +
                           (c.overrides.empty() ? "" : " under " + list_text(c.overrides)) +
                           "; catena check --ids lists a catenary's nodes");
  check_contact_sampling(cl, c, m);
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
    add(unique_name(names, study::case_stem(method, s.resolution())), "setting", method,
        s.resolution(), s.overrides());
  }
  if (mpi_rank(world) == 0) {
    std::printf("study: checking the scene under %zu settings\n", cases.size());
    std::fflush(stdout);
  }
  const std::vector<QueuedCase> to_check = queued(cases);
  const std::vector<std::string> identities = check_scenes(
      world, cl, to_check,
      [&](std::size_t i, const model::Model& m) { check_measurable(cl, to_check[i], m); });
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
  // The error bar each case would report by itself (catena run --error-bar), where the
  // study ran its method at 2 and 4 times its step: set beside its true error.
  const auto siblings = study::dt_siblings(rows);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!siblings[i]) continue;
    const auto file = [&](std::size_t j) { return (cases_dir / (rows[j].name + ".h5")).string(); };
    try {
      const study::ReferenceRun own(file(i), reference.probes(), cl.study.cutoff_hz);
      rows[i].estimates = study::worst_estimates(
          study::richardson_error_bar(own.errors_by_part(file(siblings[i]->at_2dt)),
                                      own.errors_by_part(file(siblings[i]->at_4dt))));
    } catch (const InputError&) {
      // Not comparable with its siblings (a record that ends early): no error bar.
    }
  }
  write_study_report(cl, rows, reference, directory, reference_description);
}

}  // namespace

void command_study(MPI_Comm world, const CommandLine& cl) {
  const fs::path directory = command_directory(cl, "_study");
  const fs::path cases_dir = directory / "cases";
  for (const std::string& t : cl.study.targets) study::parse_target(t);  // bad ones stop here
  study::check_ranks_per_case(world, cl.study.ranks_per_case);
  const StudyPlan plan = plan_settings(world, cl, directory);
  const std::string& reference_description = plan.reference.description;
  std::vector<StudyCase> cases = plan_cases(world, cl, plan);
  create_cases_directory(world, cases_dir);
  if (mpi_rank(world) == 0) {
    std::printf("study: %s; reference: %s\n", cl.scene.c_str(), reference_description.c_str());
    std::fflush(stdout);
  }
  const RunInterrupted stop = run_cases(world, cl, queued(cases), cases_dir);
  if (stop.signal != 0) throw stop;  // the queue and the groups freed on every rank
  if (mpi_rank(world) == 0) report(cl, cases, directory, reference_description);
}

}  // namespace catena::app

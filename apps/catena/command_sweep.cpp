// `catena sweep SCENE --vary pantographs[0].speed_kmh=200,250,300`: runs a pantograph scene
// under every combination of the varied values and tabulates each run's EN 50318
// contact-force statistics per pantograph: DIR/sweep.csv and DIR/sweep.png (the statistics
// against the first varied value). The cases run as `catena study`'s do (case_runner.hpp:
// groups of --ranks-per-case ranks, one queue, per-case logs and records, resumable).
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "case_runner.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/atomic_file.hpp"
#include "catena/io/contact_run_reader.hpp"
#include "catena/io/run_summary_reader.hpp"
#include "catena/post/contact_statistics.hpp"
#include "catena/study/case_queue.hpp"
#include "catena/study/case_record.hpp"
#include "catena/study/study_plan.hpp"
#include "catena/study/study_table.hpp"
#include "commands.hpp"
#include "plot_script.hpp"

namespace catena::app {
namespace {

namespace fs = std::filesystem;

// One pantograph of one case: the statistics, or why there are none.
struct SweepRow {
  const QueuedCase* c = nullptr;
  const study::Setting* setting = nullptr;  // the values of the varied keys
  std::string pantograph;
  std::string status;  // completed | failed (exit N) | not measured
  post::ContactStatistics statistics;
  io::RunWork work;
  std::string message;
};

std::vector<SweepRow> measure(const std::vector<QueuedCase>& cases,
                              const std::vector<study::Setting>& settings,
                              const fs::path& cases_dir, double cutoff_hz) {
  std::vector<SweepRow> rows;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const QueuedCase& c = cases[i];
    const study::Setting* setting = &settings[i];
    const auto record = study::read_record(cases_dir / (c.name + ".result"));
    if (!record) throw Error("sweep: no record of case " + c.name);
    if (!record->completed) {
      rows.push_back({&c,
                      setting,
                      "",
                      "failed (exit " + std::to_string(record->exit_code) + ")",
                      {},
                      {},
                      record->message});
      continue;
    }
    const std::string path = (cases_dir / (c.name + ".h5")).string();
    try {
      const io::ContactRun run = io::read_contact_run(path);
      const io::RunWork work = io::read_run_work(path);
      const post::EvaluationSection section = io::evaluation_section_or_record(run);
      for (const post::PantographRecord& p : run.pantographs)
        rows.push_back(
            {&c, setting, p.name, "completed",
             post::contact_statistics(p, run.registration_points, {run.dt, cutoff_hz, section}),
             work, ""});
    } catch (const InputError& e) {
      rows.push_back({&c, setting, "", "not measured", {}, {}, e.what()});
    }
  }
  return rows;
}

std::string csv_text(const std::vector<study::Variation>& variations,
                     const std::vector<SweepRow>& rows) {
  std::string out = "case";
  auto cell = [&](const std::string& text) { out.append(",").append(text); };
  for (const study::Variation& v : variations) cell(study::csv_field(v.key));
  out +=
      ",pantograph,status,samples,mean_N,std_N,stat_max_N,stat_min_N,max_N,min_N,"
      "contact_loss_percent,max_uplift_at_support_mm,steps,wall_seconds,"
      "wall_per_simulated_second,message\n";
  for (const SweepRow& r : rows) {
    out += study::csv_field(r.c->name);
    for (const auto& [key, value] : r.setting->values) cell(study::csv_field(value));
    cell(study::csv_field(r.pantograph));
    cell(r.status);
    const bool ok = r.status == "completed";
    const post::ContactStatistics& s = r.statistics;
    auto stat = [&](double x) { cell(ok ? study::number_text(x) : std::string()); };
    cell(ok ? std::to_string(s.n_samples) : std::string());
    for (double x : {s.mean, s.standard_deviation, s.statistical_max, s.statistical_min, s.max,
                     s.min, s.contact_loss_percent})
      stat(x);
    cell(ok && s.max_uplift_at_support ? study::number_text(1e3 * *s.max_uplift_at_support)
                                       : std::string());
    cell(ok ? std::to_string(r.work.steps_accepted) : std::string());
    stat(study::stepping_seconds(r.work));
    stat(study::stepping_per_simulated_second(r.work));
    cell(study::csv_field(r.message));
    out += "\n";
  }
  return out;
}

void print_table(const std::vector<SweepRow>& rows) {
  std::printf("\n%-32s %-12s %8s %8s %8s %8s %8s %8s %6s %7s %8s\n", "case", "pantograph", "mean",
              "std", "stat_max", "stat_min", "max", "min", "loss", "uplift", "[s/s]");
  std::printf("%-32s %-12s %8s %8s %8s %8s %8s %8s %6s %7s\n", "", "", "N", "N", "N", "N", "N", "N",
              "%", "mm");
  for (const SweepRow& r : rows) {
    if (r.status != "completed") {
      std::printf("%-32s %s: %s\n", r.c->name.c_str(), r.status.c_str(), r.message.c_str());
      continue;
    }
    const post::ContactStatistics& s = r.statistics;
    char uplift[32] = "-";
    if (s.max_uplift_at_support)
      std::snprintf(uplift, sizeof uplift, "%.2f", 1e3 * *s.max_uplift_at_support);
    std::printf("%-32s %-12s %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %6.2f %7s %8.3f\n",
                r.c->name.c_str(), r.pantograph.c_str(), s.mean, s.standard_deviation,
                s.statistical_max, s.statistical_min, s.max, s.min, s.contact_loss_percent, uplift,
                study::stepping_per_simulated_second(r.work));
  }
}

void plot(const fs::path& csv, const fs::path& png) {
  draw_plot("plot_sweep.py", {csv.string(), png.string()}, png.string());
}

}  // namespace

void command_sweep(MPI_Comm world, const CommandLine& cl) {
  const fs::path directory = command_directory(cl, "_sweep");
  const fs::path cases_dir = directory / "cases";
  study::check_ranks_per_case(world, cl.study.ranks_per_case);
  std::vector<study::Variation> variations;
  for (const std::string& v : cl.study.vary) variations.push_back(study::parse_variation(v));
  const std::vector<study::Setting> settings = study::expand(variations);
  std::vector<QueuedCase> cases;
  std::set<std::string> names;
  for (const study::Setting& s : settings)
    cases.push_back(
        {unique_name(names, study::case_stem(s.method(), s.resolution())), s.overrides(), ""});
  if (mpi_rank(world) == 0) {
    std::printf("sweep: checking the scene under %zu settings\n", cases.size());
    std::fflush(stdout);
  }
  const std::vector<std::string> identities =
      check_scenes(world, cl, cases, [&](std::size_t i, const model::Model& m) {
        if (m.contacts.empty())
          throw InputError({cl.scene, 0, "pantographs"},
                           "a sweep tabulates contact-force statistics; the scene under " +
                               list_text(cases[i].overrides) +
                               " has no pantographs (catena study compares other scenes)");
        check_contact_sampling(cl, cases[i], m);
      });
  for (std::size_t i = 0; i < cases.size(); ++i) cases[i].scene = study::digest(identities[i]);
  create_cases_directory(world, cases_dir);
  const RunInterrupted stop = run_cases(world, cl, cases, cases_dir);
  if (stop.signal != 0) throw stop;
  if (mpi_rank(world) != 0) return;
  const std::vector<SweepRow> rows = measure(cases, settings, cases_dir, cl.study.cutoff_hz);
  const fs::path csv = directory / "sweep.csv";
  io::write_file_atomically(csv, csv_text(variations, rows));
  std::printf("\nsweep: %s, EN 50318 statistics per pantograph (low-pass %g Hz)\n",
              cl.scene.c_str(), cl.study.cutoff_hz);
  print_table(rows);
  std::printf("\ntable: %s\n", csv.c_str());
  plot(csv, directory / "sweep.png");
  std::fflush(stdout);
}

}  // namespace catena::app

#include "study_report.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "catena/io/atomic_file.hpp"
#include "plot_script.hpp"

namespace catena::app {
namespace {

namespace fs = std::filesystem;

// The measure a study is judged and plotted by: σ's error with pantographs, else the
// probes' RMS distance.
const char* headline_measure(const study::ReferenceRun& reference) {
  return reference.has_pantographs() ? "std" : "probe_rms";
}

std::string shown(double x, const char* format) {
  if (!std::isfinite(x)) return "-";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, format, x);
  return buffer;
}

void print_table(const std::vector<study::StudyRow>& rows, const study::ReferenceRun& reference) {
  const bool contact = reference.has_pantographs();
  std::printf("\n%-24s %-24s %-24s %7s %9s %8s %7s %6s", "case", "method", "setting", "steps",
              "wall [s]", "[s/s]", "Newton", "fact.");
  if (contact)
    std::printf(" %9s %8s %8s %8s %8s\n", "F rms [N]", "mean %", "std %", "max %", "uplift %");
  else
    std::printf(" %11s %11s\n", "probe rms", "probe max");
  for (const study::StudyRow& r : rows) {
    if (!r.completed) {
      std::printf("%-24s %-24s %-24s failed (exit %d): %s\n", r.name.c_str(), r.method.c_str(),
                  r.setting.c_str(), r.exit_code, r.message.c_str());
      continue;
    }
    const io::RunWork& w = r.work;
    std::printf("%-24s %-24s %-24s %7lld %9.2f %8.3f %7lld %6lld", r.name.c_str(), r.method.c_str(),
                r.setting.c_str(), static_cast<long long>(w.steps_accepted),
                study::stepping_seconds(w), study::stepping_per_simulated_second(w),
                static_cast<long long>(w.newton_iterations),
                static_cast<long long>(w.factorizations));
    const study::CaseErrors& e = r.errors;
    if (contact)
      std::printf(" %9s %8s %8s %8s %8s\n", shown(e.force_rms_filtered, "%.3g").c_str(),
                  shown(e.mean, "%+.3f").c_str(), shown(e.std, "%+.3f").c_str(),
                  shown(e.max, "%+.3f").c_str(), shown(e.uplift, "%+.3f").c_str());
    else
      std::printf(" %11s %11s\n", shown(e.probe_rms, "%.3e").c_str(),
                  shown(e.probe_max, "%.3e").c_str());
    if (!r.message.empty()) std::printf("  (%s)\n", r.message.c_str());
  }
}

void print_reference_check(const std::vector<study::StudyRow>& rows,
                           const study::ReferenceRun& reference) {
  const char* measure = headline_measure(reference);
  for (const study::StudyRow& r : rows) {
    if (r.role.find("reference_check") == std::string::npos || !r.completed) continue;
    const double change = study::measure_value(r.errors, measure);
    double smallest = HUGE_VAL;
    for (const study::StudyRow& s : rows)
      if (s.role.rfind("setting", 0) == 0 && s.completed && &s != &r) {
        const double v = std::abs(study::measure_value(s.errors, measure));
        if (std::isfinite(v) && v > 0) smallest = std::min(smallest, v);
      }
    std::printf(
        "\nreference check: the reference differs from its unrefined run (%s) by %s = %s%s "
        "(force RMS %s N);\n  errors well above that are measured; errors near it are not "
        "resolved by this reference%s\n",
        r.name.c_str(), measure, shown(change, "%.3g").c_str(),
        reference.has_pantographs() ? " %" : " m",
        shown(r.errors.force_rms_filtered, "%.3g").c_str(),
        std::isfinite(smallest) && std::abs(change) > smallest / 3
            ? " — WARNING: the smallest error of a setting is within 3x of it: give a finer "
              "--reference"
            : "");
  }
}

void print_recommendation(const CommandLine& cl, const std::vector<study::StudyRow>& rows,
                          const study::ReferenceRun& reference) {
  std::vector<study::Target> targets;
  for (const std::string& t : cl.study.targets) targets.push_back(study::parse_target(t));
  if (targets.empty()) {
    if (!reference.has_pantographs()) return;
    targets.push_back(study::parse_target("std=1%"));
  }
  std::string wanted;
  for (const study::Target& t : targets) wanted += (wanted.empty() ? "" : ", ") + t.text;
  const auto best = study::recommend(rows, targets);
  if (!best) {
    std::printf("\nrecommendation: no setting meets %s; refine the tightest setting\n",
                wanted.c_str());
    return;
  }
  const study::StudyRow& r = rows[*best];
  std::printf(
      "\nrecommendation: %s %s — the cheapest setting within %s: %.2f s of time stepping "
      "(%.3f s per simulated second)\n",
      r.method.c_str(), r.setting.c_str(), wanted.c_str(), study::stepping_seconds(r.work),
      study::stepping_per_simulated_second(r.work));
}

void plot(const fs::path& csv, const fs::path& png, const char* measure) {
  draw_plot("plot_study.py", {csv.string(), png.string(), measure}, png.string());
}

}  // namespace

void write_study_report(const CommandLine& cl, const std::vector<study::StudyRow>& rows,
                        const study::ReferenceRun& reference, const fs::path& directory,
                        const std::string& reference_description) {
  const fs::path csv = directory / "study.csv";
  io::write_file_atomically(csv, study::csv_text(rows));

  std::printf("\nstudy: %s; reference: %s\n", cl.scene.c_str(), reference_description.c_str());
  if (reference.has_pantographs())
    std::printf("errors over the evaluation section [%g, %g] m, statistics at %g Hz\n",
                reference.section().x_start, reference.section().x_end, cl.study.cutoff_hz);
  else {
    std::string ids;
    for (auto id : reference.probes()) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
    std::printf("errors: distance of probe node%s %s from the reference's trajectory\n",
                reference.probes().size() == 1 ? "" : "s", ids.c_str());
  }
  print_table(rows, reference);
  print_reference_check(rows, reference);
  print_recommendation(cl, rows, reference);
  std::printf("\ntable: %s\n", csv.c_str());
  plot(csv, directory / "study.png", headline_measure(reference));
  std::fflush(stdout);
}

}  // namespace catena::app

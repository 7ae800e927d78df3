// `catena stats OUT.h5 [--json] [--section X0 X1] [--cutoff HZ] [--ranges R]`: the EN 50318
// contact-force statistics per pantograph of a dynamic run, checked against the acceptance
// ranges when the scene declares them (docs/output.md, "Contact-force statistics"). Serial: rank 0
// reads and prints; under mpirun the other ranks only wait.
//
//   catena stats en50318_250.h5                         # the run's evaluation section
//   catena stats en50318_250.h5 --section 240 360 --json
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/error_bar_record.hpp"
#include "commands.hpp"
#include "error_bar.hpp"
#include "rank_zero.hpp"
#include "run_statistics.hpp"

namespace catena::app {
namespace {

// Shortest decimal that reads back as the same double; null for NaN/inf (not JSON).
std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return ec == std::errc() ? std::string(buffer, end) : "null";
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string json_section(const post::EvaluationSection& s) {
  // Appended, not "[" + ...: GCC 12 warns falsely (-Wrestrict) on a literal + a temporary.
  std::string out = "[";
  out.append(json_number(s.x_start)).append(", ").append(json_number(s.x_end)).append("]");
  return out;
}

std::string json_acceptance(const PantographEvaluation& e, const std::string& ranges) {
  if (!e.acceptance) return "null";
  std::string out = "{\"ranges\": " + json_string(ranges) +
                    ", \"passed\": " + std::to_string(checks_passed(*e.acceptance)) +
                    ", \"total\": " + std::to_string(e.acceptance->size()) + ", \"checks\": [";
  for (std::size_t i = 0; i < e.acceptance->size(); ++i) {
    const post::AcceptanceCheck& c = (*e.acceptance)[i];
    out += i ? ", " : "";
    out += "{\"statistic\": " + json_string(c.statistic) + ", \"unit\": " + json_string(c.unit) +
           ", \"low\": " + json_number(c.low) + ", \"high\": " + json_number(c.high) +
           ", \"value\": " + (c.value ? json_number(*c.value) : "null") +
           ", \"pass\": " + (c.pass ? "true" : "false") + "}";
  }
  return out + "]}";
}

// The run's error bar (catena run --error-bar) as JSON, "null" without one.
std::string json_error_bar(const std::optional<io::ErrorBarRecord>& bar) {
  if (!bar) return "null";
  std::string out = "{\"dt\": " + json_number(bar->dt) + ", \"coarse_dt\": [";
  for (std::size_t i = 0; i < bar->coarse_dt.size(); ++i)
    out += (i ? ", " : "") + json_number(bar->coarse_dt[i]);
  out += "], \"entries\": [";
  for (std::size_t i = 0; i < bar->entries.size(); ++i) {
    const io::ErrorBarEntry& e = bar->entries[i];
    out += i ? ", " : "";
    out += "{\"part\": " + json_string(e.part) + ", \"measure\": " + json_string(e.measure) +
           ", \"estimate\": " + json_number(e.estimate) + ", \"order\": " + json_number(e.order) +
           ", \"unit\": " + json_string(e.unit) + "}";
  }
  return out + "]}";
}

// The run's error bar under the table, if it has one.
void print_error_bar(const std::optional<io::ErrorBarRecord>& bar) {
  if (!bar) return;
  std::printf("\nerror bar of the run (catena run --error-bar: dt %g s against", bar->dt);
  for (std::size_t i = 0; i < bar->coarse_dt.size(); ++i)
    std::printf("%s %g s", i ? " and" : "", bar->coarse_dt[i]);
  std::printf(
      "; over the run's own evaluation section, the whole record without one, at 20 Hz):\n");
  print_error_bar_entries(bar->entries);
}

void print_json(const RunEvaluation& ev, const std::string& path) {
  std::string out = "{\"status\": " + json_string(ev.run.status) +
                    ", \"complete\": " + (ev.finished ? "true" : "false") +
                    ", \"t_end\": " + json_number(ev.run.t_end) +
                    ", \"section_requested\": " + json_section(ev.section) +
                    ",\n \"pantographs\": [";
  for (std::size_t i = 0; i < ev.pantographs.size(); ++i) {
    const PantographEvaluation& e = ev.pantographs[i];
    const post::PantographRecord& p = *e.pantograph;
    out += i ? ",\n  " : "\n  ";
    out += "{\"name\": " + json_string(p.name);
    out += ", \"speed_kmh\": " + json_number(p.speed * kmh_per_ms);
    out += ", \"section\": " + (e.statistics ? json_section(e.section) : std::string("null"));
    out +=
        ", \"coverage\": " + json_number(e.statistics ? (e.section.x_end - e.section.x_start) /
                                                            (ev.section.x_end - ev.section.x_start)
                                                      : 0.0);
    out += ", \"reached_section\": " + std::string(e.statistics ? "true" : "false");
    auto number = [&](auto member) {
      return e.statistics ? json_number((*e.statistics).*member) : std::string("null");
    };
    using S = post::ContactStatistics;
    out += ", \"mean\": " + number(&S::mean);
    out += ", \"std\": " + number(&S::standard_deviation);
    out += ", \"stat_max\": " + number(&S::statistical_max);
    out += ", \"stat_min\": " + number(&S::statistical_min);
    out += ", \"max\": " + number(&S::max);
    out += ", \"min\": " + number(&S::min);
    out += ", \"contact_loss_percent\": " + number(&S::contact_loss_percent);
    out +=
        ", \"max_uplift_at_support\": " + (e.statistics && e.statistics->max_uplift_at_support
                                               ? json_number(*e.statistics->max_uplift_at_support)
                                               : "null");
    out += ", \"acceptance\": " + json_acceptance(e, ev.ranges);
    out += "}";
  }
  out += ev.pantographs.empty() ? "]" : "\n]";
  out += ",\n \"error_bar\": " + json_error_bar(io::read_error_bar(path)) + "}\n";
  std::fputs(out.c_str(), stdout);
}

// `text` followed by spaces to `width` characters (UTF-8: σ, − and – are one each).
std::string padded(const std::string& text, std::size_t width) {
  const auto continuation = static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char ch) { return (ch & 0xC0) == 0x80; }));
  const std::size_t shown = text.size() - continuation;
  return text + std::string(width > shown ? width - shown : 0, ' ');
}

// The ranges' table of one pantograph: each statistic, its value, the range and ✓ or ✗.
void print_acceptance(const PantographEvaluation& e, const post::EvaluationSection& run_section) {
  const double speed_kmh = std::abs(e.pantograph->speed) * kmh_per_ms;  // either direction
  if (!e.statistics) return;
  if (!e.acceptance) {
    std::printf("\n%s at %g km/h: EN 50318 gives acceptance ranges at 250 and 300 km/h only\n",
                e.pantograph->name.c_str(), speed_kmh);
    return;
  }
  std::printf("\nEN 50318 acceptance ranges at %g km/h, pantograph %s:\n", speed_kmh,
              e.pantograph->name.c_str());
  if (e.section.x_start != run_section.x_start || e.section.x_end != run_section.x_end)
    std::printf(
        "  (evaluated over [%g, %g] m, not the run's evaluation section [%g, %g] m: the\n"
        "  ranges hold for the reference case's whole section)\n",
        e.section.x_start, e.section.x_end, run_section.x_start, run_section.x_end);
  for (const post::AcceptanceCheck& c : *e.acceptance) {
    char value[32] = "-";
    if (c.value) std::snprintf(value, sizeof value, "%.2f", *c.value);
    char range[48];
    std::snprintf(range, sizeof range, "%g – %g", c.low, c.high);
    if (c.low == c.high) std::snprintf(range, sizeof range, "%g", c.low);
    std::printf("  %s %9s %-3s %s %s\n", padded(c.label, 30).c_str(), value, c.unit.c_str(),
                padded(range, 11).c_str(),
                c.pass    ? "✓"
                : c.value ? "✗ out of range"
                          : "✗ not measured (no support in the section)");
  }
  std::printf("  %zu of %zu statistics in range\n", checks_passed(*e.acceptance),
              e.acceptance->size());
}

void print_table(const std::string& path, const RunEvaluation& ev, const StatsArguments& args) {
  const io::ContactRun& run = ev.run;
  std::printf("catena stats: %s\n", path.c_str());
  if (!ev.series_note.empty()) std::printf("  note: %s\n", ev.series_note.c_str());
  if (!ev.finished)
    std::printf(
        "  warning: the run did not finish (status '%s'): its record ends at t = %g s; each\n"
        "  pantograph is evaluated over the part of the section it covered (a support passed\n"
        "  just before the end may not show its full uplift)\n",
        run.status.c_str(), run.t_end);
  std::printf(
      "  %zu %s every %g s (%g Hz); contact force low-pass filtered at %g Hz\n"
      "  (zero-phase 2nd-order Butterworth, forward and backward: -6 dB at %g Hz)\n",
      run.n_samples, ev.steps ? "steps" : "samples", run.dt, 1.0 / run.dt, args.cutoff_hz,
      args.cutoff_hz);
  std::printf("  evaluation section [%g, %g] m along the path (%s)\n", ev.section.x_start,
              ev.section.x_end, ev.section_given ? "--section" : "the run's evaluation section");
  const bool partial = std::any_of(ev.pantographs.begin(), ev.pantographs.end(),
                                   [](const PantographEvaluation& e) { return e.partial; });
  if (partial && ev.finished)
    std::printf(
        "  warning: the record does not cover the whole section for every pantograph (the\n"
        "  run ends before it leaves the section, or starts inside it): each is evaluated\n"
        "  over the part it covered\n");
  if (partial)
    for (const PantographEvaluation& e : ev.pantographs) {
      const double covered = e.statistics ? (e.section.x_end - e.section.x_start) /
                                                (ev.section.x_end - ev.section.x_start)
                                          : 0.0;
      if (e.statistics)
        std::printf("  %s: covered [%g, %g] m, %.0f %% of the section\n",
                    e.pantograph->name.c_str(), e.section.x_start, e.section.x_end,
                    100.0 * covered);
      else
        std::printf("  %s: did not reach the section\n", e.pantograph->name.c_str());
    }
  std::printf("\n");
  int width = 10;
  for (const auto& e : ev.pantographs)
    width = std::max(width, static_cast<int>(e.pantograph->name.size()));
  std::printf("%-*s %7s %8s %8s %8s %8s %8s %8s %8s %6s %7s\n", width, "pantograph", "speed",
              "samples", "mean", "std", "stat_max", "stat_min", "max", "min", "loss", "uplift");
  std::printf("%-*s %7s %8s %8s %8s %8s %8s %8s %8s %6s %7s\n", width, "", "km/h", "", "N", "N",
              "N", "N", "N", "N", "%", "mm");
  for (const auto& e : ev.pantographs) {
    if (!e.statistics) {
      std::printf("%-*s %7.1f %8s  (did not reach the section)\n", width,
                  e.pantograph->name.c_str(), e.pantograph->speed * kmh_per_ms, "0");
      continue;
    }
    const post::ContactStatistics& s = *e.statistics;
    char uplift[32] = "-";
    if (s.max_uplift_at_support)
      std::snprintf(uplift, sizeof uplift, "%.2f", 1e3 * *s.max_uplift_at_support);
    std::printf("%-*s %7.1f %8zu %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %6.2f %7s\n", width,
                e.pantograph->name.c_str(), e.pantograph->speed * kmh_per_ms, s.n_samples, s.mean,
                s.standard_deviation, s.statistical_max, s.statistical_min, s.max, s.min,
                s.contact_loss_percent, uplift);
  }
  if (!run.has_registration_nodes)
    std::printf("\nnote: the file has no /mesh/registration_nodes: no uplift at support\n");
  else
    for (const PantographEvaluation& e : ev.pantographs)
      if (e.statistics && e.statistics->n_supports == 0)
        std::printf(
            "\nnote: no registration (steady-arm) node lies in %s's section [%g, %g] m: no "
            "uplift at support\n",
            e.pantograph->name.c_str(), e.section.x_start, e.section.x_end);
  if (!ev.ranges.empty())
    for (const PantographEvaluation& e : ev.pantographs)
      print_acceptance(e, ev.run.evaluation_section.value_or(ev.section));
  print_error_bar(io::read_error_bar(path));
}

// Rank 0's whole work: read, compute, print. Throws InputError for bad files/arguments.
void stats_on_this_rank(const CommandLine& cl) {
  const RunEvaluation ev = evaluate_run(cl.stats);
  if (cl.stats.json)
    print_json(ev, cl.stats.file);
  else
    print_table(cl.stats.file, ev, cl.stats);
  std::fflush(stdout);
}

}  // namespace

void command_stats(MPI_Comm comm, const CommandLine& cl) {
  on_rank_zero(comm, cl.stats.file, [&] { stats_on_this_rank(cl); });
}

}  // namespace catena::app

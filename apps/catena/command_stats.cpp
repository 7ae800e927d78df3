// `catena stats OUT.h5 [--json] [--section X0 X1] [--cutoff HZ]`: the EN 50318
// contact-force statistics per pantograph of a dynamic run (docs/output.md, "Contact-force
// statistics"). Serial: rank 0 reads and prints; under mpirun the other ranks only wait.
//
//   catena stats en50318_250.h5                         # the run's evaluation section
//   catena stats en50318_250.h5 --section 240 360 --json
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/contact_run_reader.hpp"
#include "catena/post/contact_statistics.hpp"
#include "commands.hpp"

namespace catena::app {
namespace {

constexpr double kmh_per_ms = 3.6;

struct PantographResult {
  const post::PantographRecord* pantograph = nullptr;
  post::ContactStatistics statistics;
};

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

void print_json(const std::vector<PantographResult>& results,
                const post::EvaluationSection& section) {
  std::string out = "{\"pantographs\": [";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const post::ContactStatistics& s = results[i].statistics;
    const post::PantographRecord& p = *results[i].pantograph;
    out += i ? ",\n  " : "\n  ";
    out += "{\"name\": " + json_string(p.name);
    out += ", \"speed_kmh\": " + json_number(p.speed * kmh_per_ms);
    out +=
        ", \"section\": [" + json_number(section.x_start) + ", " + json_number(section.x_end) + "]";
    out += ", \"mean\": " + json_number(s.mean);
    out += ", \"std\": " + json_number(s.standard_deviation);
    out += ", \"stat_max\": " + json_number(s.statistical_max);
    out += ", \"stat_min\": " + json_number(s.statistical_min);
    out += ", \"max\": " + json_number(s.max);
    out += ", \"min\": " + json_number(s.min);
    out += ", \"contact_loss_percent\": " + json_number(s.contact_loss_percent);
    out += ", \"max_uplift_at_support\": " +
           (s.max_uplift_at_support ? json_number(*s.max_uplift_at_support) : "null");
    out += "}";
  }
  out += results.empty() ? "]}\n" : "\n]}\n";
  std::fputs(out.c_str(), stdout);
}

void print_table(const std::string& path, const io::ContactRun& run,
                 const std::vector<PantographResult>& results,
                 const post::EvaluationSection& section, const StatsArguments& args) {
  std::printf("catena stats: %s\n", path.c_str());
  std::printf(
      "  %zu %s every %g s (%g Hz); contact force low-pass filtered at %g Hz\n"
      "  (zero-phase 2nd-order Butterworth, forward and backward: -6 dB at %g Hz)\n",
      run.n_samples, args.steps ? "steps (--series steps)" : "samples", run.dt, 1.0 / run.dt,
      args.cutoff_hz, args.cutoff_hz);
  std::printf("  evaluation section [%g, %g] m along the path (%s)\n\n", section.x_start,
              section.x_end, args.section ? "--section" : "the run's evaluation section");
  int width = 10;
  for (const auto& r : results)
    width = std::max(width, static_cast<int>(r.pantograph->name.size()));
  std::printf("%-*s %7s %8s %8s %8s %8s %8s %8s %8s %6s %7s\n", width, "pantograph", "speed",
              "samples", "mean", "std", "stat_max", "stat_min", "max", "min", "loss", "uplift");
  std::printf("%-*s %7s %8s %8s %8s %8s %8s %8s %8s %6s %7s\n", width, "", "km/h", "", "N", "N",
              "N", "N", "N", "N", "%", "mm");
  for (const auto& r : results) {
    const post::ContactStatistics& s = r.statistics;
    char uplift[32] = "-";
    if (s.max_uplift_at_support)
      std::snprintf(uplift, sizeof uplift, "%.2f", 1e3 * *s.max_uplift_at_support);
    std::printf("%-*s %7.1f %8zu %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %6.2f %7s\n", width,
                r.pantograph->name.c_str(), r.pantograph->speed * kmh_per_ms, s.n_samples, s.mean,
                s.standard_deviation, s.statistical_max, s.statistical_min, s.max, s.min,
                s.contact_loss_percent, uplift);
  }
  if (!run.has_registration_nodes)
    std::printf("\nnote: the file has no /mesh/registration_nodes: no uplift at support\n");
  else if (!results.empty() && results.front().statistics.n_supports == 0)
    std::printf(
        "\nnote: no registration (steady-arm) node lies in the section [%g, %g] m: "
        "no uplift at support\n",
        section.x_start, section.x_end);
}

// Rank 0's whole work: read, compute, print. Throws InputError for bad files/arguments.
void stats_on_this_rank(const CommandLine& cl) {
  const StatsArguments& args = cl.stats;
  const io::ContactRun run =
      args.steps ? io::read_contact_run_steps(args.file) : io::read_contact_run(args.file);
  post::EvaluationSection section;
  if (args.section) {
    section = {(*args.section)[0], (*args.section)[1]};
  } else if (run.evaluation_section) {
    section = *run.evaluation_section;
  } else {
    throw InputError({args.file, 0, "evaluation_start"},
                     "the run sets no evaluation section (root attributes evaluation_start, "
                     "evaluation_end absent or 0): give one with --section X0 X1 (m along "
                     "the path)");
  }
  post::ContactStatisticsOptions options;
  options.dt = run.dt;
  options.cutoff_hz = args.cutoff_hz;
  options.section = section;
  std::vector<PantographResult> results;
  for (const post::PantographRecord& p : run.pantographs) {
    try {
      results.push_back({&p, post::contact_statistics(p, run.registration_points, options)});
    } catch (const InputError& e) {
      // Name the file, and the dataset or option the library's key stands for.
      const std::string& k = e.where().key;
      const std::string key = k == "cutoff" ? "--cutoff"
                              : k == "dt"   ? io::contact_run_times_dataset()
                                            : k;
      throw InputError({args.file, 0, key}, e.message());
    }
  }
  if (args.json)
    print_json(results, section);
  else
    print_table(args.file, run, results, section, args);
  std::fflush(stdout);
}

}  // namespace

void command_stats(MPI_Comm comm, const CommandLine& cl) {
  const int rank = mpi_rank(comm);
  std::exception_ptr failure;
  int failed = 0;
  if (rank == 0) {
    try {
      stats_on_this_rank(cl);
    } catch (...) {
      failure = std::current_exception();
      failed = 1;
    }
  }
  // Every rank leaves alike: with rank 0's exception there, an InputError elsewhere (main
  // prints rank 0's message only).
  MPI_Bcast(&failed, 1, MPI_INT, 0, comm);
  if (failure) std::rethrow_exception(failure);
  if (failed) throw InputError({cl.stats.file, 0, ""}, "catena stats failed on rank 0");
}

}  // namespace catena::app

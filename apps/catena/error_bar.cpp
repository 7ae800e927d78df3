#include "error_bar.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "case_console.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/error_bar_record.hpp"
#include "catena/io/output_error.hpp"
#include "catena/study/case_measures.hpp"
#include "catena/study/richardson.hpp"
#include "catena/study/study_plan.hpp"
#include "commands.hpp"
#include "rank_zero.hpp"

namespace catena::app {
namespace fs = std::filesystem;
namespace {

constexpr int kFactors[] = {2, 4};

// Not collective (rank 0). The table users read.
void print_error_bar(const io::ErrorBarRecord& r, const fs::path& directory) {
  std::printf(
      "error bar (Richardson: the same run at dt %g s and %g s, %s): estimated "
      "time-discretisation error of this run (dt %g s)\n",
      r.coarse_dt[0], r.coarse_dt[1], directory.c_str(), r.dt);
  print_error_bar_entries(r.entries);
  std::fflush(stdout);
}

// Collective. The first failure any rank met (its text from the lowest such rank), on
// every rank: one rank's failure stops every rank's error bar at the same point.
std::string agreed_failure(MPI_Comm comm, const std::string& mine) {
  const int size = mpi_size(comm);
  int from = mine.empty() ? size : mpi_rank(comm);
  MPI_Allreduce(MPI_IN_PLACE, &from, 1, MPI_INT, MPI_MIN, comm);
  std::string failure = from < size ? mine : std::string();
  if (from < size) broadcast_string(comm, failure, from);
  return failure;
}

}  // namespace

void print_error_bar_entries(const std::vector<io::ErrorBarEntry>& entries) {
  for (const io::ErrorBarEntry& e : entries) {
    std::printf("  %-10s %-19s %+.2g %s", e.part.c_str(), e.measure.c_str(), e.estimate,
                e.unit.c_str());
    if (std::isnan(e.order))
      std::printf("  (rough: the three runs do not converge at one order)\n");
    else
      std::printf("  (observed order %.2f)\n", e.order);
  }
}

void check_error_bar_request(const CommandLine& cl, const model::Model& m) {
  if (!cl.error_bar) return;
  if (m.analysis != model::AnalysisType::dynamic)
    throw InputError({cl.scene, 0, "--error-bar"},
                     "--error-bar estimates the time-discretisation error of a dynamic run; "
                     "this scene's analysis is static (analysis.type: static)");
  if (m.dynamic_options.integrator.adaptive)
    throw InputError({cl.scene, 0, "--error-bar"},
                     "--error-bar compares the run with the same run at 2 dt and 4 dt, which "
                     "needs fixed steps (integrator.adaptive: false); an adaptive run controls "
                     "its local error by integrator.rtol and atol instead");
}

void run_error_bar(MPI_Comm comm, const CommandLine& cl, const model::Model& m) {
  const int rank = mpi_rank(comm);
  const fs::path output = m.output.file;
  const fs::path directory = fs::path(output).replace_extension(".error_bar");
  io::ErrorBarRecord record;
  record.dt = m.dynamic_options.integrator.dt;
  std::string failure;
  if (rank == 0) {
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (ec) failure = "cannot create " + directory.string() + ": " + ec.message();
  }
  failure = agreed_failure(comm, failure);
  for (const int factor : kFactors) {
    if (!failure.empty()) break;
    const double dt = factor * record.dt;
    const std::string name = "dt_x" + std::to_string(factor);
    const fs::path file = directory / (name + ".h5");
    record.coarse_dt.push_back(dt);
    record.coarse_files.push_back(file.string());
    if (rank == 0) {
      std::printf("error bar: the run at dt %g s (%d of %zu), log %s\n", dt, factor / 2,
                  std::size(kFactors), (directory / (name + ".log")).c_str());
      std::fflush(stdout);
    }
    CommandLine coarse = cl;
    coarse.error_bar = false;
    coarse.restart = false;
    coarse.realtime = false;
    coarse.output = file.string();
    coarse.overrides.push_back("integrator.dt=" + study::number_text(dt));
    coarse.overrides.push_back("output.file=" + file.string());
    try {
      const CaseConsole console(directory / (name + ".log"), name);
      command_run(comm, coarse);
    } catch (const Error& e) {
      failure = "the run at dt " + study::number_text(dt) + " s failed (" + e.what() + ")";
    } catch (const RunInterrupted&) {
      // The run itself is complete: a stop during its error bar costs the error bar only.
      failure = "the run at dt " + study::number_text(dt) + " s was interrupted";
    }
    failure = agreed_failure(comm, failure);
  }
  if (rank == 0 && failure.empty()) {
    try {
      const study::ReferenceRun run(output.string(), {}, StatsArguments{}.cutoff_hz);
      record.entries = study::richardson_error_bar(run.errors_by_part(record.coarse_files[0]),
                                                   run.errors_by_part(record.coarse_files[1]));
      io::write_error_bar(output.string(), record);
      print_error_bar(record, directory);
    } catch (const Error& e) {
      failure = e.what();
    }
  }
  if (!failure.empty() && rank == 0) {
    std::fprintf(stderr, "catena: warning: no error bar for %s: %s; the run itself is complete\n",
                 output.c_str(), failure.c_str());
    std::fflush(stderr);
  }
}

}  // namespace catena::app

#include "error_bar.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <thread>
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
#include "output_preflight.hpp"
#include "rank_zero.hpp"
#include "scene_loading.hpp"
#include "stop_signal.hpp"

namespace catena::app {
namespace fs = std::filesystem;
namespace {

constexpr int kFactors[] = {2, 4};
// The message a served run's rank 0 sends each comparison rank when the run has ended
// (its value: 0 completed, 1 not).
constexpr int kRunEndedTag = 7301;

// Not collective. The table users read.
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

fs::path comparison_directory(const std::string& output) {
  return fs::path(output).replace_extension(".error_bar");
}

// "0.48": a simulated time for people (4 significant digits).
std::string time_text(double t) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", t);
  return text;
}

std::string comparison_name(int factor) { return "dt_x" + std::to_string(factor); }

// Collective. Creates the comparisons' directory (rank 0); "" or why not, on every rank.
std::string create_directory(MPI_Comm comm, const fs::path& directory) {
  std::string failure;
  if (mpi_rank(comm) == 0) {
    std::error_code ec;
    // One level: its parent is the output's directory, which the run checks exists.
    fs::create_directory(directory, ec);
    if (ec) failure = "cannot create " + directory.string() + ": " + ec.message();
  }
  return agreed_failure(comm, failure);
}

// Collective over `comm`, the ranks that run it. The scene at `factor` × dt, its console
// to its log; "" or why it did not complete (the same on every rank of `comm`).
std::string run_comparison(MPI_Comm comm, const CommandLine& cl, const fs::path& directory,
                           int factor, double dt) {
  const double coarse_dt = factor * dt;
  const std::string name = comparison_name(factor);
  const fs::path file = directory / (name + ".h5");
  CommandLine coarse = cl;
  coarse.error_bar = false;
  coarse.error_bar_ranks = 0;
  coarse.restart = false;
  coarse.realtime = false;
  coarse.output = file.string();
  coarse.overrides.push_back("integrator.dt=" + study::number_text(coarse_dt));
  coarse.overrides.push_back("output.file=" + file.string());
  std::string failure;
  try {
    const CaseConsole console(directory / (name + ".log"), name);
    command_run(comm, coarse);
  } catch (const Error& e) {
    failure = "the run at dt " + study::number_text(coarse_dt) + " s failed (" + e.what() + ")";
  } catch (const std::exception& e) {
    // Anything else (memory): reported like a failure, so that the ranks still meet.
    failure = "the run at dt " + study::number_text(coarse_dt) + " s failed (" + e.what() + ")";
  } catch (const RunInterrupted& stop) {
    // The run itself is complete: a stop during its error bar costs the error bar only.
    failure = "the run at dt " + study::number_text(coarse_dt) + " s was " +
              (stop.signal == 0 ? "stopped at t = " + time_text(stop.time) +
                                      " s, as the run it compares with ended early"
                                : "interrupted");
  }
  return agreed_failure(comm, failure);
}

// Collective. Rank 0 estimates the error from the run and its comparisons, stores the
// estimate in the run's output and prints it; a failure (`failure`, or one met here) is
// reported as a warning: the run itself is complete.
void finish_error_bar(MPI_Comm comm, const std::string& output, double dt, std::string failure) {
  if (mpi_rank(comm) != 0) return;
  const fs::path directory = comparison_directory(output);
  io::ErrorBarRecord record;
  record.dt = dt;
  for (const int factor : kFactors) {
    record.coarse_dt.push_back(factor * dt);
    record.coarse_files.push_back((directory / (comparison_name(factor) + ".h5")).string());
  }
  if (failure.empty()) {
    try {
      const study::ReferenceRun run(output, {}, StatsArguments{}.cutoff_hz);
      record.entries = study::richardson_error_bar(run.errors_by_part(record.coarse_files[0]),
                                                   run.errors_by_part(record.coarse_files[1]));
      io::write_error_bar(output, record);
      print_error_bar(record, directory);
    } catch (const Error& e) {
      failure = e.what();
    }
  }
  if (!failure.empty()) {
    std::fprintf(stderr, "catena: warning: no error bar for %s: %s; the run itself is complete\n",
                 output.c_str(), failure.c_str());
    std::fflush(stderr);
  }
}

// Collective over `comm`, waiting without holding a core: a rank that waits here for ranks
// still running (the run, or its comparisons) must not slow them down where ranks share
// cores (MPI's own waits spin).
void wait_for_all(MPI_Comm comm) {
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Ibarrier(comm, &request);
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

// "rank 3" or "ranks 3-5": the ranks first .. end − 1.
std::string ranks_text(int first, int end) {
  return end - first == 1 ? "rank " + std::to_string(first)
                          : "ranks " + std::to_string(first) + "-" + std::to_string(end - 1);
}

// On a comparison rank: whether the run it serves has ended, and how (the message its
// rank 0 sends each comparison rank once).
class ServedRun {
 public:
  explicit ServedRun(MPI_Comm world) : world_(world) {}
  // Not collective. True once the run has ended without completing.
  bool failed() {
    if (!known_) {
      int arrived = 0;
      MPI_Iprobe(0, kRunEndedTag, world_, &arrived, MPI_STATUS_IGNORE);
      if (arrived) receive();
    }
    return known_ && status_ != 0;
  }
  // Not collective. Waits (sleeping) for the message if it has not come.
  void wait() {
    while (!known_) {
      int arrived = 0;
      MPI_Iprobe(0, kRunEndedTag, world_, &arrived, MPI_STATUS_IGNORE);
      if (arrived)
        receive();
      else
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }

 private:
  void receive() {
    MPI_Recv(&status_, 1, MPI_INT, 0, kRunEndedTag, world_, MPI_STATUS_IGNORE);
    known_ = true;
  }
  MPI_Comm world_;
  bool known_ = false;
  int status_ = 0;
};

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
  const std::string flag = cl.error_bar_ranks > 0 ? "--error-bar-ranks" : "--error-bar";
  if (m.analysis != model::AnalysisType::dynamic)
    throw InputError({cl.scene, 0, flag},
                     flag +
                         " estimates the time-discretisation error of a dynamic run; "
                         "this scene's analysis is static (analysis.type: static)");
  if (m.dynamic_options.integrator.adaptive)
    throw InputError({cl.scene, 0, flag},
                     flag +
                         " compares the run with the same run at 2 dt and 4 dt, which "
                         "needs fixed steps (integrator.adaptive: false); an adaptive run controls "
                         "its local error by integrator.rtol and atol instead");
}

void run_error_bar(MPI_Comm comm, const CommandLine& cl, const model::Model& m) {
  const std::string output = m.output.file;
  const fs::path directory = comparison_directory(output);
  const double dt = m.dynamic_options.integrator.dt;
  std::string failure = create_directory(comm, directory);
  for (std::size_t i = 0; i < std::size(kFactors) && failure.empty(); ++i) {
    const std::string name = comparison_name(kFactors[i]);
    if (mpi_rank(comm) == 0) {
      std::printf("error bar: the run at dt %g s (%zu of %zu), log %s\n", kFactors[i] * dt, i + 1,
                  std::size(kFactors), (directory / (name + ".log")).c_str());
      std::fflush(stdout);
    }
    failure = run_comparison(comm, cl, directory, kFactors[i], dt);
  }
  finish_error_bar(comm, output, dt, failure);
}

void run_with_concurrent_error_bar(MPI_Comm world, const CommandLine& cl) {
  const int size = mpi_size(world), rank = mpi_rank(world), k = cl.error_bar_ranks;
  if (k >= size)
    throw InputError({"", 0, "--error-bar-ranks"},
                     "--error-bar-ranks " + std::to_string(k) + " leaves no rank for the run " +
                         "itself: the job has " + std::to_string(size) +
                         (size == 1 ? " rank" : " ranks") + " (mpirun -n); accepted: 1 to " +
                         std::to_string(size - 1) +
                         ", or --error-bar to run the comparisons after the run on every rank");
  // The scene's refusals, the request's and the output paths' before the ranks part, the
  // same on every rank (the run checks the rest, e.g. --restart, on its own ranks).
  std::string output;
  double dt = 0.0;
  {
    const model::Model m = load_scene(world, cl.scene, cl.overrides, memory_budget(world, cl));
    check_error_bar_request(cl, m);
    check_output_path(world, m, cl.output.has_value());
    check_modal_basis_path(world, m);
    output = m.output.file;
    dt = m.dynamic_options.integrator.dt;
  }
  const fs::path directory = comparison_directory(output);
  if (const std::string failure = create_directory(world, directory); !failure.empty())
    throw OutputError(failure + " (the comparison runs' directory of --error-bar-ranks)");
  // Ranks 0 .. size − k − 1 run the scene. The comparisons: on one rank one after the other;
  // on more, at once, the run at 2 dt (twice the steps) on about two thirds of them.
  const int first = size - k, at_4dt = k == 1 ? size : size - std::max(1, (k + 1) / 3);
  const int group_of_rank = rank < first ? 0 : rank < at_4dt ? 1 : 2;
  std::vector<int> factors;
  if (group_of_rank == 1) factors.push_back(2);
  if (group_of_rank == 2 || (group_of_rank == 1 && k == 1)) factors.push_back(4);
  if (rank == 0) {
    if (k == 1)
      std::printf(
          "error bar: the runs at dt %g s and %g s one after the other on rank %d, "
          "beside this run (logs in %s)\n",
          2 * dt, 4 * dt, first, directory.c_str());
    else
      std::printf(
          "error bar: the runs at dt %g s on %s and %g s on %s, beside this run (logs "
          "in %s)\n",
          2 * dt, ranks_text(first, at_4dt).c_str(), 4 * dt, ranks_text(at_4dt, size).c_str(),
          directory.c_str());
    std::fflush(stdout);
  }
  // A SIGTERM to the job while a rank waits (for its group's next run, or for the others
  // at the end) is kept, not fatal: the run stops cleanly and tells the comparisons.
  const StopSignal signals;
  MPI_Comm group = MPI_COMM_NULL;
  MPI_Comm_split(world, group_of_rank, rank, &group);
  std::exception_ptr run_failure;  // the run's own: rethrown on its ranks at the end
  std::string failure;             // a comparison's
  if (group_of_rank == 0) {
    CommandLine run = cl;
    run.error_bar = false;
    run.error_bar_ranks = 0;
    try {
      command_run(group, run);
    } catch (const Error&) {
      run_failure = std::current_exception();
    } catch (const RunInterrupted&) {
      run_failure = std::current_exception();
    } catch (const std::exception&) {
      // Also rethrown at the end: the comparison ranks must still hear that the run ended.
      run_failure = std::current_exception();
    }
    if (rank == 0) {
      const int ended = run_failure ? 1 : 0;
      for (int to = first; to < size; ++to) MPI_Send(&ended, 1, MPI_INT, to, kRunEndedTag, world);
    }
  } else {
    ServedRun served(world);
    {
      const ExtraStop stop_with_the_run([&served] { return served.failed(); });
      for (const int factor : factors) {
        failure = run_comparison(group, cl, directory, factor, dt);
        if (!failure.empty()) break;
      }
    }
    served.wait();
  }
  MPI_Comm_free(&group);
  wait_for_all(world);
  int completed = run_failure ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &completed, 1, MPI_INT, MPI_MIN, world);
  failure = agreed_failure(world, failure);
  if (completed) {
    finish_error_bar(world, output, dt, failure);
  } else if (rank == 0 && !failure.empty()) {
    std::fprintf(stderr, "catena: no error bar for %s: %s\n", output.c_str(), failure.c_str());
    std::fflush(stderr);
  }
  if (run_failure) std::rethrow_exception(run_failure);
}

}  // namespace catena::app

#include "case_runner.hpp"

#include <cstdio>
#include <exception>

#include "case_console.hpp"
#include "catena/core/error.hpp"
#include "catena/core/mpi_comm.hpp"
#include "catena/io/output_error.hpp"
#include "catena/io/run_files.hpp"
#include "catena/model/scene_identity.hpp"
#include "catena/post/contact_statistics.hpp"
#include "catena/study/case_queue.hpp"
#include "catena/study/case_record.hpp"
#include "catena/study/study_plan.hpp"
#include "commands.hpp"
#include "run_statistics.hpp"
#include "scene_loading.hpp"

namespace catena::app {

namespace fs = std::filesystem;

fs::path command_directory(const CommandLine& cl, const std::string& suffix) {
  return cl.study.directory.empty() ? fs::path(fs::path(cl.scene).stem().string() + suffix)
                                    : fs::path(cl.study.directory);
}

std::string unique_name(std::set<std::string>& taken, const std::string& stem) {
  std::string name = stem;
  for (int k = 2; !taken.insert(name).second; ++k) name = stem + "_" + std::to_string(k);
  return name;
}

void check_contact_sampling(const CommandLine& cl, const QueuedCase& c, const model::Model& m) {
  const double record = m.dynamic_options.duration;
  if (cl.study.cutoff_given && !m.contacts.empty() && cutoff_too_low(cl.study.cutoff_hz, record))
    throw InputError({"", 0, "--cutoff"},
                     "--cutoff " + study::number_text(cl.study.cutoff_hz) + " Hz: the run" +
                         (c.overrides.empty() ? "" : " under " + list_text(c.overrides)) +
                         " lasts " + study::number_text(record) +
                         " s, shorter than two periods of the cutoff, so the filtered force "
                         "would be its start-up transient; accepted: at least " +
                         lowest_cutoff_text(record) + " Hz (EN 50318: 20 Hz)");
  const double coarsest = 1.0 / (post::min_sampling_rate_per_cutoff * cl.study.cutoff_hz);
  if (m.contacts.empty() || m.output.interval <= coarsest * (1.0 + 1e-9)) return;
  throw InputError({cl.scene, 0, "output.interval"},
                   "output.interval = " + study::number_text(m.output.interval) + " s" +
                       (c.overrides.empty() ? "" : " under " + list_text(c.overrides)) +
                       " samples the contact force too coarsely for the statistics' " +
                       study::number_text(cl.study.cutoff_hz) + " Hz low-pass; accepted: at most " +
                       study::number_text(coarsest) + " s (--set output.interval=...)");
}

void create_cases_directory(MPI_Comm world, const fs::path& cases_dir) {
  std::string why;
  if (mpi_rank(world) == 0) {
    std::error_code ec;
    fs::create_directories(cases_dir, ec);
    if (ec) why = "cannot create " + cases_dir.string() + ": " + ec.message();
  }
  broadcast_string(world, why);
  if (!why.empty()) throw InputError({cases_dir.string(), 0, "-o"}, why);
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

std::vector<std::string> check_scenes(
    MPI_Comm world, const CommandLine& cl, const std::vector<QueuedCase>& cases,
    const std::function<void(std::size_t, const model::Model&)>& check) {
  std::vector<std::string> identities;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const model::Model m = load_scene(world, cl.scene, joined(cl.overrides, cases[i].overrides));
    if (m.analysis != model::AnalysisType::dynamic)
      throw InputError(
          {cl.scene, 0, "analysis.type"},
          "the setting " + list_text(cases[i].overrides) + " makes the analysis static");
    if (check) check(i, m);
    identities.push_back(model::scene_identity(m.source_text) + "duration " +
                         study::number_text(m.dynamic_options.duration));
  }
  return identities;
}

namespace {

// Collective over the group. Runs one case as `catena run` would; returns its record.
study::CaseRecord run_case(MPI_Comm group, const CommandLine& cl, const QueuedCase& c,
                           const fs::path& cases_dir) {
  study::CaseRecord record;
  record.overrides = c.overrides;
  record.scene = c.scene;
  CommandLine run = cl;
  run.command = "run";
  run.overrides = joined(joined(cl.overrides, c.overrides),
                         {"output.file=" + (cases_dir / (c.name + ".h5")).string()});
  run.progress_seconds = 30.0;
  // A case stopped midway (SIGTERM, the study killed after a checkpoint) continues from its
  // checkpoint; one the run refuses (another scene's: the setting changed) is run afresh.
  const std::string output = (cases_dir / (c.name + ".h5")).string();
  int resume = mpi_rank(group) == 0 && fs::exists(io::checkpoint_path(output));
  MPI_Bcast(&resume, 1, MPI_INT, 0, group);
  const double start = MPI_Wtime();
  {
    const CaseConsole console(cases_dir / (c.name + ".log"), c.name);
    try {
      if (resume) {
        run.restart = true;
        try {
          command_run(group, run);
        } catch (const InputError& e) {
          if (mpi_rank(group) == 0)
            std::printf("%s: not continued from %s (%s): running from the start\n",
                        cl.command.c_str(), io::checkpoint_path(output).c_str(), e.what());
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
      std::fprintf(stderr, "catena: %s case %s stopped: %s\n", cl.command.c_str(), c.name.c_str(),
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
// (and its output is there, if it completed): run again, a study or sweep keeps it.
bool done_before(const study::CaseGroups& groups, const QueuedCase& c, const fs::path& cases_dir) {
  int done = 0;
  if (groups.leader()) {
    const auto old = study::read_record(cases_dir / (c.name + ".result"));
    done = old && old->overrides == c.overrides && old->scene == c.scene &&
           (!old->completed || fs::exists(cases_dir / (c.name + ".h5")));
  }
  MPI_Bcast(&done, 1, MPI_INT, 0, groups.group());
  return done != 0;
}

}  // namespace

// Collective over `world`: the groups take cases from the queue until none is left, or until
// a case is interrupted (SIGTERM, or the stop testing hook): then no group takes another
// case, and the interruption is returned on every rank (signal 0: none). The errors of a
// run are every rank's of its group (run_case records them); anything else thrown here
// (a record that cannot be written, memory) is one rank's, and the ranks could not meet
// again: it aborts the whole run.
RunInterrupted run_cases(MPI_Comm world, const CommandLine& cl,
                         const std::vector<QueuedCase>& cases, const fs::path& cases_dir) {
  const int ranks_per_case = cl.study.ranks_per_case;
  const char* who = cl.command.c_str();
  const study::CaseGroups groups(world, ranks_per_case);
  study::CaseQueue queue(world);
  if (mpi_rank(world) == 0) {
    std::printf("%s: %zu cases on %d group%s of %d rank%s; logs in %s\n", who, cases.size(),
                groups.count(), groups.count() == 1 ? "" : "s", ranks_per_case,
                ranks_per_case == 1 ? "" : "s", cases_dir.c_str());
    std::fflush(stdout);
  }
  RunInterrupted interrupted;
  try {
    for (long k = queue.take(groups); k < static_cast<long>(cases.size()); k = queue.take(groups)) {
      const QueuedCase& c = cases[static_cast<std::size_t>(k)];
      const fs::path record_path = cases_dir / (c.name + ".result");
      if (done_before(groups, c, cases_dir)) {
        if (groups.leader())
          std::printf("%s: case %ld/%zu %s (%s): done before, kept\n", who, k + 1, cases.size(),
                      c.name.c_str(), list_text(c.overrides).c_str());
        std::fflush(stdout);
        continue;
      }
      if (groups.leader()) {
        std::printf("%s: case %ld/%zu %s (%s) started on group %d\n", who, k + 1, cases.size(),
                    c.name.c_str(), list_text(c.overrides).c_str(), groups.index());
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
        std::printf("%s: case %ld/%zu %s %s in %.1f s%s%s\n", who, k + 1, cases.size(),
                    c.name.c_str(), record.completed ? "completed" : "failed", record.wall_seconds,
                    record.completed ? "" : ": ", record.completed ? "" : record.message.c_str());
        std::fflush(stdout);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "catena: %s: %s; stopping every rank\n", who, e.what());
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

}  // namespace catena::app

#pragma once
// The cases of `catena study` and `catena sweep`: each one `catena run` of the scene with
// its own overrides, on a group of --ranks-per-case ranks, the groups taking cases from one
// queue (study/case_queue.hpp); each case's console to DIR/cases/NAME.log (its progress
// lines also to the console: case_console.hpp), its output to DIR/cases/NAME.h5 and a record
// of its end to DIR/cases/NAME.result, from which the same command resumes.
#include <mpi.h>

#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "catena/model/model.hpp"
#include "cli.hpp"
#include "commands.hpp"

namespace catena::app {

struct QueuedCase {
  std::string name;                    // file stem under DIR/cases
  std::vector<std::string> overrides;  // the case's own, after the command's --set ones
  std::string scene;                   // study::digest of its scene identity (the records)
};

// Not collective. The command's directory: -o DIR, else "<scene's stem><suffix>".
std::filesystem::path command_directory(const CommandLine& cl, const std::string& suffix);

// Not collective. `stem`, or stem_2, stem_3, ... : the first not yet in `taken` (then added).
std::string unique_name(std::set<std::string>& taken, const std::string& stem);

// Not collective. Throws catena::InputError (key "output.interval") when `m` has pantographs
// and samples their contact force too coarsely for the statistics' low-pass at
// cl.study.cutoff_hz (post::min_sampling_rate_per_cutoff), or (key "--cutoff") when a
// cutoff the user gave is below two periods over the run (its filtered force would be the
// filter's start-up, as catena stats refuses), naming the case's overrides: a study or sweep
// refuses it before any case runs, not after all have.
void check_contact_sampling(const CommandLine& cl, const QueuedCase& c, const model::Model& m);

// Collective over `world`. Creates `cases_dir` (rank 0); throws catena::InputError (key
// "-o") on every rank if it cannot.
void create_cases_directory(MPI_Comm world, const std::filesystem::path& cases_dir);

// Not collective. a followed by b.
std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b);

// Not collective. The overrides for people: "key=value key=value", the key removals
// ("key=~") left out; "(the scene as it is)" for none.
std::string list_text(const std::vector<std::string>& overrides);

// Collective over `world`. Reads and validates every case's scene (cl.scene after cl's and
// the case's overrides) before any runs, so that a typo stops everything at once; refuses a
// static analysis; calls `check` (may be empty) with each case's index and model. Returns each
// case's scene identity (model::scene_identity and the duration).
std::vector<std::string> check_scenes(
    MPI_Comm world, const CommandLine& cl, const std::vector<QueuedCase>& cases,
    const std::function<void(std::size_t, const model::Model&)>& check);

// Collective over `world`. Runs the cases (cl.study.ranks_per_case ranks each) until none is
// left or one is interrupted (SIGTERM, the stop testing hook): then no group takes another
// and the interruption is returned on every rank (signal 0: none). Errors of a run are its
// group's and are recorded; anything one rank alone throws aborts every rank.
RunInterrupted run_cases(MPI_Comm world, const CommandLine& cl,
                         const std::vector<QueuedCase>& cases,
                         const std::filesystem::path& cases_dir);

}  // namespace catena::app

#pragma once
// `catena run --error-bar`: after a completed fixed-step dynamic run, the same scene at
// 2 dt and 4 dt (OUT.error_bar/), and from the three runs Richardson's estimate of the
// run's own time-discretisation error on what users read — the EN 50318 statistics and the
// filtered contact force of each pantograph, or a probe node's track — with the order of
// convergence the three runs show (study/richardson.hpp). Stored in OUT.h5 (/error_bar)
// and printed. Costs up to the run again: half and a quarter of its steps, but a longer step
// takes more Newton iterations (EN 50318 with HHT: 0.96 of the run's iterations).
// `--error-bar-ranks K` runs them on K ranks of their own at the same time as the run
// (docs/accuracy.md, "Error bar of a run").
#include <mpi.h>

#include <vector>

#include "catena/io/error_bar_record.hpp"
#include "catena/model/model.hpp"
#include "cli.hpp"

namespace catena::app {

// Not collective. One line per entry: part, measure, estimate and unit, the observed order
// or "rough" (`catena run --error-bar` and `catena stats`).
void print_error_bar_entries(const std::vector<io::ErrorBarEntry>& entries);

// Not collective. Throws catena::InputError (key "--error-bar") when the scene cannot have
// one: a static analysis or adaptive steps (a step of its own choosing has no 2 dt).
void check_error_bar_request(const CommandLine& cl, const model::Model& m);

// Collective. Runs the comparison runs and reports; a comparison that cannot run or be
// compared is reported (stderr) and leaves the run without an error bar, not failed.
void run_error_bar(MPI_Comm comm, const CommandLine& cl, const model::Model& m);

// Collective over `world`. `catena run --error-bar-ranks K`: the last K ranks of `world` run
// the comparisons (at once on two groups when K >= 2, the one at 2 dt on two thirds of them;
// one after the other when K = 1) while the others run the scene; then the estimate as
// run_error_bar's. If the run ends without completing, its comparisons stop at their next
// time step (not during their set-up) and the run's error is rethrown on its ranks (the
// comparison ranks return). Throws catena::InputError when K leaves no rank for the run, the
// scene or its output path is refused or it refuses an error bar, catena::OutputError when
// the comparisons' directory cannot be made — all before the ranks part; the run's own
// checks (--restart, the output lock) follow on its ranks.
void run_with_concurrent_error_bar(MPI_Comm world, const CommandLine& cl);

}  // namespace catena::app

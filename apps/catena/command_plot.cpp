// `catena plot OUT.h5 [-o PREFIX] [--format png,pdf] [--section X0 X1] [--cutoff HZ]
// [--series S]`: the figures of a run (docs/output.md, "Plots"), drawn by the shipped
// apps/plot_run.py with Debian's matplotlib. The contact-force series and statistics come
// from the same evaluation as `catena stats` (handed to the script as `catena export`'s
// CSV files, removed afterwards), so the plot and the table cannot disagree. Serial: rank 0.
//
//   catena plot en50318_250.h5 --format png,pdf
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/io/atomic_file.hpp"
#include "catena/io/contact_run_reader.hpp"
#include "catena/io/output_error.hpp"
#include "commands.hpp"
#include "plot_script.hpp"
#include "rank_zero.hpp"
#include "run_export.hpp"
#include "run_statistics.hpp"

namespace catena::app {
namespace {

std::string joined_formats(const std::vector<std::string>& formats) {
  std::string out;
  for (const std::string& f : formats) out += (out.empty() ? "" : ",") + f;
  return out;
}

std::string exact_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

OutputError nothing_drawn(const std::string& file) {
  return OutputError("catena plot " + file +
                     ": the plot script failed (its message is above; the figures listed "
                     "before it were drawn)");
}

void plot_on_this_rank(const StatsArguments& args) {
  const std::string prefix = args.output.empty() ? default_prefix(args.file) : args.output;
  std::vector<std::string> script_args{args.file, prefix, joined_formats(args.formats)};
  refuse_unfinished_name(args.file);
  io::require_run_or_static_result(args.file);
  create_parent_directory(prefix + "_static_shape.png");
  if (!io::has_contact_forces(args.file)) {
    if (!draw_figures("plot_run.py", script_args)) throw nothing_drawn(args.file);
    return;
  }
  const RunEvaluation ev = evaluate_run(args, SectionCoverage::covered);
  if (!ev.finished)
    std::printf(
        "plot: warning: the run did not finish (status '%s'): its record ends at "
        "t = %g s\n",
        ev.run.status.c_str(), ev.run.t_end);
  const io::TemporaryFile contact(io::temporary_sibling(prefix + "_contact.csv", getpid()));
  const io::TemporaryFile statistics(io::temporary_sibling(prefix + "_statistics.csv", getpid()));
  write_contact_csv(ev, contact.path());
  write_statistics_csv(ev, statistics.path());
  script_args.insert(
      script_args.end(),
      {contact.path().string(), statistics.path().string(), exact_number(ev.section.x_start),
       exact_number(ev.section.x_end), exact_number(args.cutoff_hz),
       args.section || ev.run.evaluation_section ? "section" : "record"});
  if (!draw_figures("plot_run.py", script_args)) throw nothing_drawn(args.file);
}

}  // namespace

void command_plot(MPI_Comm comm, const CommandLine& cl) {
  on_rank_zero(comm, cl.stats.file, [&] { plot_on_this_rank(cl.stats); });
}

}  // namespace catena::app

// `catena export OUT.h5 [--csv] [-o PREFIX] [--section X0 X1] [--cutoff HZ] [--series S]
// [--ranges R]`: a dynamic run's contact-force series and statistics as CSV files for
// spreadsheets and the users' own scripts (docs/output.md, "Exports"). Serial: rank 0.
//
//   catena export en50318_250.h5            # en50318_250_contact.csv, en50318_250_statistics.csv
#include <cstdio>

#include "commands.hpp"
#include "rank_zero.hpp"
#include "run_export.hpp"

namespace catena::app {

void command_export(MPI_Comm comm, const CommandLine& cl) {
  on_rank_zero(comm, cl.stats.file, [&] {
    const RunEvaluation ev = evaluate_run(cl.stats, SectionCoverage::covered);
    const std::string prefix =
        cl.stats.output.empty() ? default_prefix(cl.stats.file) : cl.stats.output;
    if (!ev.finished)
      std::printf(
          "export: warning: the run did not finish (status '%s'): its record ends at t = %g s; "
          "statistics over the part of the section each pantograph covered\n",
          ev.run.status.c_str(), ev.run.t_end);
    const std::string contact = prefix + "_contact.csv", statistics = prefix + "_statistics.csv";
    create_parent_directory(contact);
    write_contact_csv(ev, contact);
    write_statistics_csv(ev, statistics);
    std::printf(
        "export: %s (%zu rows: time, and per pantograph position, raw and %g Hz "
        "filtered force)\nexport: %s (%zu pantograph%s)\n",
        contact.c_str(), ev.run.n_samples, cl.stats.cutoff_hz, statistics.c_str(),
        ev.pantographs.size(), ev.pantographs.size() == 1 ? "" : "s");
    std::fflush(stdout);
  });
}

}  // namespace catena::app

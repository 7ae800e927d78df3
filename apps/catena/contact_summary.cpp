#include "contact_summary.hpp"

#include <cstdio>
#include <exception>

#include "run_statistics.hpp"

namespace catena::app {

namespace {

void print_lines(const RunEvaluation& ev, const StatsArguments& args) {
  if (ev.run.evaluation_section)
    std::printf(
        "contact force (%g Hz low-pass%s; catena stats %s for the table, catena plot for the "
        "figures):\n",
        args.cutoff_hz, ev.steps ? ", every step's" : "", args.file.c_str());
  else
    std::printf(
        "contact force over the whole record, start-up included (the scene sets no evaluation "
        "section: catenary.evaluation_spans; %g Hz low-pass%s; catena stats %s --section X0 X1 "
        "for the table over a section of your choice):\n",
        args.cutoff_hz, ev.steps ? ", every step's" : "", args.file.c_str());
  for (const PantographEvaluation& e : ev.pantographs) {
    const char* name = e.pantograph->name.c_str();
    if (!e.statistics) {
      std::printf("  %s: did not reach [%g, %g] m\n", name, ev.section.x_start, ev.section.x_end);
      continue;
    }
    const post::ContactStatistics& s = *e.statistics;
    std::printf(
        "  %s over [%g, %g] m: mean %.2f N, std %.2f N, max %.2f N, min %.2f N, "
        "loss of contact %.2f %%",
        name, e.section.x_start, e.section.x_end, s.mean, s.standard_deviation, s.max, s.min,
        s.contact_loss_percent);
    if (s.max_uplift_at_support)
      std::printf(", uplift at support %.2f mm", 1e3 * *s.max_uplift_at_support);
    if (e.acceptance)
      std::printf("; EN 50318: %zu of %zu in range", checks_passed(*e.acceptance),
                  e.acceptance->size());
    if (e.partial && ev.run.evaluation_section) std::printf(" (part of the section only)");
    std::printf("\n");
  }
}

}  // namespace

void print_contact_summary(const std::string& file) {
  StatsArguments args;
  args.file = file;
  try {
    print_lines(evaluate_run(args, SectionCoverage::covered), args);
  } catch (const std::exception& e) {
    std::printf("contact force: no summary (%s)\n", e.what());
  }
  std::fflush(stdout);
}

}  // namespace catena::app

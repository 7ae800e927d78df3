#include "shape_report.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "catena/core/mpi_comm.hpp"
#include "catena/solvers/shape_finding.hpp"

namespace catena::app {
namespace {

void print_report(std::FILE* out, const model::Model& m, const solvers::ShapeFindingReport& r,
                  double seconds, const solvers::ShapeFindingOptions& options) {
  const model::CatenaryLayout& layout = *m.catenary;
  std::fprintf(out, "shape finding: %d whole-structure static solves (%d in all), %.2f s\n",
               r.n_iterations, r.n_static_solves, seconds);
  std::fprintf(out,
               "  max height error %.4f mm (tolerance %.3g mm) at droppers and registrations;"
               " per iteration:",
               1e3 * r.max_height_error, 1e3 * options.height_tolerance);
  for (const double e : r.error_history) std::fprintf(out, " %.3g", 1e3 * e);
  std::fprintf(out, " mm\n");
  std::fprintf(out,
               "  wire tensions (mean axial force): contact wire %.1f N, messenger %.1f N "
               "(design %.6g N, %.6g N)\n",
               r.contact_wire_tension, r.messenger_tension, layout.contact_wire.tension,
               layout.messenger.tension);
  if (!r.stitch_tensions.empty()) {
    const auto [lo, hi] = std::minmax_element(r.stitch_tensions.begin(), r.stitch_tensions.end());
    std::fprintf(out,
                 "  stitch wires (mean axial force): %.1f N to %.1f N (design %.6g N), %zu wires\n",
                 *lo, *hi, layout.stitch_wires.front().wire.tension, r.stitch_tensions.size());
  }
  double lo = 0.0, hi = 0.0;
  bool any = false;
  for (std::size_t j = 0; j < layout.registrations.size(); ++j) {
    if (layout.registrations[j].load < 0) continue;
    const double p = r.registration_preloads[j];
    lo = any ? std::min(lo, p) : p;
    hi = any ? std::max(hi, p) : p;
    any = true;
  }
  if (any) std::fprintf(out, "  steady-arm preloads (upward): %.1f N to %.1f N\n", lo, hi);
  std::string offsets;
  for (const double s : layout.dropper_offsets) {
    char text[32];
    std::snprintf(text, sizeof text, "%s%g", offsets.empty() ? "" : ", ", s);
    offsets += text;
  }
  std::fprintf(out, "  dropper unstretched lengths (m) per span%s%s%s:\n",
               offsets.empty() ? "" : ", droppers at ", offsets.c_str(),
               offsets.empty() ? "" : " m from the span's start");
  int span = -1;
  for (std::size_t i = 0; i < layout.droppers.size(); ++i) {
    if (layout.droppers[i].span != span) {
      span = layout.droppers[i].span;
      std::fprintf(out, "%s    span %2d:", i == 0 ? "" : "\n", span + 1);
    }
    std::fprintf(out, " %.4f", r.dropper_lengths[i]);
  }
  std::fprintf(out, "\n");
  std::fflush(out);
}

}  // namespace

void shape_catenary(MPI_Comm comm, model::Model& m, std::FILE* out) {
  if (!m.catenary) return;
  const solvers::ShapeFindingOptions options;
  const double start = MPI_Wtime();
  const solvers::ShapeFindingReport report = solvers::find_catenary_shape(comm, m, options);
  if (mpi_rank(comm) == 0) print_report(out, m, report, MPI_Wtime() - start, options);
}

}  // namespace catena::app

#include "shape_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <variant>

#include "catena/catenary/shape_finding.hpp"
#include "catena/core/mpi_comm.hpp"
#include "log_stage.hpp"

namespace catena::app {
namespace {

void print_axial_mode(std::FILE* out, const model::Model& m) {
  const double omega = cable_dropper_axial_omega(m);
  if (omega <= 0.0) return;
  std::fprintf(out,
               "  cable droppers' first axial mode: up to %.0f Hz (%.0f rad/s, shortest dropper)\n",
               omega / (2.0 * std::numbers::pi), omega);
}

void print_report(std::FILE* out, const model::Model& m, const catenary::ShapeFindingReport& r,
                  double seconds, const catenary::ShapeFindingOptions& options) {
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
  if (m.catenary->window)
    std::fprintf(out,
                 "  window: every span takes the middle span's dropper lengths (found with the "
                 "window's ends anchored, the end spans hang otherwise)\n");
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
  print_axial_mode(out, m);
  std::fflush(out);
}

}  // namespace

double cable_dropper_axial_omega(const model::Model& m) {
  if (!m.catenary) return 0.0;
  double omega = 0.0;
  for (const model::CatenaryDropper& d : m.catenary->droppers) {
    const auto* cable =
        std::get_if<model::CableProps>(&*m.elements[static_cast<std::size_t>(d.element)].props);
    if (!cable || cable->mass_per_length <= 0.0) continue;
    const double l0 = d.mesh_length / (1.0 + cable->prestrain);
    omega = std::max(omega, std::numbers::pi / l0 * std::sqrt(cable->EA / cable->mass_per_length));
  }
  return omega;
}

void warn_unresolved_dropper_mode(const model::Model& m, std::FILE* out) {
  const double omega = cable_dropper_axial_omega(m);
  const model::IntegratorOptions& integrator = m.dynamic_options.integrator;
  // Measured (docs/catenary.md, "Droppers as cables"): re-tensioning cable droppers snap
  // (short taut episodes of their own axial mode); Radau IIA's converge at dt·ω ≤ 0.5,
  // while HHT at dt·ω = 4.2 cut their largest peak from 188 N to 108 N.
  if (omega <= 0.0 || integrator.adaptive || integrator.dt * omega <= 1.0) return;
  std::fprintf(out,
               "catena: warning: the fixed step does not resolve the cable droppers' axial "
               "mode (dt*omega = %.2g > 1): the integrator damps it, and the droppers' "
               "re-tensioning snaps (their peak forces) come out too small; "
               "integrator.dt <= %.2g s resolves it (docs/catenary.md, \"Droppers as "
               "cables\")\n",
               integrator.dt * omega, 1.0 / omega);
}

void shape_catenary(MPI_Comm comm, model::Model& m, std::FILE* out, double progress_seconds) {
  if (!m.catenary) return;
  catenary::ShapeFindingOptions options;
  const double start = MPI_Wtime();
  // A progress line after a whole-structure solve once progress_seconds have passed since
  // the last one (or the start): a long line's solves take tens of seconds each.
  double last_line = start;
  const int rank = mpi_rank(comm);
  options.on_iteration = [&, rank](int iteration, double max_error) {
    const double now = MPI_Wtime();
    if (rank != 0 || progress_seconds <= 0.0 || now - last_line < progress_seconds) return;
    last_line = now;
    std::fprintf(out,
                 "progress: shape finding, whole-structure static solve %d, largest height "
                 "error %.3g mm (tolerance %.3g mm), wall %.0f s\n",
                 iteration, 1e3 * max_error, 1e3 * options.height_tolerance, now - start);
    std::fflush(out);
  };
  const catenary::ShapeFindingReport report = [&] {
    const LogStage stage("Shape finding");
    return catenary::find_catenary_shape(comm, m, options);
  }();
  if (mpi_rank(comm) == 0) print_report(out, m, report, MPI_Wtime() - start, options);
}

}  // namespace catena::app

#include "elasticity_report.hpp"

#include <algorithm>

namespace catena::app {
namespace {

void print_summary_line(std::FILE* out, const char* what, const ElasticityCurve& c,
                        const post::ElasticitySummary& s) {
  std::fprintf(out,
               "%s: max %.6f mm/N at x = %.3f m, min %.6f mm/N at x = %.3f m, mean %.6f mm/N, "
               "uniformity %.4f\n",
               what, s.max, c.x[s.at_max], s.min, c.x[s.at_min], s.mean, s.uniformity);
}

void print_summary_json(std::FILE* out, const post::ElasticitySummary& s) {
  std::fprintf(out, "\"max\": %.17g, \"min\": %.17g, \"mean\": %.17g, \"uniformity\": %.17g", s.max,
               s.min, s.mean, s.uniformity);
}

}  // namespace

void print_elasticity_table(std::FILE* out, const ElasticityCurve& c) {
  std::fprintf(out, "%10s %13s %18s %14s %6s\n", "x (m)", "uplift (mm)", "elasticity (mm/N)",
               "linear (mm/N)", "slack");
  for (std::size_t i = 0; i < c.x.size(); ++i)
    std::fprintf(out, "%10.3f %13.4f %18.6f %14.6f %6d\n", c.x[i], c.uplift[i], c.elasticity[i],
                 c.linear[i], c.slack[i]);
  char under[96];
  std::snprintf(under, sizeof under, "elasticity of span %d under %g N", c.span, c.force);
  print_summary_line(out, under, c, c.summary);
  print_summary_line(out, "linear elasticity (small forces)", c, c.linear_summary);
  std::fprintf(out,
               "uniformity u = (max - min) / (max + min) = %.4f under %g N, %.4f linear "
               "(EN 50119)\n",
               c.summary.uniformity, c.force, c.linear_summary.uniformity);
  std::fflush(out);
}

void print_elasticity_json(std::FILE* out, const ElasticityCurve& c) {
  std::fprintf(out, "{\"span\": %d, \"force\": %.17g, \"points\": [\n", c.span, c.force);
  for (std::size_t i = 0; i < c.x.size(); ++i)
    std::fprintf(out,
                 "  {\"x\": %.17g, \"uplift\": %.17g, \"elasticity\": %.17g, "
                 "\"linear_elasticity\": %.17g, \"slack_droppers\": %d}%s\n",
                 c.x[i], c.uplift[i], c.elasticity[i], c.linear[i], c.slack[i],
                 i + 1 < c.x.size() ? "," : "");
  std::fprintf(out, "], ");
  print_summary_json(out, c.summary);
  std::fprintf(out, ", \"linear\": {");
  print_summary_json(out, c.linear_summary);
  std::fprintf(out, "}}\n");
  std::fflush(out);
}

void warn_slack_droppers(const ElasticityCurve& c) {
  std::size_t points = 0, first = 0, last = 0;
  int most = 0;
  for (std::size_t i = 0; i < c.slack.size(); ++i) {
    if (c.slack[i] == 0) continue;
    if (points++ == 0) first = i;
    last = i;
    most = std::max(most, c.slack[i]);
  }
  if (points == 0) return;
  std::fprintf(stderr,
               "catena: warning: under %g N droppers go slack at %zu of %zu points (x = %.3f to "
               "%.3f m, up to %d at a point): the elasticity there is that of a line with slack "
               "droppers; the linear elasticity column is the small-force value EN 50119 "
               "means (or lower --force)\n",
               c.force, points, c.x.size(), c.x[first], c.x[last], most);
}

}  // namespace catena::app

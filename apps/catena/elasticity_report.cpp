#include "elasticity_report.hpp"

namespace catena::app {

void print_elasticity_table(std::FILE* out, const ElasticityCurve& c) {
  std::fprintf(out, "%10s %13s %18s\n", "x (m)", "uplift (mm)", "elasticity (mm/N)");
  for (std::size_t i = 0; i < c.x.size(); ++i)
    std::fprintf(out, "%10.3f %13.4f %18.6f\n", c.x[i], c.uplift[i], c.elasticity[i]);
  const post::ElasticitySummary& s = c.summary;
  std::fprintf(out,
               "elasticity of span %d under %g N: max %.6f mm/N at x = %.3f m, min %.6f mm/N "
               "at x = %.3f m, mean %.6f mm/N\n",
               c.span, c.force, s.max, c.x[s.at_max], s.min, c.x[s.at_min], s.mean);
  std::fprintf(out, "uniformity u = (max - min) / (max + min) = %.4f (EN 50119)\n", s.uniformity);
  std::fflush(out);
}

void print_elasticity_json(std::FILE* out, const ElasticityCurve& c) {
  std::fprintf(out, "{\"span\": %d, \"force\": %.17g, \"points\": [\n", c.span, c.force);
  for (std::size_t i = 0; i < c.x.size(); ++i)
    std::fprintf(out, "  {\"x\": %.17g, \"uplift\": %.17g, \"elasticity\": %.17g}%s\n", c.x[i],
                 c.uplift[i], c.elasticity[i], i + 1 < c.x.size() ? "," : "");
  const post::ElasticitySummary& s = c.summary;
  std::fprintf(out, "], \"max\": %.17g, \"min\": %.17g, \"mean\": %.17g, \"uniformity\": %.17g}\n",
               s.max, s.min, s.mean, s.uniformity);
  std::fflush(out);
}

}  // namespace catena::app

#pragma once
// What `catena elasticity` prints: the elasticity curve of one span as a table or as JSON
// (docs/catenary.md, "Elasticity"). Not collective: rank 0 calls these.
#include <cstdio>
#include <vector>

#include "catena/post/elasticity_summary.hpp"

namespace catena::app {

struct ElasticityCurve {
  int span = 0;        // 1-based
  double force = 0.0;  // N, the static upward force
  // Per point, in the span's order:
  std::vector<double> x;                   // m along the track from the span's start support
  std::vector<double> uplift;              // mm
  std::vector<double> elasticity;          // mm/N, under `force`
  std::vector<double> linear;              // mm/N, the linear (small-force) elasticity
  std::vector<int> slack;                  // droppers taut at rest and slack under `force`
  post::ElasticitySummary summary;         // of `elasticity`, mm/N
  post::ElasticitySummary linear_summary;  // of `linear`, mm/N
};

// The table (x, uplift, elasticity, linear elasticity, slack droppers) and the summary
// lines.
void print_elasticity_table(std::FILE* out, const ElasticityCurve& curve);
// {"span": N, "force": F, "points": [{"x", "uplift", "elasticity", "linear_elasticity",
// "slack_droppers"}], "max", "min", "mean", "uniformity", "linear": {"max", "min", "mean",
// "uniformity"}}: x in m, uplift in mm, elasticities in mm/N.
void print_elasticity_json(std::FILE* out, const ElasticityCurve& curve);
// A warning (stderr) when droppers go slack under the force: where, and that the linear
// elasticity is the line's small-force value. Nothing when none do.
void warn_slack_droppers(const ElasticityCurve& curve);

}  // namespace catena::app

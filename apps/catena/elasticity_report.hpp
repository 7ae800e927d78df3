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
  std::vector<double> x;            // m along the track from the span's start support
  std::vector<double> uplift;       // mm
  std::vector<double> elasticity;   // mm/N
  post::ElasticitySummary summary;  // of `elasticity`, mm/N
};

// The table (x, uplift, elasticity) and the summary lines.
void print_elasticity_table(std::FILE* out, const ElasticityCurve& curve);
// {"span": N, "force": F, "points": [{"x", "uplift", "elasticity"}], "max", "min", "mean",
// "uniformity"}: x in m, uplift in mm, elasticity in mm/N.
void print_elasticity_json(std::FILE* out, const ElasticityCurve& curve);

}  // namespace catena::app

#pragma once
// Summary of a static elasticity curve (EN 50119): its largest, smallest and mean value
// over the points of a span and the uniformity coefficient
//
//   u = (e_max − e_min) / (e_max + e_min),
//
// 0 for a perfectly uniform span, 1 when the elasticity vanishes somewhere (a fixed point).
// The mean is the arithmetic mean of the points (the span average for equally spaced
// points). Pure function: no files, no MPI; any consistent unit (m/N, mm/N).
#include <cstddef>
#include <span>

namespace catena::post {

struct ElasticitySummary {
  double max = 0.0, min = 0.0, mean = 0.0;
  double uniformity = 0.0;             // 0 when e_max + e_min = 0
  std::size_t at_max = 0, at_min = 0;  // indices of the (first) largest and smallest value
};

// Not collective. `elasticity` must not be empty.
ElasticitySummary summarize_elasticity(std::span<const double> elasticity);

}  // namespace catena::post

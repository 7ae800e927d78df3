#include "catena/post/elasticity_summary.hpp"

#include <algorithm>
#include <numeric>

#include "catena/core/error.hpp"

namespace catena::post {

ElasticitySummary summarize_elasticity(std::span<const double> elasticity) {
  CATENA_ASSERT(!elasticity.empty(), "an elasticity curve needs at least one point");
  ElasticitySummary s;
  const auto lo = std::min_element(elasticity.begin(), elasticity.end());
  const auto hi = std::max_element(elasticity.begin(), elasticity.end());
  s.at_min = static_cast<std::size_t>(lo - elasticity.begin());
  s.at_max = static_cast<std::size_t>(hi - elasticity.begin());
  s.min = *lo;
  s.max = *hi;
  s.mean = std::accumulate(elasticity.begin(), elasticity.end(), 0.0) /
           static_cast<double>(elasticity.size());
  const double sum = s.max + s.min;
  s.uniformity = sum != 0.0 ? (s.max - s.min) / sum : 0.0;
  return s;
}

}  // namespace catena::post

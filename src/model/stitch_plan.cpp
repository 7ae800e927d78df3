#include "stitch_plan.hpp"

#include <algorithm>
#include <limits>

namespace catena::model::detail {

std::vector<std::vector<double>> stitch_clamp_stations(const CatenaryDesign& d) {
  const std::size_t n_spans = d.span_lengths.size();
  std::vector<std::vector<double>> clamps(n_spans);
  if (!d.stitch) return clamps;
  const double half = 0.5 * d.stitch->length;
  for (std::size_t span = 0; span < n_spans; ++span) {
    if (span > 0) clamps[span].push_back(half);  // the stitch at the span's start support
    if (span + 1 < n_spans) clamps[span].push_back(d.span_lengths[span] - half);
  }
  return clamps;
}

int stitch_carrying(const CatenaryDesign& d, std::size_t span, double s) {
  if (!d.stitch) return -1;
  const double half = 0.5 * d.stitch->length;
  // The clamp stations are computed the same way (stitch_clamp_stations), so a dropper given
  // exactly on a clamp compares equal and stays on the messenger.
  if (span > 0 && s < half) return static_cast<int>(span) - 1;
  if (span + 1 < d.span_lengths.size() && s > d.span_lengths[span] - half)
    return static_cast<int>(span);
  return -1;
}

StitchPlan plan_stitch(const Vec3& first_clamp, const Vec3& last_clamp,
                       const std::vector<double>& dropper_x, double element_length) {
  StitchPlan plan;
  plan.shortest_element = std::numeric_limits<double>::infinity();
  std::vector<double> stations{first_clamp.x()};
  stations.insert(stations.end(), dropper_x.begin(), dropper_x.end());
  stations.push_back(last_clamp.x());
  const double span = last_clamp.x() - first_clamp.x();
  plan.positions.push_back(first_clamp);
  for (std::size_t k = 0; k + 1 < stations.size(); ++k) {
    const double gap = stations[k + 1] - stations[k];
    const int n = elements_in_gap(gap, element_length);
    for (int e = 1; e <= n; ++e) {
      const bool last = e == n && k + 2 == stations.size();
      const double x = stations[k] + gap * static_cast<double>(e) / static_cast<double>(n);
      plan.positions.push_back(
          last ? last_clamp
               : Vec3(first_clamp + (last_clamp - first_clamp) * ((x - first_clamp.x()) / span)));
      const int node = static_cast<int>(plan.positions.size()) - 1;
      plan.elements.emplace_back(node - 1, node);
      plan.shortest_element =
          std::min(plan.shortest_element, (plan.positions[node] - plan.positions[node - 1]).norm());
      if (e == n && k + 2 < stations.size()) plan.dropper_nodes.push_back(node);
    }
  }
  return plan;
}

}  // namespace catena::model::detail

#pragma once
// Where the stitch wires of a catenary go (catenary.stitch, docs/catenary.md "Stitch
// wires"): the clamp points they add to the messenger's stations, which droppers they
// carry, and each stitch wire's own nodes and elements. The builder (catenary_builder)
// adds them to the model.
//
// Stitch wire k sits at intermediate support k + 1 (support_x index) and runs from its
// first clamp, length/2 before the support (in span k), to its last clamp, length/2 after
// it (in span k + 1); the reader has checked that both lie strictly inside their spans and
// that the stitch wires at the two ends of a span do not meet. A dropper strictly between
// the two clamps hangs from the stitch wire; one on a clamp point hangs from the messenger.
#include <utility>
#include <vector>

#include "catena/core/vec3.hpp"
#include "catenary_builder.hpp"

namespace catena::model::detail {

// Not collective. Per span, the distances from its start support of the stitch clamps in
// it (none without stitch wires, else one in the first and last span, two in the others),
// increasing.
std::vector<std::vector<double>> stitch_clamp_stations(const CatenaryDesign& d);

// Not collective. The stitch wire that carries the dropper at distance s from the start of
// span `span` (0-based), or −1 when it hangs from the messenger.
int stitch_carrying(const CatenaryDesign& d, std::size_t span, double s);

// One stitch wire's mesh: straight from the messenger's reference position at its first
// clamp to that at its last, a node at each dropper it carries, each gap between these
// stations cut into the fewest equal elements no longer than the element length.
struct StitchPlan {
  std::vector<Vec3> positions;                // new nodes in x order; first, last: the clamps
  std::vector<std::pair<int, int>> elements;  // local node numbers, in x order
  std::vector<int> dropper_nodes;             // local node of each dropper it carries, x order
  double shortest_element = 0.0;              // m
};

// Not collective. `dropper_x`: the x of the droppers it carries, increasing and strictly
// between the clamps' x.
StitchPlan plan_stitch(const Vec3& first_clamp, const Vec3& last_clamp,
                       const std::vector<double>& dropper_x, double element_length);

}  // namespace catena::model::detail

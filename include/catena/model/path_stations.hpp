#pragma once
// Arc length along a path of elements (model::ElementPath, a moving load's elements),
// measured on the reference geometry as the sum of the elements' chords: the coordinate in
// which moving loads and pantograph contacts travel, and which `catena check` reports.
#include <cstddef>
#include <vector>

#include "catena/model/model.hpp"

namespace catena::model {

// Not collective. Chord of element e between its end nodes on the reference geometry, m.
double element_chord(const Model& model, int element);

// Stations of a path: start[i] is the arc length at the start of its element i, and the
// last entry the path's length.
struct PathStations {
  std::vector<double> start;  // n_elements + 1, ascending, start[0] = 0

  double length() const { return start.back(); }
  bool contains(double s) const { return s >= 0.0 && s <= length(); }
  // The element (index into the path) holding s ∈ [0, length()]: at a boundary between two
  // elements, the first.
  std::size_t element_at(double s) const;
  double element_length(std::size_t i) const { return start[i + 1] - start[i]; }
};

// Not collective.
PathStations path_stations(const Model& model, const std::vector<int>& elements);

// Not collective. The point at arc length s (clamped to [0, length]) of the path `elements`
// on the reference geometry, on the chord of the element holding it: where a moving load
// or a pantograph's contact is at s. Consecutive elements share a node; each element is
// walked from that shared node, whatever the order of its own nodes.
Vec3 path_point(const Model& model, const std::vector<int>& elements, const PathStations& stations,
                double s);

// Not collective. Whether path element i (index into `elements`) is walked from its last
// node to its first: consecutive elements share a node, and each is walked from the node it
// shares with the one before (the first: away from the node it shares with the next).
bool element_reversed(const Model& model, const std::vector<int>& elements, std::size_t i);

// Not collective. The path elements (indices into `elements`, ascending) a pantograph's
// contact point can reach within the analysis: from its start to where its velocity takes
// it by analysis.duration (its start alone in a static analysis), widened by one metre on
// either side. A head is coupled to these elements' nodes only, not to its whole path: on a
// 20 km line a pantograph crosses a few hundred metres of it.
struct PathReach {
  std::size_t first = 0, last = 0;  // the elements first..last (inclusive); none if empty
  bool empty = true;
  bool contains(std::size_t i) const { return !empty && i >= first && i <= last; }
};
PathReach contact_reach(const Model& model, const MovingContact& contact,
                        const PathStations& stations);

}  // namespace catena::model

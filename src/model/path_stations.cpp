#include "catena/model/path_stations.hpp"

#include <algorithm>

namespace catena::model {

double element_chord(const Model& model, int element) {
  const auto& nodes = model.elements[static_cast<std::size_t>(element)].nodes;
  return (model.nodes[static_cast<std::size_t>(nodes.back())].position -
          model.nodes[static_cast<std::size_t>(nodes.front())].position)
      .norm();
}

std::size_t PathStations::element_at(double s) const {
  const auto it = std::upper_bound(start.begin() + 1, start.end() - 1, s);
  return static_cast<std::size_t>(it - start.begin()) - 1;
}

PathStations path_stations(const Model& model, const std::vector<int>& elements) {
  PathStations p;
  p.start.reserve(elements.size() + 1);
  p.start.push_back(0.0);
  for (int e : elements) p.start.push_back(p.start.back() + element_chord(model, e));
  return p;
}

bool element_reversed(const Model& model, const std::vector<int>& elements, std::size_t i) {
  const auto& nodes = model.elements[static_cast<std::size_t>(elements[i])].nodes;
  const auto shares = [&](std::size_t j, int node) {
    const auto& other = model.elements[static_cast<std::size_t>(elements[j])].nodes;
    return node == other.front() || node == other.back();
  };
  return (i > 0 && shares(i - 1, nodes.back())) ||
         (i == 0 && elements.size() > 1 && shares(1, nodes.front()));
}

Vec3 path_point(const Model& model, const std::vector<int>& elements, const PathStations& stations,
                double s) {
  s = std::clamp(s, 0.0, stations.length());
  const std::size_t i = stations.element_at(s);
  const auto& nodes = model.elements[static_cast<std::size_t>(elements[i])].nodes;
  int from = nodes.front(), to = nodes.back();
  if (element_reversed(model, elements, i)) std::swap(from, to);
  const double length = stations.element_length(i);
  const double xi = length > 0.0 ? (s - stations.start[i]) / length : 0.0;
  const Vec3& a = model.nodes[static_cast<std::size_t>(from)].position;
  const Vec3& b = model.nodes[static_cast<std::size_t>(to)].position;
  return a + xi * (b - a);
}

PathReach contact_reach(const Model& model, const MovingContact& contact,
                        const PathStations& stations) {
  constexpr double kMargin = 1.0;  // m: far above round-off in start + speed·t
  const double t_end =
      model.analysis == AnalysisType::dynamic ? model.dynamic_options.duration : 0.0;
  double s0 = contact.start, s1 = contact.start + contact.speed * t_end;
  if (model.catenary && model.catenary->window && !model.contacts.empty()) {
    // A window moves its pantographs back a period whenever the first passes span
    // behind + period: they stay within a period of where they are then, plus the travel of
    // the step that takes the first past it (at most a span).
    const CatenaryWindow& w = *model.catenary->window;
    const double d = contact.start - model.contacts.front().start;
    s0 = std::min(w.behind * w.span_arc + d, contact.start);
    s1 = (w.behind + w.period + 1) * w.span_arc + d;
  }
  const double low = std::min(s0, s1) - kMargin, high = std::max(s0, s1) + kMargin;
  PathReach r;
  if (stations.start.size() < 2 || high < 0.0 || low > stations.length()) return r;
  r.first = stations.element_at(std::max(low, 0.0));
  r.last = stations.element_at(std::min(high, stations.length()));
  r.empty = false;
  return r;
}

}  // namespace catena::model

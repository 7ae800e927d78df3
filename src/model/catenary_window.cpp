#include "catena/model/catenary_window.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <variant>

#include "catena/core/error.hpp"

namespace catena::model {
namespace {

constexpr double kTolerance = 1e-6;  // m: far above the builder's round-off, below any element

bool same_point(const Vec3& a, const Vec3& b) { return (a - b).cwiseAbs().maxCoeff() < kTolerance; }

// The nodes at a point: nodes sorted by x, searched within the tolerance.
class NodeLocator {
 public:
  explicit NodeLocator(const Model& m) : m_(m) {
    for (std::size_t n = 0; n < m.nodes.size(); ++n) order_.push_back(static_cast<int>(n));
    std::sort(order_.begin(), order_.end(), [&](int a, int b) { return x(a) < x(b); });
  }
  std::vector<int> at(const Vec3& p) const {
    auto first = std::lower_bound(order_.begin(), order_.end(), p.x() - kTolerance,
                                  [&](int n, double v) { return x(n) < v; });
    std::vector<int> out;
    for (; first != order_.end() && x(*first) <= p.x() + kTolerance; ++first)
      if (same_point(m_.nodes[static_cast<std::size_t>(*first)].position, p)) out.push_back(*first);
    return out;
  }

 private:
  double x(int n) const { return m_.nodes[static_cast<std::size_t>(n)].position.x(); }
  const Model& m_;
  std::vector<int> order_;
};

[[noreturn]] void fail_not_repeating(const Model& m, int node, const std::string& why) {
  std::ostringstream os;
  const Vec3& p = m.nodes[static_cast<std::size_t>(node)].position;
  os << "catenary.window: the built window does not repeat after its period: node "
     << m.nodes[static_cast<std::size_t>(node)].id << " at (" << p.x() << ", " << p.y() << ", "
     << p.z() << ") m " << why;
  throw Error(os.str());
}

}  // namespace

std::vector<int> window_state_sources(const Model& m, WindowImage image) {
  CATENA_ASSERT(m.catenary && m.catenary->window, "the model has a window");
  const CatenaryWindow& w = *m.catenary->window;
  const Vec3 shift(image == WindowImage::ahead ? w.shift_x() : -w.shift_x(), 0.0, 0.0);
  const double x_start = m.catenary->support_x.front(), x_end = m.catenary->support_x.back();
  // Where x + shift lies beyond the window, or on its end.
  const auto outside = [&](double x) {
    return x + shift.x() > x_end + kTolerance || x + shift.x() < x_start - kTolerance;
  };
  const auto on_end = [&](double x) {
    return std::abs(x + shift.x() - x_end) < kTolerance ||
           std::abs(x + shift.x() - x_start) < kTolerance;
  };
  constexpr int kUnset = -2;
  std::vector<int> source(m.nodes.size(), kUnset);
  for (const MovingContact& c : m.contacts)
    for (const int n : pantograph_nodes(c)) source[static_cast<std::size_t>(n)] = n;
  const NodeLocator locate(m);
  // Elements by their first node, to find an element's copy one period ahead.
  std::vector<std::vector<int>> starting(m.nodes.size());
  for (std::size_t e = 0; e < m.elements.size(); ++e)
    starting[static_cast<std::size_t>(m.elements[e].nodes.front())].push_back(static_cast<int>(e));
  const auto position = [&](int n) { return m.nodes[static_cast<std::size_t>(n)].position; };
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const ElementDesc& element = m.elements[e];
    const int first = element.nodes.front();
    if (source[static_cast<std::size_t>(first)] == first) continue;  // a pantograph's
    bool beyond = false;
    for (const int n : element.nodes) beyond = beyond || outside(position(n).x());
    if (beyond) continue;  // its copy lies ahead of the window: its nodes may enter
    // The element one period ahead: the same kind, its nodes at the shifted points.
    int copy = -1, copies = 0;
    for (const int candidate_first : locate.at(position(first) + shift))
      for (const int candidate : starting[static_cast<std::size_t>(candidate_first)]) {
        const ElementDesc& other = m.elements[static_cast<std::size_t>(candidate)];
        // The same set too: a stitch wire's reference line lies on the messenger's.
        if (other.props->index() != element.props->index() || other.set != element.set ||
            other.nodes.size() != element.nodes.size())
          continue;
        bool match = true;
        for (std::size_t k = 0; k < element.nodes.size() && match; ++k)
          match = same_point(position(other.nodes[k]), position(element.nodes[k]) + shift);
        if (match) {
          copy = candidate;
          ++copies;
        }
      }
    // A staggered wire's joint at the last support of the window's overlap: the window
    // ends there, with one node per wire and no joint.
    bool at_end = true;
    for (const int n : element.nodes) at_end = at_end && on_end(position(n).x());
    if (copies == 0 && at_end) continue;
    if (copies != 1)
      fail_not_repeating(m, first,
                         copies == 0 ? "starts an element with no copy one period away"
                                     : "starts an element with more than one copy one period away");
    const ElementDesc& other = m.elements[static_cast<std::size_t>(copy)];
    for (std::size_t k = 0; k < element.nodes.size(); ++k) {
      int& s = source[static_cast<std::size_t>(element.nodes[k])];
      if (s != kUnset && s != other.nodes[k])
        fail_not_repeating(m, element.nodes[k], "has two different nodes one period away");
      s = other.nodes[k];
    }
  }
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    if (source[n] != kUnset) continue;
    // The nodes of the last period enter, and so does a staggered wire's node that starts
    // the last period (its copy would lie at the window's end).
    const double x = m.nodes[n].position.x();
    if (!outside(x) && !on_end(x))
      fail_not_repeating(m, static_cast<int>(n), "has no copy one period away");
    source[n] = kWindowEnters;
  }
  return source;
}

}  // namespace catena::model

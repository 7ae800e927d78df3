// `catenary.window` (model/catenary_window_reader.hpp, model/catenary_window.hpp): a few spans
// of a longer line placed around the first pantograph, and the map by which the line's state
// moves one period when the window moves. Base scene: tests/data/app/catenary_pantograph.yaml
// (60 m spans, element_length 1 m, a pantograph at 300 km/h from 40 m), made a 20-span
// line by --set.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "catena/model/catenary_window.hpp"
#include "catena/model/scene_reader.hpp"
#include "input_errors.hpp"

namespace {

namespace fs = std::filesystem;
using namespace catena;
using namespace catena::model;

const std::string scene_file =
    (fs::path(CATENA_TEST_DATA) / "app" / "catenary_pantograph.yaml").string();

Model read_window(std::vector<std::string> overrides) {
  overrides.insert(overrides.begin(), {"catenary.spans=20", "catenary.window.spans=6"});
  return read_scene(scene_file, overrides);
}

std::set<int> pantograph_node_set(const Model& m) {
  std::set<int> nodes;
  for (const MovingContact& c : m.contacts)
    for (const int n : pantograph_nodes(c)) nodes.insert(n);
  return nodes;
}

// Every catenary node's image lies `dx` along x (or enters), every pantograph node is its
// own, and no two nodes share an image.
void expect_images(const Model& m, WindowImage image, double dx) {
  const std::vector<int> source = window_state_sources(m, image);
  ASSERT_EQ(source.size(), m.nodes.size());
  const std::set<int> pantograph = pantograph_node_set(m);
  const double x0 = m.catenary->support_x.front(), x1 = m.catenary->support_x.back();
  std::set<int> used;
  int entering = 0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    const int s = source[n];
    if (pantograph.contains(static_cast<int>(n))) {
      EXPECT_EQ(s, static_cast<int>(n));
      continue;
    }
    const double x = m.nodes[n].position.x() + dx;
    if (s == kWindowEnters) {
      ++entering;
      EXPECT_TRUE(x > x1 - 1e-6 || x < x0 + 1e-6) << "node " << n << " could have an image";
      continue;
    }
    EXPECT_TRUE(used.insert(s).second) << "two nodes take node " << s;
    const Vec3 expected = m.nodes[n].position + Vec3(dx, 0.0, 0.0);
    EXPECT_LT((m.nodes[static_cast<std::size_t>(s)].position - expected).norm(), 1e-6)
        << "node " << n;
  }
  EXPECT_GT(entering, 0);
}

TEST(CatenaryWindow, PlacedBehindTheFirstPantographOnTheLine) {
  // Start 40 m: span 0 of the line; two spans behind it: the window starts at span -2.
  const Model m = read_window({});
  ASSERT_TRUE(m.catenary && m.catenary->window);
  const CatenaryWindow& w = *m.catenary->window;
  EXPECT_EQ(w.spans, 6);
  EXPECT_EQ(w.behind, 2);
  EXPECT_EQ(w.period, 1);
  EXPECT_EQ(w.line_spans, 20);
  EXPECT_EQ(w.origin_span, -2);
  EXPECT_NEAR(w.span_arc, 60.0, 1e-9);  // chords of 1 m elements summed
  EXPECT_EQ(m.catenary->support_x.size(), 7u);
  EXPECT_DOUBLE_EQ(m.catenary->support_x.front(), -120.0);
  EXPECT_DOUBLE_EQ(m.catenary->support_x.back(), 240.0);
  EXPECT_TRUE(m.catenary->absorbing_ends);
  // The pantograph along the window's path, the evaluation section along the line's.
  EXPECT_NEAR(m.contacts.front().start, 160.0, 1e-9);
  EXPECT_NEAR(m.evaluation_start, 60.0, 1e-9);
  EXPECT_NEAR(m.evaluation_end, 120.0, 1e-9);
  EXPECT_EQ(m.catenary->droppers.size(), 6u * 9u);
}

TEST(CatenaryWindow, EachNodeTakesItsImageOnePeriodAway) {
  const Model m = read_window({});
  expect_images(m, WindowImage::ahead, 60.0);
  expect_images(m, WindowImage::behind, -60.0);
}

TEST(CatenaryWindow, StaggeredWiresRepeatEveryTwoSpans) {
  // Stagger alternates at the supports, and each span has its own nodes there: the period
  // is two spans, and the window starts on an even span of the line.
  const Model m =
      read_window({"catenary.dimension=3", "catenary.stagger=0.2", "pantographs[0].start=130"});
  const CatenaryWindow& w = *m.catenary->window;
  EXPECT_EQ(w.period, 2);
  EXPECT_EQ(w.origin_span % 2, 0);
  EXPECT_EQ(w.origin_span, 0);  // span 2 of the line, two behind
  expect_images(m, WindowImage::ahead, 120.0);
  expect_images(m, WindowImage::behind, -120.0);
}

TEST(CatenaryWindow, CableDroppersRepeatToo) {
  const Model m = read_window({"catenary.window.spans=7", "catenary.droppers.model=cable",
                               "catenary.droppers.elements=2", "catenary.droppers.EI=1",
                               "catenary.droppers.mass_per_length=0.1"});
  expect_images(m, WindowImage::ahead, 60.0);
  expect_images(m, WindowImage::behind, -60.0);
}

// The scene's pantograph and a second one, `second` its speed and start.
std::string two_pantographs(const std::string& second) {
  return "pantographs=[{name: leading, path: contact_wire, speed_kmh: 300, start: 40, "
         "static_force: 120, model: en50318}, {name: second, path: contact_wire, " +
         second + ", static_force: 120, model: en50318}]";
}

TEST(CatenaryWindow, BadInputNamesTheKeyAndWhatIsAccepted) {
  const std::vector<test::InputErrorCase> cases{
      {{"catenary.window.spans=2"}, {"catenary.window.spans", "spans >= 4"}},
      {{"catenary.window.spans=20"}, {"catenary.window.spans", "models no less than the line"}},
      {{"catenary.window.behind=0"}, {"catenary.window.behind", "[1, 1000]"}},
      {{"catenary.window.ahead=1"}, {"catenary.window", "ahead"}},
      {{"catenary.spans=auto", "catenary.span_length=60"}, {"catenary.spans", "'auto'"}},
      {{"catenary.ends=anchored"}, {"catenary.ends", "absorbing ends"}},
      {{"analysis={type: static}"}, {"catenary.window", "dynamic run"}},
      {{"catenary.stitch={length: 18, EA: 1e6, EI: 10, mass_per_length: 0.5, tension: 2800}"},
       {"catenary.stitch", "not available with a window"}},
      {{"analysis.structure=modal"}, {"analysis.structure", "not available"}},
      {{"integrator.type=bdf"}, {"integrator.type", "cannot follow a window"}},
      {{"masses=[{node: 1, mass: 2}]"}, {"masses", "catenary and its pantographs only"}},
      {{"pantographs[0].direction=backward"}, {"pantographs[0].direction", "forward"}},
      {{two_pantographs("speed_kmh: 250, start: 0")}, {"pantographs[1]", "same speed"}},
      {{two_pantographs("speed_kmh: 300, start: 300")}, {"pantographs[1].start", "more spans"}},
  };
  test::expect_input_errors([](const auto& o) { read_window(o); }, "catenary_pantograph.yaml",
                            cases);
}

}  // namespace

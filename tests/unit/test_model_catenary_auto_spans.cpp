// `catenary: {spans: auto}`: the run's length and speed decide the span count — the spans
// up to the one holding the farthest point a pantograph reaches in analysis.duration, plus
// run_out_spans (default 2). Base scene: tests/data/app/catenary_pantograph.yaml (3 spans of
// 60 m, a pantograph at 300 km/h from x = 40 m, 1.2 s: it reaches 140 m), varied by --set.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "catena/model/scene_reader.hpp"
#include "input_errors.hpp"

namespace {

namespace fs = std::filesystem;
using namespace catena;
using namespace catena::model;

const std::string scene_file =
    (fs::path(CATENA_TEST_DATA) / "app" / "catenary_pantograph.yaml").string();

Model read_with(std::vector<std::string> overrides) {
  overrides.insert(overrides.begin(), "catenary.spans=auto");
  return read_scene(scene_file, overrides);
}

TEST(CatenaryAutoSpans, ReachPlusTwoRunOutSpansByDefault) {
  // 40 m + 83.333 m/s * 1.2 s = 140 m lies in span 3 (120-180 m): 3 + 2 = 5 spans.
  const Model m = read_with({});
  ASSERT_TRUE(m.catenary.has_value());
  const CatenaryLayout& c = *m.catenary;
  EXPECT_EQ(c.support_x, (std::vector<double>{0, 60, 120, 180, 240, 300}));
  ASSERT_TRUE(c.auto_spans.has_value());
  EXPECT_NEAR(c.auto_spans->reach, 140.0, 1e-9);
  EXPECT_EQ(c.auto_spans->pantograph, "leading");
  EXPECT_DOUBLE_EQ(c.auto_spans->duration, 1.2);
  EXPECT_EQ(c.auto_spans->run_out_spans, 2);
  EXPECT_EQ(c.droppers.size(), 5u * 9u);
  EXPECT_EQ(c.registrations.size(), 4u);
}

TEST(CatenaryAutoSpans, SpanCountFollowsDurationSpeedAndRunOut) {
  struct Case {
    std::vector<std::string> overrides;
    std::size_t spans;
  };
  const std::vector<Case> cases{
      {{"catenary.run_out_spans=0"}, 3},                            // 140 m: span 3
      {{"analysis.duration=2.0"}, 6},                               // 206.7 m: span 4, + 2
      {{"pantographs[0].speed_kmh=72", "analysis.duration=4"}, 4},  // exactly 120 m: span 2
      {{"pantographs[0].speed_kmh=0"}, 3},                          // standing at 40 m
      {{"catenary.span_length=50", "catenary.droppers.positions=[5, 25, 45]"}, 5},  // 140/50
  };
  for (const Case& c : cases) {
    const Model m = read_with(c.overrides);
    EXPECT_EQ(m.catenary->support_x.size(), c.spans + 1) << c.overrides.front();
  }
}

TEST(CatenaryAutoSpans, FarthestOfSeveralPantographsDecides) {
  const Model m = read_with(
      {"pantographs=[{name: slow, path: contact_wire, speed: 10, start: 0, static_force: 100, "
       "model: en50318}, {name: fast, path: contact_wire, speed: 150, start: 0, static_force: "
       "100, model: en50318}]"});
  ASSERT_TRUE(m.catenary->auto_spans.has_value());
  EXPECT_EQ(m.catenary->auto_spans->pantograph, "fast");
  EXPECT_NEAR(m.catenary->auto_spans->reach, 180.0, 1e-9);  // exactly 3 spans, + 2
  EXPECT_EQ(m.catenary->support_x.size(), 6u);
}

TEST(CatenaryAutoSpans, AnExplicitCountIsUnchanged) {
  const Model m = read_scene(scene_file);
  EXPECT_EQ(m.catenary->support_x.size(), 4u);
  EXPECT_FALSE(m.catenary->auto_spans.has_value());
}

TEST(CatenaryAutoSpans, BadInputNamesTheKeyAndWhatIsAccepted) {
  const std::vector<test::InputErrorCase> cases{
      {{"catenary.spans=auto", "analysis={type: static}"},
       {"catenary.spans", "sizes the line to a dynamic run", "'static'"}},
      {{"catenary.spans=auto", "pantographs=[]"},
       {"catenary.spans", "no pantograph runs on the contact wire"}},
      {{"catenary.spans=auto", "catenary.span_length="},
       {"catenary.span_length", "no value given"}},
      {{"catenary.spans=auto", "catenary.span_lengths=[60, 60]"},
       {"catenary.span_lengths", "not both"}},
      {{"catenary.run_out_spans=1"}, {"catenary.run_out_spans", "goes with 'spans: auto'"}},
      {{"catenary.spans=auto", "catenary.run_out_spans=-1"},
       {"catenary.run_out_spans", "[0, 10000]"}},
      {{"catenary.spans=many"}, {"catenary.spans", "or 'auto'", "many"}},
      {{"catenary.spans=auto", "pantographs[0].speed_kmh=36000", "analysis.duration=1000"},
       {"catenary.spans", "at most 10000"}},
  };
  test::expect_input_errors([](const auto& o) { read_scene(scene_file, o); },
                            "catenary_pantograph.yaml", cases);
}

}  // namespace

// The scene's `moving_loads` become model::MovingLoad: the path is the named lines'
// elements in order, speeds convert from km/h, defaults apply, and the path, speed and
// start are checked. Malformed files: tests/data/bad_scenes/moving_load*.yaml (run by
// test_model_scene_errors.cpp); the cases here vary one key of the good scene by --set.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "catena/core/error.hpp"
#include "catena/model/scene_reader.hpp"
#include "input_errors.hpp"

namespace {

namespace fs = std::filesystem;
using namespace catena;
using namespace catena::model;

const std::string moving_load_scene =
    (fs::path(CATENA_TEST_DATA) / "good_scenes" / "moving_load.yaml").string();

std::vector<std::int64_t> element_ids(const Model& m, const std::vector<int>& elements) {
  std::vector<std::int64_t> ids;
  for (int e : elements) ids.push_back(m.elements[e].id);
  return ids;
}

std::vector<std::int64_t> ids_from(std::int64_t first, std::int64_t last) {
  std::vector<std::int64_t> ids;
  for (std::int64_t id = first; id <= last; ++id) ids.push_back(id);
  return ids;
}

// The message of the InputError that reading the good scene with `overrides` throws.
std::string error_with(const std::vector<std::string>& overrides) {
  return test::input_error_message([&] { read_scene(moving_load_scene, overrides); });
}

TEST(MovingLoads, PathSpeedStartAndDefaultsFromTheScene) {
  const Model m = read_scene(moving_load_scene);
  ASSERT_EQ(m.moving_loads.size(), 2u);

  const MovingLoad& leading = m.moving_loads[0];
  EXPECT_EQ(leading.name, "leading");
  // Line elements are numbered in line order: span1 holds 1..10, span2 11..30.
  EXPECT_EQ(element_ids(m, leading.elements), ids_from(1, 30));
  EXPECT_EQ(leading.force, Vec3(0, 0, 120));
  EXPECT_DOUBLE_EQ(leading.speed, 50.0);  // 180 km/h
  EXPECT_EQ(leading.start, 0.0);
  EXPECT_EQ(leading.start_time, 0.0);

  const MovingLoad& trailing = m.moving_loads[1];
  EXPECT_EQ(trailing.name, "trailing");
  EXPECT_EQ(element_ids(m, trailing.elements), ids_from(11, 30));
  EXPECT_EQ(trailing.force, Vec3(0, 0, 100));
  EXPECT_DOUBLE_EQ(trailing.speed, 40.0);
  EXPECT_DOUBLE_EQ(trailing.start, 12.5);
  EXPECT_DOUBLE_EQ(trailing.start_time, 0.25);
}

TEST(MovingLoads, PathIsAChainOfElementsRunningForward) {
  const Model m = read_scene(moving_load_scene);
  const std::vector<int>& path = m.moving_loads[0].elements;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    EXPECT_EQ(m.elements[path[i]].nodes.back(), m.elements[path[i + 1]].nodes.front()) << i;
  EXPECT_DOUBLE_EQ(m.nodes[m.elements[path.front()].nodes.front()].position.x(), 0.0);
  EXPECT_DOUBLE_EQ(m.nodes[m.elements[path.back()].nodes.back()].position.x(), 100.0);
}

TEST(MovingLoads, AbsentOrEmptyMeansNone) {
  EXPECT_TRUE(read_scene(moving_load_scene, {"moving_loads=[]"}).moving_loads.empty());
}

TEST(MovingLoads, SpeedIsRequiredInOneOfTwoUnits) {
  const std::string message = error_with({"moving_loads[0].speed_kmh="});
  EXPECT_NE(message.find("'moving_loads[0].speed_kmh': no value given"), std::string::npos)
      << message;
  // Removing a key is not possible with --set; replace the entry without any speed.
  const std::string missing =
      error_with({"moving_loads[1]={name: slow, line: span2, force: [0, 0, 1]}"});
  EXPECT_NE(missing.find("'moving_loads[1]': missing required key 'speed' (m/s"), std::string::npos)
      << missing;
  const std::string negative = error_with({"moving_loads[1].speed=-3"});
  EXPECT_NE(negative.find("value -3 is out of range; expected a finite number >= 0"),
            std::string::npos)
      << negative;
}

TEST(MovingLoads, StartMustLieOnThePathAndStartTimeInTheRun) {
  const std::string start = error_with({"moving_loads[1].start=60"});
  EXPECT_NE(start.find("'moving_loads[1].start': value 60 is out of range; expected a finite "
                       "number in [0, 50]"),
            std::string::npos)
      << start;
  const std::string time = error_with({"moving_loads[1].start_time=2"});
  EXPECT_NE(time.find("'moving_loads[1].start_time': value 2 is out of range; expected a finite "
                      "number in [0, 2)"),
            std::string::npos)
      << time;
}

TEST(MovingLoads, NamesAreUnique) {
  const std::string message = error_with({"moving_loads[1].name=leading"});
  EXPECT_NE(message.find("duplicate moving load name 'leading' (first used at "
                         "moving_loads[0].name"),
            std::string::npos)
      << message;
}

TEST(MovingLoads, PathRunsOnCableOrBeamLinesOnceEach) {
  const std::string bar = error_with({"moving_loads[1].line=hanger"});
  EXPECT_NE(bar.find("line 'hanger' is made of bar elements; moving loads run on cable or beam "
                     "lines"),
            std::string::npos)
      << bar;
  const std::string twice = error_with({"moving_loads[0].line=[span1, span2, span1]"});
  EXPECT_NE(twice.find("'moving_loads[0].line[2]': line 'span1' appears twice in the path"),
            std::string::npos)
      << twice;
  const std::string backwards = error_with({"moving_loads[0].line=[span2, span1]"});
  EXPECT_NE(backwards.find("lines 'span2' and 'span1' do not connect: 'span2' ends at node 3 "
                           "but 'span1' starts at node 1"),
            std::string::npos)
      << backwards;
  const std::string empty = error_with({"moving_loads[0].line=[]"});
  EXPECT_NE(empty.find("the path is empty; expected a line name or a list of line names"),
            std::string::npos)
      << empty;
}

TEST(MovingLoads, ExplicitElementSetsAreNotLines) {
  // An explicit element whose set is called like a line is not part of any line.
  const std::string message =
      error_with({"elements=[{id: 100, section: dropper, nodes: [3, 4], set: catenary}]",
                  "moving_loads[1].line=catenary"});
  EXPECT_NE(message.find("no line named 'catenary'; expected the name of a line under 'lines'; "
                         "lines: span1, span2, hanger"),
            std::string::npos)
      << message;
}

}  // namespace

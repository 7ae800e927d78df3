// model::path_point: the point at arc length s along a path of elements on the reference
// geometry (where a pantograph's contact is drawn), whatever the order of each element's
// own nodes, clamped to the path's ends.
#include <gtest/gtest.h>

#include "catena/model/model.hpp"
#include "catena/model/path_stations.hpp"

namespace catena::model {
namespace {

// Nodes at x = 0, 1, 3 and (3, 4, 0); the first element listed from its far end, the
// third from its near end: a path 0 → 1 → 3 → (3, 4) of length 1 + 2 + 4.
Model bent_path() {
  Model m;
  for (const Vec3& x : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(3, 4, 0)}) {
    Node node;
    node.id = static_cast<int>(m.nodes.size()) + 1;
    node.position = x;
    m.nodes.push_back(node);
  }
  for (const auto& [a, b] : {std::pair{1, 0}, std::pair{1, 2}, std::pair{2, 3}}) {
    ElementDesc e;
    e.id = static_cast<int>(m.elements.size()) + 1;
    e.nodes = {a, b};
    m.elements.push_back(e);
  }
  return m;
}

TEST(PathPoint, WalksEachElementFromTheNodeItSharesWithThePreviousOne) {
  const Model m = bent_path();
  const std::vector<int> path{0, 1, 2};
  const PathStations stations = path_stations(m, path);
  ASSERT_DOUBLE_EQ(stations.length(), 7.0);
  EXPECT_TRUE(path_point(m, path, stations, 0.5).isApprox(Vec3(0.5, 0, 0)));
  EXPECT_TRUE(path_point(m, path, stations, 2.0).isApprox(Vec3(2, 0, 0)));
  EXPECT_TRUE(path_point(m, path, stations, 5.0).isApprox(Vec3(3, 2, 0)));
  EXPECT_TRUE(path_point(m, path, stations, 7.0).isApprox(Vec3(3, 4, 0)));
}

TEST(PathPoint, ClampsToTheEnds) {
  const Model m = bent_path();
  const std::vector<int> path{0, 1, 2};
  const PathStations stations = path_stations(m, path);
  EXPECT_TRUE(path_point(m, path, stations, -1.0).isApprox(Vec3(0, 0, 0)));
  EXPECT_TRUE(path_point(m, path, stations, 9.0).isApprox(Vec3(3, 4, 0)));
}

TEST(PathPoint, AOneElementPathRunsFromItsFirstNode) {
  const Model m = bent_path();
  const std::vector<int> path{1};
  const PathStations stations = path_stations(m, path);
  EXPECT_TRUE(path_point(m, path, stations, 0.5).isApprox(Vec3(1.5, 0, 0)));
}

}  // namespace
}  // namespace catena::model

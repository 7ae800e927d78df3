// node_kinds (shared with the assembly layer) and the `catena check` summary.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "catena/model/model_summary.hpp"
#include "catena/model/node_kinds.hpp"
#include "catena/model/scene_reader.hpp"

namespace {

namespace fs = std::filesystem;
using namespace catena::model;

Model mini_catenary() {
  return read_scene((fs::path(CATENA_TEST_DATA) / "good_scenes" / "mini_catenary.yaml").string());
}

int index_of(const Model& m, std::int64_t id) {
  for (std::size_t i = 0; i < m.nodes.size(); ++i)
    if (m.nodes[i].id == id) return static_cast<int>(i);
  ADD_FAILURE() << "no node " << id;
  return -1;
}

bool contains(const std::string& text, const std::string& fragment) {
  return text.find(fragment) != std::string::npos;
}

TEST(NodeKinds, TheKindThatHoldsEveryAttachedElementsUnknowns) {
  const Model m = mini_catenary();
  const std::vector<UnknownKind> kinds = node_kinds(m);
  EXPECT_EQ(kinds[index_of(m, 33)], UnknownKind::ancf_cable);  // messenger: cable only
  EXPECT_EQ(kinds[index_of(m, 32)], UnknownKind::ancf_cable);  // cable + dropper (bar)
  EXPECT_EQ(kinds[index_of(m, 31)], UnknownKind::ancf_beam);   // beam + spring
  EXPECT_EQ(kinds[index_of(m, 38)], UnknownKind::ancf_beam);   // beam interior
  const std::vector<int> dofs = all_node_dofs(m);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) EXPECT_EQ(dofs[i], kind_info(kinds[i]).size);
}

TEST(NodeKinds, NodesTouchedOnlyByBarsSpringsOrMassesArePoints) {
  Model m;
  m.nodes.resize(3);
  m.elements.push_back(ElementDesc{1, {0, 1}, BarProps{}, catena::Vec3::Zero(), ""});
  const std::vector<UnknownKind> kinds = node_kinds(m);
  EXPECT_EQ(kinds[0], UnknownKind::point);
  EXPECT_EQ(kinds[2], UnknownKind::point);  // untouched: every node has a position
  EXPECT_EQ(element_node_dofs(SpringProps{}), 3);
  EXPECT_EQ(element_node_dofs(CableProps{}), 6);
  EXPECT_EQ(element_node_dofs(BeamProps{}), 12);
}

TEST(Summary, CountsDofsSetsAndSuggestsRanks) {
  const Model m = mini_catenary();
  const std::string text = describe(m, 2);
  // 10 cable nodes x 6 + 3 beam nodes x 12 = 96; fixed 3 + 3 + 4 + 11 = 21 (the clamped
  // beam node keeps its slope's length).
  EXPECT_TRUE(contains(text, "Scene 'mini catenary' from ")) << text;
  EXPECT_TRUE(contains(text, "nodes             13")) << text;
  EXPECT_TRUE(contains(text, "13 (cable 8, beam 2, bar 2, spring 1)")) << text;
  EXPECT_TRUE(contains(text, "96 = 3 beam nodes x 12 + 10 cable nodes x 6")) << text;
  EXPECT_TRUE(contains(text, "fixed DOFs        21")) << text;
  EXPECT_TRUE(contains(text, "free DOFs         75")) << text;
  EXPECT_TRUE(contains(text, "elastic supports  1")) << text;
  EXPECT_TRUE(contains(text, "1 (sum (0, 0, 100) N)")) << text;
  EXPECT_TRUE(contains(text, "1 (sum 2.5 kg)")) << text;
  EXPECT_TRUE(contains(text,
                       "messenger       4 elements (cable 4), prestrain 0.00142857 "
                       "(tension at mesh length EA*prestrain = 10000 N)"))
      << text;
  EXPECT_TRUE(contains(text, "droppers        2 elements (bar 2)")) << text;
  EXPECT_TRUE(contains(text, "(no set)        1 element (spring 1)")) << text;
  EXPECT_TRUE(contains(text,
                       "suggested ranks   1 (about 20000 free DOFs per rank); this "
                       "check ran on 2 ranks"))
      << text;
  EXPECT_TRUE(contains(text, "output            mini.h5")) << text;
}

TEST(Summary, SuggestedRanksScaleWithFreeDofs) {
  const Model small = mini_catenary();
  EXPECT_EQ(suggested_rank_count(small), 1);
  // 3 × 10 000 elements of 6-DOF nodes: about 180 000 free DOFs → 9 ranks.
  const Model big = read_scene((fs::path(CATENA_SOURCE_DIR) / "meshes" / "default.yaml").string(),
                               {"lines[0].elements=10000", "lines[3].elements=10000",
                                "lines[1].elements=5000", "lines[2].elements=5000"});
  const double free_dofs = 6.0 * static_cast<double>(big.nodes.size()) - 6.0;  // pins: 3 + 3
  EXPECT_EQ(suggested_rank_count(big), static_cast<int>(std::round(free_dofs / 20000.0)));
  EXPECT_EQ(suggested_rank_count(big), 9);
}

}  // namespace

// Element properties are shared between the elements that have the same values
// (catena/model/shared_props.hpp): the scene reader gives a line's elements one block, and
// explicit elements of one section with the same prestrain one block; an edit reaches its
// own element only; edit_shared keeps a group sharing. Shape finding's group edits:
// tests/regression/test_catenary_shape_finding.cpp.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "catena/model/model.hpp"
#include "catena/model/scene_reader.hpp"

namespace {

using namespace catena;
using namespace catena::model;

const std::string scene = R"(sections:
  cw: {type: cable, EA: 1.8e7, EI: 195, mass_per_length: 1.35}
  stiff: {type: cable, EA: 3.6e7, EI: 195, mass_per_length: 1.35}
nodes:
  - {id: 1, position: [0, 0, 0]}
  - {id: 2, position: [10, 0, 0]}
  - {id: 3, position: [20, 0, 0]}
  - {id: 4, position: [25, 0, 0]}
  - {id: 5, position: [30, 0, 0]}
  - {id: 6, position: [36, 0, 0]}
lines:
  - {name: a, from: 1, to: 2, elements: 10, section: cw, tension: 18000}
  - {name: b, from: 2, to: 3, elements: 10, section: cw, tension: 9000}
elements:
  - {id: 1, section: stiff, nodes: [3, 4], tension: 1000}
  - {id: 2, section: stiff, nodes: [4, 5], tension: 1000}
  - {id: 3, section: stiff, nodes: [5, 6], unstretched_length: 5.9}
supports:
  - {node: 1, fix: pinned}
  - {node: 6, fix: pinned}
)";

const ElementDesc& with_id(const Model& m, std::int64_t id) {
  for (const ElementDesc& e : m.elements)
    if (e.id == id) return e;
  throw std::runtime_error("no element " + std::to_string(id));
}

std::vector<int> elements_of_set(const Model& m, const std::string& set) {
  std::vector<int> out;
  for (std::size_t e = 0; e < m.elements.size(); ++e)
    if (m.elements[e].set == set) out.push_back(static_cast<int>(e));
  return out;
}

double prestrain(const ElementDesc& e) { return std::get<CableProps>(*e.props).prestrain; }

TEST(SharedProps, AnElementDescriptionHoldsAHandleNotTheProperties) {
  // Every rank holds every element: 208 bytes before, the variant inline.
  EXPECT_EQ(sizeof(SharedProps), 2 * sizeof(void*));
  EXPECT_LE(sizeof(ElementDesc), 96u);
}

TEST(SharedProps, ALinesElementsShareOneBlockAndLinesOfOtherTensionsTheirOwn) {
  const Model m = parse_scene(scene, "shared.yaml");
  const std::vector<int> a = elements_of_set(m, "a"), b = elements_of_set(m, "b");
  ASSERT_EQ(a.size(), 10u);
  ASSERT_EQ(b.size(), 10u);
  for (const int e : a) EXPECT_TRUE(m.elements[e].props.same_block(m.elements[a[0]].props));
  for (const int e : b) EXPECT_TRUE(m.elements[e].props.same_block(m.elements[b[0]].props));
  EXPECT_FALSE(m.elements[a[0]].props.same_block(m.elements[b[0]].props));
  EXPECT_DOUBLE_EQ(prestrain(m.elements[a[0]]), 18000.0 / 1.8e7);
  EXPECT_DOUBLE_EQ(prestrain(m.elements[b[0]]), 9000.0 / 1.8e7);
}

TEST(SharedProps, ExplicitElementsShareWhereSectionAndPrestrainAgree) {
  const Model m = parse_scene(scene, "shared.yaml");
  EXPECT_TRUE(with_id(m, 1).props.same_block(with_id(m, 2).props));
  EXPECT_FALSE(with_id(m, 1).props.same_block(with_id(m, 3).props));
  EXPECT_DOUBLE_EQ(prestrain(with_id(m, 1)), 1000.0 / 3.6e7);
  EXPECT_DOUBLE_EQ(prestrain(with_id(m, 3)), 6.0 / 5.9 - 1.0);
  EXPECT_DOUBLE_EQ(std::get<CableProps>(*with_id(m, 3).props).EA, 3.6e7);
}

TEST(SharedProps, AnEditReachesItsOwnElementOnly) {
  Model m = parse_scene(scene, "shared.yaml");
  const std::vector<int> a = elements_of_set(m, "a");
  std::get<CableProps>(m.elements[a[3]].props.edit()).prestrain = 0.5;
  EXPECT_DOUBLE_EQ(prestrain(m.elements[a[3]]), 0.5);
  for (const int e : a) {
    if (e == a[3]) continue;
    EXPECT_DOUBLE_EQ(prestrain(m.elements[e]), 1e-3);
    EXPECT_TRUE(m.elements[e].props.same_block(m.elements[a[0]].props));
  }
  // A block held by one element alone is edited in place.
  const ElementProps* own = &*m.elements[a[3]].props;
  std::get<CableProps>(m.elements[a[3]].props.edit()).prestrain = 0.25;
  EXPECT_EQ(&*m.elements[a[3]].props, own);
}

TEST(SharedProps, EditSharedKeepsEachGroupSharingAndEditsOncePerBlock) {
  Model m = parse_scene(scene, "shared.yaml");
  std::vector<int> group = elements_of_set(m, "a");
  const std::vector<int> b = elements_of_set(m, "b");
  group.insert(group.end(), b.begin(), b.end());
  group.push_back(group.front());  // listed twice: edited once
  int calls = 0;
  edit_shared(m.elements, group, [&](ElementProps& p) {
    ++calls;
    std::get<CableProps>(p).prestrain += 1.0;
  });
  EXPECT_EQ(calls, 2);  // one block per line
  for (const int e : elements_of_set(m, "a")) {
    EXPECT_DOUBLE_EQ(prestrain(m.elements[e]), 1.0 + 1e-3);
    EXPECT_TRUE(m.elements[e].props.same_block(m.elements[group.front()].props));
  }
  for (const int e : b) {
    EXPECT_DOUBLE_EQ(prestrain(m.elements[e]), 1.0 + 5e-4);
    EXPECT_TRUE(m.elements[e].props.same_block(m.elements[b[0]].props));
  }
  // A copy of the model taken before is untouched by the edit of the original.
  const Model before = parse_scene(scene, "shared.yaml");
  Model copy = before;
  std::get<CableProps>(copy.elements[0].props.edit()).prestrain = 7.0;
  EXPECT_DOUBLE_EQ(prestrain(before.elements[0]), 1000.0 / 3.6e7);
}

}  // namespace

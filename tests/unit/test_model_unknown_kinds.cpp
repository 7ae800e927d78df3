// The table of unknown kinds (model/unknown_kinds.hpp): which kind holds which, and the
// facts the numbering, supports, output and checkpoints read from it.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "catena/model/unknown_kinds.hpp"

namespace {

using namespace catena::model;

TEST(UnknownKinds, NodeKindsNestByTheirComponents) {
  EXPECT_EQ(kind_holding_both(UnknownKind::point, UnknownKind::ancf_cable),
            UnknownKind::ancf_cable);
  EXPECT_EQ(kind_holding_both(UnknownKind::ancf_beam, UnknownKind::ancf_cable),
            UnknownKind::ancf_beam);
  EXPECT_EQ(kind_holding_both(UnknownKind::ancf_beam, UnknownKind::point), UnknownKind::ancf_beam);
  EXPECT_EQ(kind_holding_both(UnknownKind::point, UnknownKind::point), UnknownKind::point);
}

TEST(UnknownKinds, MultipliersShareABlockWithNoNode) {
  // Same component names as a point (x, y, z), but not a node's unknowns.
  EXPECT_FALSE(kind_holding_both(UnknownKind::point, UnknownKind::multiplier).has_value());
  EXPECT_FALSE(kind_holding_both(UnknownKind::multiplier, UnknownKind::ancf_beam).has_value());
  EXPECT_FALSE(kind_info(UnknownKind::multiplier).nodal);
  EXPECT_EQ(kind_info(UnknownKind::multiplier).size, kMaxMultipliersPerConstraint);
}

TEST(UnknownKinds, EveryRowIsWellFormed) {
  std::set<std::string> names;
  for (const UnknownKind kind : all_unknown_kinds()) {
    const UnknownKindInfo& info = kind_info(kind);
    SCOPED_TRACE(std::string(info.name));
    EXPECT_TRUE(names.insert(std::string(info.name)).second) << "names are unique";
    ASSERT_GE(info.size, 1);
    ASSERT_LE(info.size, kMaxBlockUnknowns);
    std::set<std::string_view> components;
    for (int k = 0; k < info.size; ++k) {
      EXPECT_FALSE(info.components[k].empty()) << "component " << k << " has a name";
      EXPECT_TRUE(components.insert(info.components[k]).second) << info.components[k];
    }
    for (int k = info.size; k < kMaxBlockUnknowns; ++k) EXPECT_TRUE(info.components[k].empty());
    if (info.nodal) {
      // Every node has a position: supports pin it, output writes it.
      ASSERT_GE(info.position, 0);
      EXPECT_EQ(info.components[info.position], "x");
    }
    // The gradient slots: an ANCF node's r_x (r_y, r_z), a rigid body's axes e1 (e2, e3),
    // which reference values, output and supports treat alike.
    if (info.gradients >= 0) {
      EXPECT_TRUE(info.components[info.gradients] == "rx_x" ||
                  info.components[info.gradients] == "e1_x")
          << info.components[info.gradients];
    }
  }
  EXPECT_EQ(all_unknown_kinds().size(), 6u);
}

TEST(UnknownKinds, ARigidBodyNodeHoldsAPointButNoCableOrBeam) {
  EXPECT_EQ(kind_holding_both(UnknownKind::point, UnknownKind::rigid_body),
            UnknownKind::rigid_body);
  EXPECT_FALSE(kind_holding_both(UnknownKind::ancf_cable, UnknownKind::rigid_body).has_value());
  EXPECT_FALSE(kind_holding_both(UnknownKind::ancf_beam, UnknownKind::rigid_body).has_value());
  EXPECT_EQ(kind_info(UnknownKind::rigid_body).size, 12);
  EXPECT_EQ(kind_info(UnknownKind::rigid_body).gradients, 3);
}

TEST(UnknownKinds, ASliderNodeHoldsAPointButNoCableBeamOrBody) {
  EXPECT_EQ(kind_holding_both(UnknownKind::point, UnknownKind::slider), UnknownKind::slider);
  EXPECT_EQ(kind_holding_both(UnknownKind::slider, UnknownKind::point), UnknownKind::slider);
  EXPECT_FALSE(kind_holding_both(UnknownKind::ancf_cable, UnknownKind::slider).has_value());
  EXPECT_FALSE(kind_holding_both(UnknownKind::rigid_body, UnknownKind::slider).has_value());
  EXPECT_EQ(kind_info(UnknownKind::slider).size, 4);
  EXPECT_EQ(kind_info(UnknownKind::slider).components[3], "s");
  EXPECT_EQ(kind_info(UnknownKind::slider).gradients, -1);
}

TEST(UnknownKinds, TheWidestNodeFillsACheckpointRow) {
  int widest = 0;
  for (const UnknownKind kind : all_unknown_kinds())
    widest = std::max(widest, kind_info(kind).size);
  EXPECT_EQ(widest, kMaxBlockUnknowns);
  EXPECT_EQ(kind_info(UnknownKind::ancf_beam).size, 12);
  EXPECT_EQ(kind_info(UnknownKind::ancf_cable).gradients, 3);
  EXPECT_EQ(kind_info(UnknownKind::point).gradients, -1);
}

}  // namespace

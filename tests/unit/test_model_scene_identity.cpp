// A restart continues only a checkpoint of the same run: the scene identity ignores the
// keys a restart may change and names the first key that differs otherwise.
#include <gtest/gtest.h>

#include "catena/model/scene_identity.hpp"

namespace {

using catena::model::first_identity_difference;
using catena::model::scene_identity;

const char* const scene = R"(# a comment
name: s
analysis: {type: dynamic, duration: 1.0}
integrator:
  type: hht
  dt: 1.0e-3
lines:
  - {from: 1, to: 2, elements: 4}
output: {file: a.h5, interval: 0.01, flush_wall_seconds: 5}
)";

TEST(SceneIdentity, IgnoresCommentsDurationAndOutputWallClockKeys) {
  const std::string other = R"(name: s
analysis: {type: dynamic, duration: 20}   # extended
integrator:
  type: hht
  dt: 1.0e-3
lines:
  - {from: 1, to: 2, elements: 4}
output: {file: b.h5, interval: 0.01, checkpoint_wall_seconds: 60}
)";
  EXPECT_EQ(scene_identity(scene), scene_identity(other));
  EXPECT_EQ(first_identity_difference(scene_identity(scene), scene_identity(other)), "");
}

TEST(SceneIdentity, NamesTheFirstDifferingKeyByPath) {
  std::string other = scene;
  other.replace(other.find("elements: 4"), 11, "elements: 8");
  EXPECT_EQ(first_identity_difference(scene_identity(other), scene_identity(scene)),
            "lines[0].elements: '8' here, '4' in the checkpoint");
}

TEST(SceneIdentity, NamesAKeyPresentOnOneSideOnly) {
  std::string other = scene;
  other.replace(other.find("  dt: 1.0e-3"), 12, "  dt: 1.0e-3\n  alpha: -0.2");
  EXPECT_EQ(first_identity_difference(scene_identity(other), scene_identity(scene)),
            "integrator.alpha: '-0.2' here, nothing in the checkpoint");
  EXPECT_EQ(first_identity_difference(scene_identity(scene), scene_identity(other)),
            "integrator.alpha: nothing here, '-0.2' in the checkpoint");
}

TEST(SceneIdentity, TheOutputIntervalBelongsToTheRun) {
  std::string other = scene;
  other.replace(other.find("interval: 0.01"), 14, "interval: 0.02");
  EXPECT_NE(first_identity_difference(scene_identity(other), scene_identity(scene)), "");
}

}  // namespace

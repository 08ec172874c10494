// A sweep's light-size override on a point-light scene: the size is the sphere's
// diameter, so the derived scene gets radius = size / 2 and reports lightWidth = size; the
// sibling: the unchanged point_room keeps its own radius (0.15, lightWidth 0.3).
#include <gtest/gtest.h>

#include "runtime/scene/scene.h"
#include "support/test_support.h"
#include "sweep/sweep_scene.h"

namespace shadowc::sweep {
namespace {

TEST(SweepPointScene, LightSizeOverrideIsTheSphereDiameter) {
  const auto dir = test::freshTempDir("sweep-point-scene");
  SceneEntry wide{"point_room_wide", "point_room", 0.6};
  const ResolvedScene r = resolveScene(wide, dir);
  EXPECT_FLOAT_EQ(r.lightWidth, 0.6f);
  const rt::Scene s = rt::loadScene(r.nameOrPath);
  EXPECT_EQ(s.light.type, rt::LightType::Point);
  EXPECT_FLOAT_EQ(s.light.radius, 0.3f);
  const ResolvedScene plain = resolveScene(SceneEntry{"point_room", "point_room", std::nullopt}, dir);
  EXPECT_FLOAT_EQ(plain.lightWidth, 0.3f);
  EXPECT_NE(plain.hash, r.hash);
}

}  // namespace
}  // namespace shadowc::sweep

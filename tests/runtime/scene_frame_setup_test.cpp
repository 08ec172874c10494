// setupFrame: the light frustum covers every vertex with frame.glsl's exact mapping, the UBO
// is column-major, and the Vulkan clip matrices agree with the uv convention.
#include <gtest/gtest.h>

#include <glm/gtc/type_ptr.hpp>

#include "runtime/scene/frame_setup.h"

namespace shadowc::rt {
namespace {

// frame.glsl's shadowc_lightSpace, from the UBO alone (frame_ortho.glsl's for a sun, lightShape.x 3).
glm::vec4 lightSpace(const ShadowcFrame& f, const glm::vec3& world) {
  const glm::mat4 view = glm::make_mat4(f.lightView);
  const glm::vec3 p = glm::vec3(view * glm::vec4(world, 1.0f));
  const bool sun = f.lightShape[0] == 3.0f;
  const glm::vec2 uv = 0.5f + 0.5f * glm::vec2(p) / ((sun ? 1.0f : p.z) * f.lightParams[0]);
  const float d = (p.z - f.lightParams[1]) / (f.lightParams[2] - f.lightParams[1]);
  return {uv, d, p.z};
}

TEST(SceneFrameSetup, LightFrustumCoversEveryBuiltinTightly) {
  for (const std::string& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    const Scene s = loadScene(name);
    if (s.light.type == LightType::Point) continue;  // six faces: point_light_test.cpp checks their coverage
    const FrameSetup f = setupFrame(s, 512, 320, 240);
    EXPECT_GT(f.nearPlane, 0.0f);
    float maxEdge = 0, minD = 1, maxD = 0, minZ = 1e30f, maxZ = 0;
    for (const Mesh& m : s.meshes) {
      for (const glm::vec3& p : m.positions) {
        const glm::vec4 l = lightSpace(f.frame, p);
        ASSERT_GE(l.x, 0.0f);
        ASSERT_LE(l.x, 1.0f);
        ASSERT_GE(l.y, 0.0f);
        ASSERT_LE(l.y, 1.0f);
        maxEdge = std::max({maxEdge, std::abs(l.x - 0.5f), std::abs(l.y - 0.5f)});
        minD = std::min(minD, l.z);
        maxD = std::max(maxD, l.z);
        minZ = std::min(minZ, l.w);
        maxZ = std::max(maxZ, l.w);
        // The coverage matrix maps to the same place (ndc = 2 uv - 1) with depth in [0, 1].
        const glm::vec4 clip = f.lightViewProj * glm::vec4(p, 1.0f);
        ASSERT_NEAR(clip.x / clip.w, 2 * l.x - 1, 1e-4f);
        ASSERT_NEAR(clip.y / clip.w, 2 * l.y - 1, 1e-4f);
        ASSERT_GE(clip.z / clip.w, 0.0f);
        ASSERT_LE(clip.z / clip.w, 1.0f);
      }
    }
    EXPECT_GT(maxEdge, 0.5f / 1.03f);  // fitted with a 2% margin, not a loose guess
    EXPECT_GT(minD, 0.0f);             // strictly inside (0, 1): 1.0 means "nothing hit"
    EXPECT_LT(maxD, 1.0f);
    // near/far hug the nearest and farthest vertex (2% margins).
    EXPECT_NEAR(f.nearPlane, 0.98f * minZ, 1e-5f * minZ);
    EXPECT_NEAR(f.farPlane, 1.02f * maxZ, 1e-5f * maxZ);
  }
}

TEST(SceneFrameSetup, UniformsFollowFrameGlsl) {
  Scene s = loadScene("two_planes");
  const FrameSetup f = setupFrame(s, 1024, 640, 480);
  const ShadowcFrame& u = f.frame;
  EXPECT_EQ(0, std::memcmp(u.lightView, glm::value_ptr(f.lightView), sizeof u.lightView));
  // Column-major: element [12..14] is the translation column.
  const glm::vec3 centre = glm::vec3(glm::make_mat4(u.lightView) * glm::vec4(s.light.position, 1));
  EXPECT_NEAR(glm::length(centre), 0.0f, 1e-5f);
  const glm::vec3 ahead =
      glm::vec3(glm::make_mat4(u.lightView) * glm::vec4(s.light.position + 3.0f * s.light.direction, 1));
  EXPECT_NEAR(ahead.x, 0, 1e-5f);
  EXPECT_NEAR(ahead.y, 0, 1e-5f);
  EXPECT_NEAR(ahead.z, 3, 1e-5f);
  // light.up maps to +y of light view.
  const glm::vec3 up = glm::mat3(f.lightView) * s.light.up;
  EXPECT_NEAR(up.y, 1.0f, 1e-5f);
  EXPECT_FLOAT_EQ(u.lightParams[0], f.tanHalfFov);
  EXPECT_FLOAT_EQ(u.lightParams[1], f.nearPlane);
  EXPECT_FLOAT_EQ(u.lightParams[2], f.farPlane);
  EXPECT_FLOAT_EQ(u.lightParams[3], 1.0f);
  // two_planes: the occluder at y = 2 is 4 below the light at y = 6; the floor 6 below.
  EXPECT_NEAR(f.nearPlane, 4 * 0.98f, 1e-4f);
  EXPECT_NEAR(f.farPlane, 6 * 1.02f, 1e-4f);
  EXPECT_NEAR(f.tanHalfFov, 5.0f / 6.0f * 1.02f, 1e-5f);  // floor corner (5, 5) at depth 6
  EXPECT_EQ(u.lightShape[0], 0.0f);
  EXPECT_EQ(u.mapInfo[0], 1024.0f);
  EXPECT_EQ(u.mapInfo[1], 1.0f / 1024.0f);
  EXPECT_EQ(u.screenInfo[0], 640.0f);
  EXPECT_EQ(u.screenInfo[1], 480.0f);
  EXPECT_EQ(u.screenInfo[2], 1.0f / 640.0f);
  EXPECT_EQ(u.screenInfo[3], 1.0f / 480.0f);

  s.light.shape = LightShape::Disk;
  EXPECT_EQ(setupFrame(s, 8, 8, 8).frame.lightShape[0], 1.0f);
  s.light.width = 0;
  EXPECT_EQ(setupFrame(s, 8, 8, 8).frame.lightShape[0], 2.0f);
}

TEST(SceneFrameSetup, CameraIsVulkanClipWithRowZeroAtTheTop) {
  const Scene s = loadScene("two_planes");
  const FrameSetup f = setupFrame(s, 256, 400, 200);
  const glm::vec4 t = f.cameraViewProj * glm::vec4(s.camera.target, 1);
  EXPECT_NEAR(t.x / t.w, 0, 1e-5f);
  EXPECT_NEAR(t.y / t.w, 0, 1e-5f);
  const glm::vec4 above = f.cameraViewProj * glm::vec4(s.camera.target + glm::vec3(0, 0.5f, 0), 1);
  EXPECT_LT(above.y / above.w, 0.0f);  // up in the world = towards row 0
  const glm::vec4 right = f.cameraViewProj * glm::vec4(s.camera.target + glm::vec3(0.5f, 0, 0), 1);
  EXPECT_GT(right.x / right.w, 0.0f);  // camera at +z looking at -z: +x is to the right
  for (const Mesh& m : s.meshes) {
    for (const glm::vec3& p : m.positions) {
      const glm::vec4 c = f.cameraViewProj * glm::vec4(p, 1);
      EXPECT_GT(c.z / c.w, 0.0f);  // inside near..far
      EXPECT_LT(c.z / c.w, 1.0f);
    }
  }
}

TEST(SceneFrameSetup, DepthRangeSpansMilliToTenThousand) {
  const FrameSetup f = setupFrame(loadScene("depth_range"), 1024, 64, 64);
  EXPECT_NEAR(f.nearPlane, 1e-3f, 0.05e-3f);
  EXPECT_NEAR(f.farPlane, 1e4f, 0.05e4f);
}

TEST(SceneFrameSetup, RejectsZeroSizes) { EXPECT_THROW(setupFrame(loadScene("empty"), 0, 4, 4), SceneError); }

// A sun: an orthographic map (the coverage test above runs on the sun scenes too), the penumbra
// slope 2 tan(angle / 2) in lightParams.w, and the light-view z axis along the sun's direction.
TEST(SceneFrameSetup, SunIsOrthographicWithThePenumbraSlope) {
  const Scene s = loadScene("sun_outdoor");
  ASSERT_EQ(s.light.type, LightType::Sun);
  const FrameSetup f = setupFrame(s, 1024, 320, 240);
  EXPECT_TRUE(f.orthographic);
  EXPECT_EQ(f.frame.lightShape[0], 3.0f);
  EXPECT_FLOAT_EQ(f.frame.lightParams[0], f.halfExtent);
  EXPECT_NEAR(f.frame.lightParams[3], 2 * std::tan(0.5 * 0.53 * M_PI / 180), 1e-7);
  const glm::mat4 view = glm::make_mat4(f.frame.lightView);
  const glm::vec3 zAxis(view[0][2], view[1][2], view[2][2]);  // row 2: world direction of view +z
  EXPECT_NEAR(glm::dot(zAxis, glm::normalize(glm::vec3(0.5f, -0.8f, -0.3f))), 1.0f, 1e-6f);
  // Parallel projection: two points along the sun's direction share a uv, unlike a spot's.
  const glm::vec3 a(1, 0, 2), b = a - 3.0f * zAxis;
  const glm::vec4 la = lightSpace(f.frame, a), lb = lightSpace(f.frame, b);
  EXPECT_NEAR(la.x, lb.x, 1e-5f);
  EXPECT_NEAR(la.y, lb.y, 1e-5f);
  EXPECT_NEAR(la.w - lb.w, 3.0f, 1e-4f);
  const FrameSetup spot = setupFrame(loadScene("two_planes"), 1024, 320, 240);
  EXPECT_FALSE(spot.orthographic);
  EXPECT_NE(spot.frame.lightShape[0], 3.0f);
}

}  // namespace
}  // namespace shadowc::rt

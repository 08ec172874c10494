// Rasterizer on a hand-built scene: a ground plane and an off-centre occluder square, both
// parallel to the light, so every light-depth texel has an analytic value. Validation on.
#include <cmath>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "gpu/vulkan_fixture.h"
#include "runtime/raster/rasterizer.h"
#include "runtime/scene/frame_setup.h"

namespace shadowc::test {
namespace {

using RasterTest = VulkanTest;

rt::Mesh quad(const std::string& name, float y, float x0, float x1, float z0, float z1) {
  rt::Mesh m;
  m.name = name;
  m.positions = {{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

rt::Scene scene() {
  rt::Scene s;
  s.name = "raster_test";
  s.light.position = {0, 10, 0};
  s.light.direction = {0, -1, 0};
  s.light.up = {0, 0, 1};
  s.light.width = 0.5f;
  s.camera.eye = {0, 8, 8};
  s.camera.target = {0, 0, 0};
  s.meshes = {quad("ground", 0, -5, 5, -5, 5), quad("occluder", 5, 1, 3, 1, 3)};
  return s;
}

// The texel that frame.glsl's mapping sends a world point to.
std::pair<uint32_t, uint32_t> texelOf(const rt::FrameSetup& f, glm::vec3 world) {
  const glm::vec3 p = glm::vec3(f.lightView * glm::vec4(world, 1.0f));
  const glm::vec2 uv = 0.5f + 0.5f * glm::vec2(p.x, p.y) / (p.z * f.tanHalfFov);
  return {uint32_t(uv.x * f.mapSize), uint32_t(uv.y * f.mapSize)};
}

double depthOf(const rt::FrameSetup& f, double viewZ) { return (viewZ - f.nearPlane) / (f.farPlane - f.nearPlane); }

::testing::AssertionResult near(double actual, double expected, double tol) {
  if (std::fabs(actual - expected) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << actual << " differs from " << expected << " by more than " << tol;
}

struct Rendered {
  rt::FrameSetup setup;
  rt::RasterOutputs out;
};
Rendered render() {
  Rendered r;
  const rt::Scene s = scene();
  r.setup = rt::setupFrame(s, 128, 96, 64);
  r.out = rt::rasterize(VulkanTest::context(), s, r.setup);
  return r;
}

TEST_F(RasterTest, LightDepthMatchesTheAnalyticPlanes) {
  const Rendered r = render();
  const rt::HostImage& d = r.out.lightDepth;
  ASSERT_EQ(d.width, 128u);
  ASSERT_EQ(d.format, ImageFormat::R32F);
  // Light at y = 10 looking down: the ground is at view z = 10, the occluder at z = 5.
  const double ground = depthOf(r.setup, 10.0), occluder = depthOf(r.setup, 5.0);
  auto at = [&](glm::vec3 w) {
    const auto [x, y] = texelOf(r.setup, w);
    return double(d.texel(x, y));
  };
  EXPECT_TRUE(near(at({0, 0, 0}), ground, 1e-5)) << "centre texel";
  EXPECT_TRUE(near(at({2, 5, 2}), occluder, 1e-5)) << "occluder centre";
  // The mirrored positions see the ground: the map is neither flipped in x nor in y.
  EXPECT_TRUE(near(at({-2, 5, 2}), ground, 1e-5)) << "x mirror";
  EXPECT_TRUE(near(at({2, 5, -2}), ground, 1e-5)) << "y mirror";
  // The frustum has a 2% margin around the ground: the corner texel sees nothing -> cleared 1.0.
  EXPECT_EQ(d.texel(0, 0), 1.0f);
}

// The depth check can fail: the centre texel is not at the occluder's depth.
TEST_F(RasterTest, WrongDepthExpectationFails) {
  const Rendered r = render();
  const auto [x, y] = texelOf(r.setup, {0, 0, 0});
  EXPECT_FALSE(near(r.out.lightDepth.texel(x, y), depthOf(r.setup, 5.0), 1e-5));
  EXPECT_FALSE(near(r.out.lightDepth.texel(x, y), depthOf(r.setup, 10.0) + 1e-4, 1e-5));
}

TEST_F(RasterTest, GBufferPositionsLieOnTheGeometryAndReprojectToTheirPixel) {
  const Rendered r = render();
  const rt::HostImage& pos = r.out.gbufferPosition;
  const rt::HostImage& nrm = r.out.gbufferNormal;
  ASSERT_EQ(pos.width, 96u);
  ASSERT_EQ(pos.height, 64u);
  uint32_t geometry = 0, bad = 0;
  double worstReprojection = 0;
  for (uint32_t y = 0; y < pos.height; ++y)
    for (uint32_t x = 0; x < pos.width; ++x) {
      const float w = pos.texel(x, y, 3);
      if (w == 0.0f) {
        bad += nrm.texel(x, y, 0) != 0.0f || nrm.texel(x, y, 1) != 0.0f;
        continue;
      }
      ++geometry;
      const glm::vec3 p(pos.texel(x, y, 0), pos.texel(x, y, 1), pos.texel(x, y, 2));
      const bool onGround = std::fabs(p.y) < 1e-4f && std::fabs(p.x) <= 5.001f && std::fabs(p.z) <= 5.001f;
      const bool onOccluder = std::fabs(p.y - 5) < 1e-4f && p.x >= 0.999f && p.x <= 3.001f && p.z >= 0.999f && p.z <= 3.001f;
      bad += !(w == 1.0f && (onGround || onOccluder));
      bad += std::fabs(nrm.texel(x, y, 1) - 1.0f) > 1e-6f;
      // The stored point projects back to this pixel's centre.
      const glm::vec4 clip = r.setup.cameraViewProj * glm::vec4(p, 1.0f);
      const double px = (clip.x / clip.w * 0.5 + 0.5) * pos.width, py = (clip.y / clip.w * 0.5 + 0.5) * pos.height;
      worstReprojection = std::max({worstReprojection, std::fabs(px - (x + 0.5)), std::fabs(py - (y + 0.5))});
    }
  EXPECT_EQ(bad, 0u);
  EXPECT_GT(geometry, pos.width * pos.height / 4);
  EXPECT_LT(worstReprojection, 1e-2) << "pixels";
  // The camera looks at the origin: the centre pixel sees the ground near it.
  const glm::vec3 c(pos.texel(48, 32, 0), pos.texel(48, 32, 1), pos.texel(48, 32, 2));
  EXPECT_LT(glm::length(c), 0.3f);
}

TEST_F(RasterTest, EmptySceneClearsEverything) {
  rt::Scene s = scene();
  s.meshes.clear();
  const rt::FrameSetup setup = rt::setupFrame(s, 16, 8, 8);
  const rt::RasterOutputs out = rt::rasterize(context(), s, setup);
  for (float v : out.lightDepth.channel()) ASSERT_EQ(v, 1.0f);
  for (float v : out.gbufferPosition.channel(3)) ASSERT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace shadowc::test

// setupLightSamples (runtime/scene/light_sample_setup.h) on large_penumbra, on the CPU: the views
// the rasterizer renders are the ones the lookup reads (templates/frame_light_samples.glsl:
// uv = 0.5 + 0.5 q.xy / (q.z tanHalfFov), q = light view of p minus the view's point on the
// light), every vertex lies inside every view, and the refusals.
#include "runtime/scene/light_sample_setup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>

#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {
namespace {

nlohmann::json specWith(int count, int grid, const std::vector<std::array<double, 2>>& offsets) {
  nlohmann::json o = nlohmann::json::array();
  for (const auto& [x, y] : offsets) o.push_back({x, y});
  return {{"light_samples", {{"count", count}, {"grid", grid}, {"offsets", o}}}};
}

LightSampleConfig fourCorners() {
  return lightSampleConfigFromSpec(specWith(4, 2, {{-0.25, -0.25}, {0.25, -0.25}, {-0.25, 0.25}, {0.25, 0.25}}));
}

TEST(LightSampleSetup, ConfigFromTheManifestSpec) {
  const LightSampleConfig c = fourCorners();
  EXPECT_EQ(c.count, 4);
  EXPECT_EQ(c.grid, 2);
  ASSERT_EQ(c.offsets.size(), 4u);
  EXPECT_EQ(c.offsets[1], glm::dvec2(0.25, -0.25));
  EXPECT_EQ(lightSampleConfigFromSpec(nlohmann::json::object()).count, 0);
  // Malformed: fewer offsets than views, a view off the light, more views than tiles.
  EXPECT_THROW(lightSampleConfigFromSpec(specWith(4, 2, {{0, 0}})), std::invalid_argument);
  EXPECT_THROW(lightSampleConfigFromSpec(specWith(1, 1, {{0.75, 0}})), std::invalid_argument);
  EXPECT_THROW(lightSampleConfigFromSpec(specWith(5, 2, {{0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}})),
               std::invalid_argument);
}

TEST(LightSampleSetup, EveryViewCoversTheSceneWhereTheLookupReadsIt) {
  const Scene s = loadScene("large_penumbra");
  const LightSampleConfig c = fourCorners();
  FrameSetup f = setupFrame(s, 1024, 256, 256);
  const float centreTan = f.tanHalfFov;
  setupLightSamples(s, c, f);
  ASSERT_EQ(f.lightSampleViewProj.size(), 4u);
  // Views off the centre see the scene's edges at wider angles.
  EXPECT_GT(f.tanHalfFov, centreTan);
  EXPECT_EQ(f.frame.lightParams[0], f.tanHalfFov);
  const double width = s.light.width;
  int checked = 0;
  for (const Mesh& m : s.meshes)
    for (const glm::vec3& p : m.positions)
      for (int i = 0; i < 4; ++i) {
        // The rasterizer's clip position of the vertex in view i.
        const glm::vec4 clip = f.lightSampleViewProj[size_t(i)] * glm::vec4(p, 1.0f);
        const glm::dvec2 ndc(clip.x / clip.w, clip.y / clip.w);
        EXPECT_LE(std::abs(ndc.x), 1.0) << "vertex outside view " << i;
        EXPECT_LE(std::abs(ndc.y), 1.0) << "vertex outside view " << i;
        // The lookup's uv of the same point (frame_light_samples.glsl).
        const glm::dvec3 q = glm::dvec3(f.lightView * glm::vec4(p, 1.0f)) -
                             glm::dvec3(width * c.offsets[size_t(i)].x, width * c.offsets[size_t(i)].y, 0.0);
        const glm::dvec2 uv = 0.5 + 0.5 * glm::dvec2(q.x, q.y) / (q.z * double(f.tanHalfFov));
        EXPECT_NEAR(uv.x, 0.5 + 0.5 * ndc.x, 1e-5);
        EXPECT_NEAR(uv.y, 0.5 + 0.5 * ndc.y, 1e-5);
        ++checked;
      }
  EXPECT_GT(checked, 0);
}

TEST(LightSampleSetup, RefusesASunAndAMapWithoutTiles) {
  FrameSetup sun = setupFrame(loadScene("sun_two_planes"), 1024, 64, 64);
  EXPECT_THROW(setupLightSamples(loadScene("sun_two_planes"), fourCorners(), sun), SceneError);
  const Scene s = loadScene("large_penumbra");
  const LightSampleConfig many =
      lightSampleConfigFromSpec(specWith(256, 16, std::vector<std::array<double, 2>>(256, {0.0, 0.0})));
  FrameSetup small = setupFrame(s, 8, 64, 64);
  EXPECT_THROW(setupLightSamples(s, many, small), SceneError);
}

}  // namespace
}  // namespace shadowc::rt

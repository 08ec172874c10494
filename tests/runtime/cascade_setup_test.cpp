// setupCascades (runtime/scene/cascade_setup.h) on sun_outdoor_long, on the CPU: the split schemes,
// the atlas mapping the lookup uses (templates/frame_cascades.glsl: uv = 0.5 + 0.5 (p.xy + o) / H
// must land in the cascade's tile exactly where its raster matrix puts the point), texel snapping
// (a camera moved by a fraction of a texel moves no window off the texel grid, and the window size
// does not change as the camera turns), and the refusals.
#include "runtime/scene/cascade_setup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>

#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {
namespace {

CascadeConfig four(CascadeScheme split = CascadeScheme::Practical) {
  CascadeConfig c;
  c.count = 4;
  c.split = split;
  c.grid = 2;
  return c;
}

FrameSetup cascaded(const Scene& s, const CascadeConfig& c, uint32_t map = 2048) {
  FrameSetup f = setupFrame(s, map, 512, 512);
  setupCascades(s, c, f);
  return f;
}

TEST(CascadeSetup, SplitSchemes) {
  const auto u = cascadeSplitDepths(four(CascadeScheme::Uniform), 1, 101);
  const auto l = cascadeSplitDepths(four(CascadeScheme::Log), 1, 100);
  const auto p = cascadeSplitDepths(four(CascadeScheme::Practical), 1, 100);
  ASSERT_EQ(u.size(), 5u);
  EXPECT_DOUBLE_EQ(u[1], 26.0);
  EXPECT_NEAR(l[2], 10.0, 1e-9);  // the geometric mean of 1 and 100
  // Practical, lambda 0.5: halfway between log (sqrt(10) = 3.16) and uniform (25.75).
  EXPECT_NEAR(p[1], 0.5 * (std::sqrt(10.0) + 25.75), 1e-9);
  EXPECT_EQ(p.front(), 1.0);
  EXPECT_EQ(p.back(), 100.0);
}

// The lookup's atlas uv of a world point in cascade i, as frame_cascades.glsl computes it.
glm::vec2 lookupUv(const FrameSetup& f, int i, glm::vec3 p) {
  glm::vec3 v = glm::vec3(f.lightView * glm::vec4(p, 1));
  const float* c = f.frame.cascades[i];
  return glm::vec2(0.5f) + 0.5f * (glm::vec2(v) + glm::vec2(c[0], c[1])) / c[2];
}

// Where cascade i's raster matrix puts the point, in atlas uv (tile (i mod 2, i div 2) of 2x2).
glm::vec2 rasterUv(const FrameSetup& f, int i, glm::vec3 p) {
  const glm::vec4 clip = f.cascadeViewProj[size_t(i)] * glm::vec4(p, 1);
  const glm::vec2 tileUv = glm::vec2(0.5f) + 0.5f * glm::vec2(clip) / clip.w;
  return (glm::vec2(float(i % 2), float(i / 2)) + tileUv) / 2.0f;
}

TEST(CascadeSetup, LookupAndRasterAgreeAndEverySliceIsInsideItsTile) {
  const Scene s = loadScene("sun_outdoor_long");
  const FrameSetup f = cascaded(s, four());
  ASSERT_EQ(f.cascadeCount, 4);
  const glm::mat4 camToWorld = glm::inverse(f.cameraView);
  const double t = std::tan(0.5 * glm::radians(double(s.camera.fovYDegrees)));
  for (int i = 0; i < 4; ++i) {
    const float lo = f.cascadeSplits[size_t(i)], hi = f.cascadeSplits[size_t(i) + 1];
    EXPECT_FLOAT_EQ(f.frame.cascades[i][3], hi);
    for (float depth : {lo, 0.5f * (lo + hi), hi})
      for (float sx : {-1.0f, 0.0f, 1.0f})
        for (float sy : {-1.0f, 1.0f}) {
          const glm::vec3 p =
              glm::vec3(camToWorld * glm::vec4(sx * depth * float(t), sy * depth * float(t), -depth, 1));
          const glm::vec2 a = lookupUv(f, i, p), b = rasterUv(f, i, p);
          EXPECT_NEAR(a.x, b.x, 1e-5f);
          EXPECT_NEAR(a.y, b.y, 1e-5f);
          // Inside the tile (the slice's frustum corners are on its circumscribed sphere).
          EXPECT_GE(a.x, float(i % 2) / 2.0f);
          EXPECT_LE(a.x, float(i % 2 + 1) / 2.0f);
          EXPECT_GE(a.y, float(i / 2) / 2.0f);
          EXPECT_LE(a.y, float(i / 2 + 1) / 2.0f);
        }
  }
  // Sibling: the same point through cascade 0's frame is not where cascade 3 rasterizes it.
  const glm::vec3 far = glm::vec3(camToWorld * glm::vec4(0, 0, -0.5f * (f.cascadeSplits[3] + f.cascadeSplits[4]), 1));
  EXPECT_GT(glm::length(lookupUv(f, 0, far) - rasterUv(f, 3, far)), 0.1f);
}

// The window centre c of cascade i, from the frame: o = h (2t + 1) - H - c with h = H T / mapSize.
glm::dvec2 windowCentre(const FrameSetup& f, int i) {
  const double H = f.frame.cascades[i][2], h = H / 2.0;  // 2x2 atlas: T = mapSize / 2
  const glm::dvec2 t(i % 2, i / 2);
  return h * (2.0 * t + 1.0) - H - glm::dvec2(f.frame.cascades[i][0], f.frame.cascades[i][1]);
}

TEST(CascadeSetup, WindowsStayOnTheTexelGridAndKeepTheirSize) {
  Scene s = loadScene("sun_outdoor_long");
  const FrameSetup a = cascaded(s, four());
  s.camera.eye += glm::vec3(0.013f, 0, -0.029f);  // moved by a fraction of a texel of every cascade
  s.camera.target += glm::vec3(0.013f, 0, -0.029f);
  const FrameSetup b = cascaded(s, four());
  Scene turned = loadScene("sun_outdoor_long");
  turned.camera.target.x += 7.0f;  // the camera turns ~8 degrees about its eye
  const FrameSetup c = cascaded(turned, four());
  for (int i = 0; i < 4; ++i) {
    for (const FrameSetup* f : {&a, &b, &c}) {
      const double texel = 2.0 * f->frame.cascades[i][2] / 2048.0;  // 2h / T
      const glm::dvec2 q = windowCentre(*f, i) / texel;
      // float storage of o and H: a few 1e-3 texel of slack at 100 m windows.
      EXPECT_NEAR(q.x, std::round(q.x), 2e-2) << "cascade " << i;
      EXPECT_NEAR(q.y, std::round(q.y), 2e-2) << "cascade " << i;
    }
    // Turning about the eye keeps every slice's shape, so the window's size.
    EXPECT_NEAR(a.frame.cascades[i][2], c.frame.cascades[i][2], 1e-5f * a.frame.cascades[i][2]) << "cascade " << i;
  }
  // Sibling: the unsnapped centre of cascade 0's slice is not on the grid (else the check above
  // would hold for any fit).
  const glm::mat4 camToWorld = glm::inverse(a.cameraView);
  const glm::vec3 mid = glm::vec3(camToWorld * glm::vec4(0, 0, -0.5f * (a.cascadeSplits[0] + a.cascadeSplits[1]), 1));
  const glm::dvec2 raw =
      glm::dvec2(glm::vec2(a.lightView * glm::vec4(mid, 1))) / (2.0 * a.frame.cascades[0][2] / 2048.0);
  EXPECT_GT(std::abs(raw.x - std::round(raw.x)) + std::abs(raw.y - std::round(raw.y)), 0.05);
}

TEST(CascadeSetup, ConfigFromManifestAndRefusals) {
  nlohmann::json spec = {{"cascades", {{"count", 3}, {"split", "log"}, {"lambda", 0.5}, {"blend", 0.2}, {"grid", 2}}}};
  const CascadeConfig c = cascadeConfigFromSpec(spec);
  EXPECT_EQ(c.count, 3);
  EXPECT_EQ(c.split, CascadeScheme::Log);
  EXPECT_EQ(cascadeConfigFromSpec(nlohmann::json::object()).count, 0);
  spec["cascades"]["split"] = "cubic";
  EXPECT_THROW(cascadeConfigFromSpec(spec), std::invalid_argument);
  // A spot scene, and a map side the 3x3 atlas does not divide.
  EXPECT_THROW(cascaded(loadScene("two_planes"), four()), SceneError);
  CascadeConfig nine = four();
  nine.count = 5;
  nine.grid = 3;
  EXPECT_THROW(cascaded(loadScene("sun_outdoor_long"), nine, 2048), SceneError);
  EXPECT_NO_THROW(cascaded(loadScene("sun_outdoor_long"), nine, 1536));
}

}  // namespace
}  // namespace shadowc::rt

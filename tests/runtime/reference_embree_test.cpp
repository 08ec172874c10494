// Embree ground truth: analytic visibility of the two-planes case, light shapes, background,
// determinism, and the on-disk cache.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "runtime/reference/cpu_gbuffer.h"
#include "runtime/reference/embree_reference.h"
#include "runtime/scene/frame_setup.h"
#include "support/test_support.h"

namespace shadowc::rt {
namespace {

// two_planes: light L x L at y = 6 (L = 1 in the scene), occluder 2x2 at y = 2, floor at y = 0.
// Seen from floor point (px, 0, pz), the occluder projects onto the light plane (scale 3 about
// p) as [-3 - 2 px, 3 - 2 px] x [-3 - 2 pz, 3 - 2 pz]; the hidden part of the light is its
// overlap with [-L/2, L/2]^2, an axis-aligned rectangle.

// Integral of h^2 / (x^2 + y^2 + h^2)^2 (= cos_r cos_l / r^2 for a floor point and a parallel
// light h above) over [0, X] x [0, Y] of the light plane, relative to the point: pi times the
// form factor of a parallel rectangle with one corner above the point (Howell's catalogue,
// C-11). Odd in X and in Y, so any rectangle is four corner terms.
double cornerIntegral(double X, double Y, double h) {
  const double a = X / h, b = Y / h, sa = std::sqrt(1 + a * a), sb = std::sqrt(1 + b * b);
  return 0.5 * (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb));
}
double rectIntegral(double x0, double x1, double z0, double z1, double h) {
  return cornerIntegral(x1, z1, h) - cornerIntegral(x0, z1, h) - cornerIntegral(x1, z0, h) + cornerIntegral(x0, z0, h);
}

// The exact reference of either measure at floor point (px, 0, pz) for light side L.
double twoPlanesExact(double px, double pz, double L = 1, ReferenceMeasure m = ReferenceMeasure::ShadowingTerm) {
  const double hl = 0.5 * L;
  const double x0 = std::max(-hl, -3 - 2 * px), x1 = std::min(hl, 3 - 2 * px);
  const double z0 = std::max(-hl, -3 - 2 * pz), z1 = std::min(hl, 3 - 2 * pz);
  if (x1 <= x0 || z1 <= z0) return 1.0;
  if (m == ReferenceMeasure::LightFraction) return 1.0 - (x1 - x0) * (z1 - z0) / (L * L);
  return 1.0 -
         rectIntegral(x0 - px, x1 - px, z0 - pz, z1 - pz, 6) / rectIntegral(-hl - px, hl - px, -hl - pz, hl - pz, 6);
}

TEST(ReferenceEmbree, TwoPlanesMatchesTheClosedFormShadowingTerm) {
  for (const double L : {1.0, 4.0}) {
    SCOPED_TRACE(L);
    Scene s = loadScene("two_planes");
    s.light.width = float(L);
    const int n = 32;
    for (const ReferenceMeasure m : {ReferenceMeasure::ShadowingTerm, ReferenceMeasure::LightFraction}) {
      SCOPED_TRACE(referenceMeasureName(m));
      double worst = 0;
      for (double px = 0.0; px <= 2.0 + 0.5 * L; px += 0.0625) {
        const double pz = 0.3 * px;
        const double traced = referenceVisibilityAt(s, {float(px), 0, float(pz)}, {0, 1, 0}, n, uint64_t(px * 1000), m);
        worst = std::max(worst, std::abs(traced - twoPlanesExact(px, pz, L, m)));
      }
      // Stratified sampling: an edge crossing the light touches n strata of about 1/n^2 each
      // (weights vary by less than 2x over the light).
      EXPECT_LT(worst, 1.0 / n);
    }
  }
  // Siblings: the check can fail. The weighting matters under a large light (the penumbra
  // point where the edge halves the light: 0.570 weighted, 0.5 unweighted) ...
  Scene large = loadScene("two_planes");
  large.light.width = 4;
  EXPECT_GT(std::abs(referenceVisibilityAt(large, {1.5f, 0, 0}, {0, 1, 0}, 32, 0, ReferenceMeasure::LightFraction) -
                     twoPlanesExact(1.5, 0, 4)),
            0.06);
  // ... and a light twice as wide gives a visibly different answer.
  Scene wide = loadScene("two_planes");
  wide.light.width = 2;
  EXPECT_GT(std::abs(referenceVisibilityAt(wide, {1.8f, 0, 0}, {0, 1, 0}, 32) - twoPlanesExact(1.8, 0)), 0.1);
}

// A lone box under a light four times its size: a point on a side face has 3/8 of the light in
// front of its tangent plane and nothing between it and that part, so its shadowing term is
// exactly 1. The light fraction counts the 5/8 behind the face (rays that hit the box itself)
// as shadow.
TEST(ReferenceEmbree, LoneBoxFaceSeesPartOfALargeLightAndIsFullyLit) {
  const Scene s = parseScene(R"({
    "camera": { "eye": [4, 3, 4], "target": [0, 0, 0] },
    "light": { "position": [0, 3, 0], "direction": [0, -1, 0], "size": 4 },
    "objects": [ { "type": "box", "size": 1 } ]
  })",
                             "lone_box.json", {});
  for (const int n : {8, 32}) {
    EXPECT_EQ(referenceVisibilityAt(s, {0.5f, 0, 0}, {1, 0, 0}, n), 1.0f) << n;
    EXPECT_EQ(referenceVisibilityAt(s, {0.1f, 0, -0.5f}, {0, 0, -1}, n), 1.0f) << n;
    EXPECT_EQ(referenceVisibilityAt(s, {0.2f, 0.5f, 0.3f}, {0, 1, 0}, n), 1.0f) << n;  // the top face
  }
  // Sibling: the old measure is far from 1 on the same face (3/8 of the samples reach it).
  EXPECT_NEAR(referenceVisibilityAt(s, {0.5f, 0, 0}, {1, 0, 0}, 32, 0, ReferenceMeasure::LightFraction), 0.375,
              1.0 / 32);
  // A face with no light in front of its plane receives none: 0 (what a shadow map says too).
  EXPECT_EQ(referenceVisibilityAt(s, {0.1f, -0.5f, 0.2f}, {0, -1, 0}, 8), 0.0f);
}

TEST(ReferenceEmbree, EdgeThroughTheLightCentreHidesHalfOfRectAndDisk) {
  // Floor point whose occluder edge projects through the light centre: 3 - 2 px = 0 -> px = 1.5.
  // Half of the samples are hidden; the shadowing term weighs the nearer, visible half more
  // (0.519 for the rectangle).
  Scene s = loadScene("two_planes");
  for (LightShape shape : {LightShape::Rect, LightShape::Disk}) {
    s.light.shape = shape;
    EXPECT_NEAR(referenceVisibilityAt(s, {1.5f, 0, 0}, {0, 1, 0}, 32, 0, ReferenceMeasure::LightFraction), 0.5,
                1.0 / 32);
    const float term = referenceVisibilityAt(s, {1.5f, 0, 0}, {0, 1, 0}, 32);
    EXPECT_GT(term, 0.5f);
    EXPECT_LT(term, 0.5f + 1.0f / 32);
  }
  // Under the centre: all hidden; far away: all visible.
  EXPECT_EQ(referenceVisibilityAt(s, {0, 0, 0}, {0, 1, 0}, 8), 0.0f);
  EXPECT_EQ(referenceVisibilityAt(s, {4.5f, 0, 4.5f}, {0, 1, 0}, 8), 1.0f);
  // A point light (width 0) is one ray: 0 or 1.
  s.light.width = 0;
  EXPECT_EQ(referenceVisibilityAt(s, {1.4f, 0, 0}, {0, 1, 0}, 8), 0.0f);  // shadow edge at x = 1.5
  EXPECT_EQ(referenceVisibilityAt(s, {1.6f, 0, 0}, {0, 1, 0}, 8), 1.0f);
}

TEST(ReferenceEmbree, ResolvesAnOccluderAMillimetreFromTheLightSeenFromTenThousand) {
  // depth_range: the 4e-4 plane 1e-3 below the light shadows x in [1000, 5000] on the floor at
  // y = -1e4 (umbra about [1500, 4500]). Traced from the receiver in fp32 it would be lost.
  const Scene s = loadScene("depth_range");
  EXPECT_EQ(referenceVisibilityAt(s, {3000, -10000, 0}, {0, 1, 0}, 8), 0.0f);
  EXPECT_EQ(referenceVisibilityAt(s, {6000, -10000, 0}, {0, 1, 0}, 8), 1.0f);
  const float penumbra = referenceVisibilityAt(s, {5000, -10000, 0}, {0, 1, 0}, 16);
  EXPECT_GT(penumbra, 0.2f);
  EXPECT_LT(penumbra, 0.8f);
}

TEST(ReferenceEmbree, LightSamplesCoverTheShape) {
  const Scene s = loadScene("empty");  // disk light of diameter 1 at (0, 6, 0)
  AreaLight l = s.light;
  float maxR = 0;
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 p = lightSamplePoint(l, i, j, 8, 0.999f, 0.999f);
      EXPECT_NEAR(p.y, 6.0f, 1e-6f);
      maxR = std::max(maxR, glm::length(glm::vec2(p.x, p.z)));
    }
  }
  EXPECT_LE(maxR, 0.5f + 1e-6f);
  EXPECT_GT(maxR, 0.45f);
  l.shape = LightShape::Rect;
  const glm::vec3 corner = lightSamplePoint(l, 0, 0, 4, 0, 0);
  EXPECT_NEAR(std::abs(corner.x), 0.5f, 1e-6f);
  EXPECT_NEAR(std::abs(corner.z), 0.5f, 1e-6f);
}

class ReferenceImage : public ::testing::Test {
 protected:
  void SetUp() override {
    scene = loadScene("two_planes");
    frame = setupFrame(scene, 256, 64, 64);
    gbuffer = rayCastGBuffer(scene, frame);
  }
  Scene scene;
  FrameSetup frame;
  CpuGBuffer gbuffer;
};

TEST_F(ReferenceImage, CpuGBufferSeesTheFloorAndBackground) {
  size_t geometry = 0;
  for (size_t i = 0; i < 64 * 64; ++i) geometry += gbuffer.positions[i * 4 + 3] != 0 ? 1 : 0;
  EXPECT_GT(geometry, 64u * 64 / 4);
  EXPECT_LT(geometry, 64u * 64);  // the sky above the floor's far edge
  // The centre pixel looks at the target (0, 0, 0) on the floor... or the occluder above it.
  const float* centre = &gbuffer.positions[(32 * 64 + 32) * 4];
  EXPECT_EQ(centre[3], 1.0f);
  // Row 0 is the top of the image: background (sky); the bottom row sees the floor.
  EXPECT_EQ(gbuffer.positions[(0 * 64 + 32) * 4 + 3], 0.0f);
  EXPECT_EQ(gbuffer.positions[(63 * 64 + 32) * 4 + 3], 1.0f);
}

TEST_F(ReferenceImage, TracesDeterministicallyWithProgressAndBackgroundLit) {
  std::vector<ReferenceProgress> reports;
  const ReferenceResult a = traceReference(
      scene, gbuffer.positions, gbuffer.normals, 64, 64, 4, {},
      [&](const ReferenceProgress& p) { reports.push_back(p); }, false);
  const ReferenceResult b = traceReference(scene, gbuffer.positions, gbuffer.normals, 64, 64, 4, {}, {}, false);
  ASSERT_EQ(a.visibility.size(), 64u * 64);
  EXPECT_EQ(a.visibility, b.visibility);
  EXPECT_FALSE(a.fromCache);
  ASSERT_FALSE(reports.empty());
  EXPECT_EQ(reports.back().pixelsDone, reports.back().pixelsTotal);
  EXPECT_EQ(reports.back().rays, a.rays);
  size_t geometry = 0, dark = 0, penumbra = 0;
  for (size_t i = 0; i < a.visibility.size(); ++i) {
    const float v = a.visibility[i];
    ASSERT_GE(v, 0.0f);
    ASSERT_LE(v, 1.0f);
    if (gbuffer.positions[i * 4 + 3] == 0) {
      EXPECT_EQ(v, 1.0f);
      continue;
    }
    ++geometry;
    dark += v == 0 ? 1 : 0;
    penumbra += (v > 0 && v < 1) ? 1 : 0;
  }
  EXPECT_EQ(a.rays, geometry * 16);
  EXPECT_GT(a.raysPerSecond, 0.0);
  EXPECT_GT(dark, 10u);  // the umbra under the occluder
  EXPECT_GT(penumbra, 10u);
}

TEST_F(ReferenceImage, CacheIsReusedAndKeyedByContent) {
  const auto dir = test::freshTempDir("reference_cache");
  const ReferenceResult first = traceReference(scene, gbuffer.positions, gbuffer.normals, 64, 64, 4, dir);
  ASSERT_FALSE(first.fromCache);
  ASSERT_TRUE(std::filesystem::exists(first.cacheFile)) << first.cacheWarning;
  const ReferenceResult again = traceReference(scene, gbuffer.positions, gbuffer.normals, 64, 64, 4, dir);
  EXPECT_TRUE(again.fromCache);
  EXPECT_EQ(again.visibility, first.visibility);
  // One G-buffer bit different, other samples or another scene: a different entry.
  std::vector<float> moved = gbuffer.positions;
  moved[(40 * 64 + 10) * 4 + 0] += 1e-3f;
  EXPECT_FALSE(traceReference(scene, moved, gbuffer.normals, 64, 64, 4, dir).fromCache);
  EXPECT_FALSE(traceReference(scene, gbuffer.positions, gbuffer.normals, 64, 64, 2, dir).fromCache);
  Scene other = scene;
  other.light.width = 1.5f;
  EXPECT_FALSE(traceReference(other, gbuffer.positions, gbuffer.normals, 64, 64, 4, dir).fromCache);
  // The measure is part of the key: the light fraction never reads a shadowing-term entry.
  const ReferenceResult fraction = traceReference(scene, gbuffer.positions, gbuffer.normals, 64, 64, 4, dir, {}, true,
                                                  ReferenceMeasure::LightFraction);
  EXPECT_FALSE(fraction.fromCache);
  EXPECT_NE(fraction.cacheFile, first.cacheFile);
  EXPECT_NE(fraction.visibility, first.visibility);
  // A damaged file is ignored and rewritten, never trusted.
  {
    std::fstream f(first.cacheFile, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(100);
    f.put('\x7f');
  }
  const ReferenceResult repaired = traceReference(scene, gbuffer.positions, gbuffer.normals, 64, 64, 4, dir);
  EXPECT_FALSE(repaired.fromCache);
  EXPECT_EQ(repaired.visibility, first.visibility);
  EXPECT_TRUE(traceReference(scene, gbuffer.positions, gbuffer.normals, 64, 64, 4, dir).fromCache);
}

TEST(ReferenceEmbree, EmptyIsLitAndFullyOccludedIsDark) {
  for (const char* name : {"empty", "fully_occluded"}) {
    const Scene s = loadScene(name);
    const FrameSetup f = setupFrame(s, 64, 32, 32);
    const CpuGBuffer g = rayCastGBuffer(s, f);
    const ReferenceResult r = traceReference(s, g.positions, g.normals, 32, 32, 4, {}, {}, false);
    size_t geometry = 0;
    for (size_t i = 0; i < r.visibility.size(); ++i) {
      if (g.positions[i * 4 + 3] == 0) continue;
      ++geometry;
      EXPECT_EQ(r.visibility[i], std::string(name) == "empty" ? 1.0f : 0.0f) << name << " pixel " << i;
    }
    EXPECT_GT(geometry, 100u) << name;
  }
}

TEST(ReferenceEmbree, RejectsMismatchedSizes) {
  const Scene s = loadScene("empty");
  EXPECT_THROW(traceReference(s, std::vector<float>(16), std::vector<float>(16), 4, 4, 2, {}, {}, false),
               std::invalid_argument);
  EXPECT_THROW(traceReference(s, std::vector<float>(64), std::vector<float>(64), 4, 4, 0, {}, {}, false),
               std::invalid_argument);
}

}  // namespace
}  // namespace shadowc::rt

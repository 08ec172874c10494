// A point light's cube shadow map on the point_room scene: PCF, PCSS and a VSM
// sample compiled with `light point(radius: scene)` against the Embree reference (the sphere's
// cone of directions, docs/scenes.md), within bounds measured first (docs/accuracy.md "Point
// lights"), and the seams: the error on pixels whose light direction lies near a cube-face
// boundary is not markedly higher than elsewhere. Siblings: a radius 4x too large folded into the
// same filters misses the bound; the faces rendered without a guard band (tan(half fov) = 1, so
// kernels near a seam read another face's cell) make the seam error markedly higher; a spot filter
// on the point scene is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"
#include "runtime/scene/cube_setup.h"

namespace shadowc::test {
namespace {

// Full size on purpose: the bounds are docs/accuracy.md's "Point lights" rows, measured at these sizes.
constexpr uint32_t kScreen = 256, kMap = 1536;  // 512-texel faces, 341 of them across 90 degrees
constexpr int kSamples = 16;

struct PointCase {
  const char* sample;
  double bound;  // RMSE over geometry pixels (measured, docs/accuracy.md "Point lights")
};
// Measured (lavapipe, map 1536, screen 256, 16^2 reference samples): see docs/accuracy.md.
// Measured 0.0982 / 0.0543 / 0.0805. pcf_poisson16 and the VSM sample: most of it is their bias,
// not the cube map: slope(0.05) of a 4.4 m depth range lets light through the 0.2-0.4 m casters'
// back faces (docs/accuracy.md). pcss_poisson's receiver-plane bias (the gradient taken in the
// receiver's cube face, bias.glsl) has no such slab: 0.0946 with the slope bias, and 0.226 while
// the gradient was taken in the spot's single frame (the face's axes are not the light view's).
constexpr PointCase kCases[] = {
    {"pcf_poisson16", 0.11},
    {"pcss_poisson", 0.07},
    {"vsm_blur_mips_bleeding", 0.095},
};

// The frame with light view x mirrored: every receiver picks the wrong face's cell on the x axis
// (+x reads -x), the lookup's face selection deliberately broken.
rt::PreparedScene withMirroredFaces(const rt::PreparedScene& sc) {
  rt::PreparedScene wrong = sc;
  for (int c = 0; c < 4; ++c) wrong.setup.frame.lightView[c * 4] = -wrong.setup.frame.lightView[c * 4];
  return wrong;
}

const CompiledFilter* pointFilter(const std::string& sample, const std::string& light) {
  return compileFilterCached(sample + "/" + light, withLight(sampleSource(sample), light));
}

// Penumbra pixels (reference strictly between 0.05 and 0.95) split by the direction from the
// light: near a face boundary when the second-largest |component| is within 2% of the largest
// (in the 90-degree face, |x_f / z_f| or |y_f / z_f| > 0.98: within ~3.4 texels of a 341-texel
// face's edge, where a kernel's taps cross the seam). Wider bands dilute it: at 0.85 the
// no-guard-band sibling is 0.068 vs 0.081 elsewhere, at 0.98 0.133 vs 0.078 (PCSS, screen 256).
struct SeamSplit {
  double seamRmse = 0, restRmse = 0;
  size_t seamCount = 0, restCount = 0;
};
SeamSplit seamSplit(const rt::PreparedScene& sc, const std::vector<float>& vis, float near = 0.98f,
                    bool penumbraOnly = true) {
  const std::vector<float> pos = sc.raster.gbufferPosition.floats();
  double seam = 0, rest = 0;
  SeamSplit s;
  for (size_t i = 0; i < vis.size(); ++i) {
    if (!sc.mask[i] || (penumbraOnly && !(sc.reference[i] > 0.05f && sc.reference[i] < 0.95f))) continue;
    const glm::vec3 d = glm::abs(glm::vec3(pos[i * 4], pos[i * 4 + 1], pos[i * 4 + 2]) - sc.scene.light.position);
    const float major = std::max({d.x, d.y, d.z});
    const float second = d.x + d.y + d.z - major - std::min({d.x, d.y, d.z});
    const double e = (double(vis[i]) - sc.reference[i]) * (double(vis[i]) - sc.reference[i]);
    if (second > near * major) {
      seam += e;
      ++s.seamCount;
    } else {
      rest += e;
      ++s.restCount;
    }
  }
  s.seamRmse = std::sqrt(seam / double(std::max<size_t>(1, s.seamCount)));
  s.restRmse = std::sqrt(rest / double(std::max<size_t>(1, s.restCount)));
  return s;
}

// "Not markedly higher": within 1.25x of the rest plus 0.01 (the two sets hold different shadows).
bool seamNotMarkedlyWorse(const SeamSplit& s) { return s.seamRmse <= 1.25 * s.restRmse + 0.01; }

using PointRoomTest = VulkanTest;

TEST_F(PointRoomTest, PcfPcssAndVsmMatchTheReference) {
  const rt::PreparedScene& sc = sceneCase(context(), "point_room", kMap, kScreen, kSamples);
  ASSERT_TRUE(sc.setup.cube);
  const rt::PreparedScene mirrored = withMirroredFaces(sc);
  for (const PointCase& c : kCases) {
    const CompiledFilter* good = pointFilter(c.sample, "light point(radius: scene)");
    // Sibling: a sphere of 4x the scene's radius (0.6) folded in: penumbrae 4x too wide.
    const CompiledFilter* wide = pointFilter(c.sample, "light point(radius: 0.6)");
    ASSERT_NE(good, nullptr);
    ASSERT_NE(wide, nullptr);
    const double e = rt::runOnScene(context(), good->passes, sc).metrics.rmse;
    const double eWide = rt::runOnScene(context(), wide->passes, sc).metrics.rmse;
    const double eMirror = rt::runOnScene(context(), good->passes, mirrored).metrics.rmse;
    fmt::print("point_room {}: rmse {:.4f} (bound {}); radius 0.6 folded in: {:.4f}; wrong faces: {:.4f}\n", c.sample,
               e, c.bound, eWide, eMirror);
    EXPECT_LT(e, c.bound) << c.sample;
    // Siblings: wrong face selection misses for every filter; a 4x radius only moves the
    // penumbra-sized kernel (PCSS), the fixed-kernel samples do not read the radius.
    EXPECT_GT(eMirror, 2 * c.bound) << c.sample;
    if (std::string(c.sample) == "pcss_poisson") {
      EXPECT_GT(eWide, c.bound) << c.sample;
    }
  }
}

TEST_F(PointRoomTest, NoSeamInTheErrorImage) {
  // 512^2 pixels (8^2 reference samples) so that the thin band near the seams holds enough penumbra.
  constexpr uint32_t kSeamScreen = 512;
  constexpr int kSeamSamples = 8;
  const rt::PreparedScene& sc = sceneCase(context(), "point_room", kMap, kSeamScreen, kSeamSamples);
  // Sibling scene: the same faces with no guard band (tan(half fov) = 1).
  rt::SceneSettings bare;
  bare.scene = "point_room";
  bare.screen = kSeamScreen;
  bare.map = kMap;
  bare.referenceSamples = kSeamSamples;
  bare.referenceCache = referenceCacheDir();
  bare.cubeTanHalf = 1.0f;
  const auto noBand = rt::prepareScene(context(), bare);
  for (const char* sample : {"pcss_poisson", "vsm_blur_mips_bleeding"}) {
    const CompiledFilter* f = pointFilter(sample, "light point(radius: scene)");
    ASSERT_NE(f, nullptr);
    const SeamSplit s = seamSplit(sc, rt::runOnScene(context(), f->passes, sc).outputs.visibility);
    const SeamSplit b = seamSplit(*noBand, rt::runOnScene(context(), f->passes, *noBand).outputs.visibility);
    fmt::print(
        "point_room {}: penumbra rmse near seams {:.4f} ({} px) vs elsewhere {:.4f} ({} px); "
        "without a guard band {:.4f} vs {:.4f}\n",
        sample, s.seamRmse, s.seamCount, s.restRmse, s.restCount, b.seamRmse, b.restRmse);
    ASSERT_GT(s.seamCount, 60u) << "too few penumbra pixels near a seam: the scene does not test seams";
    ASSERT_GT(s.restCount, 200u);
    EXPECT_TRUE(seamNotMarkedlyWorse(s)) << sample;
    // Sibling: PCSS's penumbra-wide kernels cross the seam; without a guard band they read another
    // face's cell. (The VSM sample's fixed kernel and radius-3 blur reach ~4 texels: too little to
    // show a seam either way at this size, so it has no sibling here.)
    if (std::string(sample) == "pcss_poisson") {
      EXPECT_FALSE(seamNotMarkedlyWorse(b)) << sample << ": the sibling without a guard band shows no seam";
    }
  }
}

TEST_F(PointRoomTest, SpotFilterOnPointSceneIsRefused) {
  // The refusal reads the scene's light, not its pixels: a small scene (the sibling runs on it too).
  const rt::PreparedScene& sc = sceneCase(context(), "point_room", 384, 32, 1);
  const CompiledFilter* spot = compileFilterCached("pcss_poisson", sampleSource("pcss_poisson"));
  ASSERT_NE(spot, nullptr);
  try {
    rt::runOnScene(context(), spot->passes, sc);
    ADD_FAILURE() << "a spot filter ran on a point-light scene";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("light point(radius: scene)"), std::string::npos) << e.what();
  }
  // Sibling: the point filter runs on it.
  const CompiledFilter* point = pointFilter("pcss_poisson", "light point(radius: scene)");
  ASSERT_NE(point, nullptr);
  EXPECT_NO_THROW(rt::runOnScene(context(), point->passes, sc));
}

}  // namespace
}  // namespace shadowc::test

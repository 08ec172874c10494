// Every sample filter family that can filter a cube map compiles for a point light: each
// samples/filters/*.shadow with its `light` line replaced by `light point(radius: 0.15)` either compiles (every SPIR-V
// module passes spirv-val, the shade GLSL takes frame_cube.glsl's atlas light space, the manifest says "point") or is
// refused with E0450 — and which of the two is decided here from the spot sample's spec (a SAT, the min-max pyramid or
// a subdivided kernel), independently of light_rules.cpp. Siblings: the spot sample has none of the cube code, and a
// refusal must name its technique.
#include <gtest/gtest.h>

#include "backend/spirv_backend.h"
#include "emit/emit_support.h"
#include "spec/filter_spec.h"

namespace shadowc {
namespace {

constexpr const char* kCubeMarker = "shadowc_cubeCell";  // only frame_cube.glsl defines it

bool cannotSpanFaces(const FilterSpec& s) {
  return (s.representation == Representation::Moments && s.storage.sat != SatKind::None) || s.earlyOutMinMax ||
         s.kernel.subdivision == Subdivision::Quadtree || s.kernel.subdivision == Subdivision::Uniform;
}

class PointSample : public ::testing::TestWithParam<std::string> {};

TEST_P(PointSample, CompilesWithCubeAtlasOrIsRefusedForItsSeams) {
  const driver::Result spot = test::compileSample(GetParam());
  ASSERT_TRUE(spot.ok) << spot.log;
  const std::string text = test::readFile(test::samplePath(GetParam()));
  const driver::Result r =
      driver::compileSource(test::withLight(text, "light point(radius: 0.15)"), GetParam() + "_point.shadow");
  if (spot.artifact->spec.lightSamples > 0) {  // views stand on an area light's surface
    EXPECT_FALSE(r.ok) << GetParam() << " should be refused for a point light";
    EXPECT_NE(r.log.find("[E0471]"), std::string::npos) << r.log;
    return;
  }
  if (cannotSpanFaces(spot.artifact->spec)) {
    ASSERT_FALSE(r.ok) << GetParam() << " should be refused for a cube map";
    EXPECT_NE(r.log.find("[E0450]"), std::string::npos) << r.log;
    EXPECT_NE(r.log.find("cannot span them"), std::string::npos) << r.log;
    return;
  }
  ASSERT_TRUE(r.ok) << GetParam() << ":\n" << r.log;
  EXPECT_EQ(r.artifact->spec.light.type, LightType::Point);
  EXPECT_GE(test::expectEverySpirvValid(*r.artifact, GetParam()), 1);
  const std::string* shade = r.artifact->file("shade.glsl");
  ASSERT_NE(shade, nullptr);
  EXPECT_NE(shade->find(kCubeMarker), std::string::npos) << "the point light's shade pass lacks frame_cube.glsl";
  EXPECT_NE(r.artifact->file("manifest.json")->find(R"("type": "point")"), std::string::npos);
  // The radius is folded as the sphere's diameter 2R = 0.3 (a literal), not read from the frame.
  EXPECT_NE(shade->find("0.3"), std::string::npos);
}

TEST_P(PointSample, SpotSampleHasNoCubeCode) {
  const driver::Result r = test::compileSample(GetParam());
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_EQ(r.artifact->file("shade.glsl")->find(kCubeMarker), std::string::npos);
  EXPECT_EQ(r.artifact->file("manifest.json")->find(R"("type": "point")"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Samples, PointSample, ::testing::ValuesIn(test::sampleFilterNames()),
                         [](const auto& info) { return info.param; });

// The families the GPU test runs must be among the accepted ones (else the GPU test runs nothing).
TEST(PointLight, PcfPcssAndVsmFamiliesAreAccepted) {
  for (const char* name : {"pcf_poisson16", "pcf_grid5x5", "pcss_poisson", "pcss_grid_search", "vsm_chebyshev",
                           "vsm_blur_mips_bleeding", "evsm4", "msm_blur", "layered_vsm_uniform"}) {
    const std::string text = test::readFile(test::samplePath(name));
    const driver::Result r = driver::compileSource(test::withLight(text, "light point(radius: scene)"), "p.shadow");
    EXPECT_TRUE(r.ok) << name << ":\n" << r.log;
  }
}

// Radius 0 is a hard cube shadow: a blocker estimate has nothing to size (E0451); a fixed kernel
// compiles. The scene-supplied radius reads lightParams.w.
TEST(PointLight, ZeroRadiusRefusesABlockerEstimateAndSceneRadiusReadsTheFrame) {
  const driver::Result pcss = driver::compileSource(
      "filter f {\n    light point(radius: 0)\n    depth\n    blocker search(16)\n}\n", "f.shadow");
  EXPECT_FALSE(pcss.ok);
  EXPECT_NE(pcss.log.find("[E0451]"), std::string::npos) << pcss.log;
  const driver::Result pcf =
      driver::compileSource("filter f {\n    light point(radius: 0)\n    depth\n    kernel fixed(3)\n}\n", "f.shadow");
  EXPECT_TRUE(pcf.ok) << pcf.log;
  const driver::Result scene = driver::compileSource(
      "filter f {\n    light point(radius: scene)\n    depth\n    blocker search(16)\n}\n", "f.shadow");
  ASSERT_TRUE(scene.ok) << scene.log;
  EXPECT_NE(scene.artifact->file("shade.glsl")->find("lightParams . w"), std::string::npos);
}

}  // namespace
}  // namespace shadowc

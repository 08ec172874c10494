// Every sample filter family compiles for a sun as well as for its spot light: each
// samples/filters/*.shadow with its `light` line replaced by `light sun(angle: 0.53)` goes through
// the driver, every SPIR-V module passes spirv-val, and the shade GLSL takes frame_ortho.glsl's
// orthographic light space with the folded penumbra slope 2 tan(0.265 deg). The sibling checks
// prove the marker can fail: the unchanged samples carry none of it.
#include <gtest/gtest.h>

#include <cmath>

#include "backend/spirv_backend.h"
#include "emit/emit_support.h"
#include "spec/filter_spec.h"

namespace shadowc {
namespace {

// What only frame_ortho.glsl defines (the perspective light space has no such function).
constexpr const char* kOrthoMarker = "shadowc_worldToUV";

class SunSample : public ::testing::TestWithParam<std::string> {};

TEST_P(SunSample, CompilesWithOrthographicLightSpaceAndEverySpvValidates) {
  const std::string text = test::readFile(test::samplePath(GetParam()));
  const driver::Result r =
      driver::compileSource(test::withLight(text, "light sun(angle: 0.53)"), GetParam() + "_sun.shadow");
  // Light samples stand on an area light's surface: a sun has none (docs/dsl.md "light_samples").
  if (test::compileSample(GetParam()).artifact->spec.lightSamples > 0) {
    EXPECT_FALSE(r.ok) << GetParam() << " should be refused for a sun";
    EXPECT_NE(r.log.find("[E0471]"), std::string::npos) << r.log;
    return;
  }
  ASSERT_TRUE(r.ok) << GetParam() << ":\n" << r.log;
  EXPECT_EQ(r.artifact->spec.light.type, LightType::Sun);
  EXPECT_GE(test::expectEverySpirvValid(*r.artifact, GetParam()), 1);
  const std::string* shade = r.artifact->file("shade.glsl");
  ASSERT_NE(shade, nullptr);
  EXPECT_NE(shade->find(kOrthoMarker), std::string::npos) << "the sun's shade pass lacks frame_ortho.glsl";
  EXPECT_NE(r.artifact->file("manifest.json")->find(R"("type": "sun")"), std::string::npos);
}

TEST_P(SunSample, SpotSampleHasNoOrthographicCode) {
  const driver::Result r = test::compileSample(GetParam());
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_EQ(r.artifact->spec.light.type, LightType::Spot);
  EXPECT_EQ(r.artifact->file("shade.glsl")->find(kOrthoMarker), std::string::npos);
  EXPECT_EQ(r.artifact->file("manifest.json")->find(R"("type": "sun")"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Samples, SunSample, ::testing::ValuesIn(test::sampleFilterNames()),
                         [](const auto& info) { return info.param; });

// `light spot` is today's light written out: the same files, byte for byte, as no `light` at all.
TEST(LightTypes, SpotSpelledOutIsByteIdenticalToTheDefault) {
  const std::string base = "filter f {\n    depth\n    blocker search(16)\n}\n";
  const std::string spot = "filter f {\n    light spot\n    depth\n    blocker search(16)\n}\n";
  const std::string spotArea =
      "filter f {\n    light spot(shape: area, size: scene)\n    depth\n    blocker search(16)\n}\n";
  const driver::Result a = driver::compileSource(base, "f.shadow"), b = driver::compileSource(spot, "f.shadow"),
                       c = driver::compileSource(spotArea, "f.shadow");
  ASSERT_TRUE(a.ok && b.ok && c.ok) << a.log << b.log << c.log;
  ASSERT_EQ(a.artifact->files.size(), b.artifact->files.size());
  for (size_t i = 0; i < a.artifact->files.size(); ++i) {
    EXPECT_TRUE(a.artifact->files[i].bytes == b.artifact->files[i].bytes) << a.artifact->files[i].name;
    EXPECT_TRUE(a.artifact->files[i].bytes == c.artifact->files[i].bytes) << a.artifact->files[i].name;
  }
}

// A folded sun angle becomes the penumbra slope 2 tan(angle / 2), not the angle.
TEST(LightTypes, FoldedSunAngleIsThePenumbraSlope) {
  EXPECT_NEAR(sunPenumbraSlope(0.53), 2 * std::tan(0.265 * M_PI / 180), 1e-15);
  EXPECT_NEAR(sunPenumbraSlope(90), 2.0, 1e-12);
  const driver::Result r =
      driver::compileSource("filter f {\n    light sun(angle: 4)\n    depth\n    blocker search(16)\n}\n", "f.shadow");
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_FALSE(r.artifact->spec.light.sizeFromScene);
  EXPECT_DOUBLE_EQ(r.artifact->spec.light.angleDegrees, 4.0);
  const driver::Result fromScene =
      driver::compileSource("filter f {\n    light sun\n    depth\n    blocker search(16)\n}\n", "f.shadow");
  ASSERT_TRUE(fromScene.ok) << fromScene.log;
  EXPECT_TRUE(fromScene.artifact->spec.light.sizeFromScene);
  // The folded slope 0.069849... is a literal of the shade pass; the scene-supplied one reads lightParams.w.
  EXPECT_NE(r.artifact->file("shade.glsl")->find("0.0698"), std::string::npos);
  EXPECT_EQ(r.artifact->file("shade.glsl")->find("lightParams . w"), std::string::npos);
  EXPECT_NE(fromScene.artifact->file("shade.glsl")->find("lightParams . w"), std::string::npos);
}

}  // namespace
}  // namespace shadowc

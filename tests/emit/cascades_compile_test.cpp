// Cascaded suns at compile time: every sample with the depth representation and
// no min-max pyramid compiles as `light sun(angle: 0.53)` + `cascades 4`, every SPIR-V module
// passes spirv-val, the shade pass and the includable lookup carry the atlas code (the tile clamp,
// the cascade selection) and the block's cascade fields, and the manifest says cascades{count,
// grid}. Every other sample is refused with E0452 (their prefilters would mix tiles). Siblings:
// the same suns without `cascades` carry none of the cascade code or fields.
#include <gtest/gtest.h>

#include "backend/spirv_backend.h"
#include "emit/emit_support.h"
#include "spec/filter_spec.h"
#include "spec/load_filter.h"
#include "spec/print_filter.h"

namespace shadowc {
namespace {

constexpr const char* kTileClamp = "shadowc_cascadeTileRect";
constexpr const char* kBlockField = "vec4 cascades[8];";

std::string withCascades(const std::string& sample, const std::string& cascades) {
  std::string text = test::withLight(test::readFile(test::samplePath(sample)), "light sun(angle: 0.53)");
  const size_t close = text.rfind('}');
  return text.substr(0, close) + cascades + text.substr(close);
}

class CascadeSample : public ::testing::TestWithParam<std::string> {};

TEST_P(CascadeSample, CompilesAsAnAtlasOrIsRefusedWithTheReason) {
  const driver::Result plain = driver::compileSource(withCascades(GetParam(), ""), GetParam() + "_sun.shadow");
  if (test::compileSample(GetParam()).artifact->spec.lightSamples > 0) {  // no sun: E0471 (light_types test)
    EXPECT_FALSE(plain.ok);
    EXPECT_NE(plain.log.find("[E0471]"), std::string::npos) << plain.log;
    return;
  }
  ASSERT_TRUE(plain.ok) << plain.log;
  const FilterSpec& s = plain.artifact->spec;
  const bool servable = s.representation == Representation::Depth && !s.earlyOutMinMax;
  const driver::Result r =
      driver::compileSource(withCascades(GetParam(), "    cascades 4\n"), GetParam() + "_cascaded.shadow");
  if (!servable) {
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.log.find("[E0452]"), std::string::npos) << r.log;
    return;
  }
  ASSERT_TRUE(r.ok) << GetParam() << ":\n" << r.log;
  EXPECT_EQ(r.artifact->spec.cascades.count, 4);
  EXPECT_GE(test::expectEverySpirvValid(*r.artifact, GetParam()), 1);
  const std::string shade = *r.artifact->file("shade.glsl");
  const std::string lookup = *r.artifact->file(s.name + "_lookup.glsl");
  for (const std::string* text : {&shade, &lookup}) {
    EXPECT_NE(text->find(kTileClamp), std::string::npos);
    EXPECT_NE(text->find("shadowc_visibilityInCascade"), std::string::npos);
    EXPECT_NE(text->find(kBlockField), std::string::npos);
  }
  EXPECT_NE(r.artifact->file("manifest.json")->find(R"("grid": 2)"), std::string::npos);
  // Sibling: without `cascades` none of it.
  for (const char* name : {"shade.glsl", "manifest.json"}) {
    const std::string& text = *plain.artifact->file(name);
    EXPECT_EQ(text.find(kTileClamp), std::string::npos) << name;
    EXPECT_EQ(text.find(kBlockField), std::string::npos) << name;
    EXPECT_EQ(text.find(R"("cascades")"), std::string::npos) << name;
  }
  EXPECT_EQ(plain.artifact->file(s.name + "_lookup.glsl")->find("cascade"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Samples, CascadeSample, ::testing::ValuesIn(test::sampleFilterNames()),
                         [](const auto& info) { return info.param; });

// The 3x3 atlas for 5..8 cascades; the printed spec reads back to the same spec.
TEST(Cascades, GridAndPrintedSpecRoundTrip) {
  EXPECT_EQ(cascadeGrid(1), 1);
  EXPECT_EQ(cascadeGrid(4), 2);
  EXPECT_EQ(cascadeGrid(5), 3);
  EXPECT_EQ(cascadeGrid(8), 3);
  const driver::Result r =
      driver::compileSource(withCascades("pcss_poisson", "    cascades log(count: 6, blend: 0.25)\n"), "c.shadow");
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_EQ(r.artifact->spec.cascades.split, CascadeSplit::Log);
  EXPECT_DOUBLE_EQ(r.artifact->spec.cascades.blend, 0.25);
  EXPECT_NE(r.artifact->file("shade.glsl")->find("ivec2(c % 3, c / 3)"), std::string::npos);  // the 3x3 tiles
  const std::string printed = printFilter(r.artifact->spec);
  EXPECT_NE(printed.find("cascades   log(count: 6, blend: 0.25)"), std::string::npos) << printed;
  const LoadResult back = loadFilterSource(printed, "printed.shadow");
  ASSERT_TRUE(back.spec) << printed << formatDiagnostics(back);
  EXPECT_EQ(specToJson(*back.spec).dump(2), specToJson(r.artifact->spec).dump(2)) << printed;
}

}  // namespace
}  // namespace shadowc

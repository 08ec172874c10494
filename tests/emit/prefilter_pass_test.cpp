// Every prefilter pass of every technique family compiles from its template, at -O and -O0,
// to SPIR-V that passes spirv-val; the emitted GLSL is the preprocessed, folded text.
#include <gtest/gtest.h>

#include <string>

#include "backend/spirv_backend.h"
#include "driver/shader_compile.h"
#include "emit/template_includes.h"
#include "plan/planner.h"
#include "plan/test_specs.h"

namespace shadowc {
namespace {

std::vector<FilterSpec> variants() {
  std::vector<FilterSpec> v = {test::vssmInt32Spec(), test::layeredEvsmSpec(), test::blurMipSpec()};
  for (Warp w : {Warp::Exp, Warp::Evsm2}) {
    FilterSpec s = test::blurMipSpec();
    s.moments.warp = w;
    s.prefilter.blur = BlurKind::Box;
    s.storage.format = StorageFormat::Unorm16;
    v.push_back(s);
  }
  FilterSpec lloyd = test::layeredEvsmSpec();
  lloyd.moments.split = SplitPlacement::Lloyd;
  v.push_back(lloyd);
  for (SatKind k : {SatKind::Fp32Centered, SatKind::Fp32Naive}) {
    FilterSpec s = test::vssmInt32Spec();
    s.storage.sat = k;
    s.moments.layers = 2;                // layered SAT: a filtered-moments lookup (VSSM needs one layer)
    s.moments.splits = {0.0, 0.5, 1.0};  // uniform, as normalization writes it
    s.blocker.kind = BlockerKind::None;
    s.kernel.subdivision = Subdivision::None;
    v.push_back(s);
    s.moments.split = SplitPlacement::Lloyd;  // the fused row scan reads the Lloyd splits
    v.push_back(s);
  }
  FilterSpec blurredSat = test::vssmInt32Spec();  // unfused: the rows read the blurred moments
  blurredSat.prefilter.blur = BlurKind::Box;
  blurredSat.prefilter.blurRadius = 1;
  v.push_back(blurredSat);
  return v;
}

TEST(PrefilterPasses, EveryPassOfEveryVariantCompilesAndValidatesAtBothLevels) {
  int compiled = 0;
  for (const FilterSpec& spec : variants()) {
    const PassGraph g = planPasses(spec);
    std::set<std::string> seen;
    for (const PassSource& src : g.sources) {
      if (src.templatePath == "shade.comp" || !seen.insert(src.stem).second) continue;
      for (bool optimize : {true, false}) {
        const driver::CompiledShader sh = driver::compileShader(src.templatePath, src.values, {optimize, true});
        ASSERT_TRUE(sh.ok) << spec.name << " " << src.stem << (optimize ? " -O" : " -O0") << "\n" << sh.log;
        EXPECT_EQ(validateSpirv(sh.spirv), "") << src.stem;
        EXPECT_EQ(sh.glsl.find("@shadowc:specialize"), std::string::npos);  // marker replaced
        EXPECT_EQ(sh.glsl.find("#define"), std::string::npos) << src.stem;  // folded by the preprocessor
        ++compiled;
      }
    }
  }
  EXPECT_GE(compiled, 30);
}

TEST(PrefilterPasses, LocalSizeIsReadBackFromTheEmittedShader) {
  const PassGraph g = planPasses(test::vssmInt32Spec());
  for (const PassSource& src : g.sources) {
    if (src.stem != "sat_rows" && src.stem != "moments") continue;
    const driver::CompiledShader sh = driver::compileShader(src.templatePath, src.values, {});
    ASSERT_TRUE(sh.ok) << sh.log;
    const std::array<uint32_t, 3> expected =
        src.stem == "sat_rows" ? std::array<uint32_t, 3>{64, 1, 1} : std::array<uint32_t, 3>{8, 8, 1};
    EXPECT_EQ(sh.localSize, expected) << src.stem;
  }
}

TEST(PrefilterPasses, UnusedWarpsAndSatKindsAreAbsentFromTheEmittedGlsl) {
  const PassGraph g = planPasses(test::vssmInt32Spec());
  for (const PassSource& src : g.sources) {
    if (src.stem == "moments") {
      const driver::CompiledShader sh = driver::compileShader(src.templatePath, src.values, {});
      ASSERT_TRUE(sh.ok) << sh.log;
      EXPECT_EQ(sh.glsl.find("exp("), std::string::npos) << "linear warp must not carry the EVSM code";
      EXPECT_EQ(sh.glsl.find("splitsImage"), std::string::npos);
    }
    if (src.stem == "sat_rows") {
      const driver::CompiledShader sh = driver::compileShader(src.templatePath, src.values, {});
      ASSERT_TRUE(sh.ok) << sh.log;
      EXPECT_NE(sh.glsl.find("uimage2DArray"), std::string::npos);
      EXPECT_NE(sh.glsl.find("65536.0"), std::string::npos) << "16.16 fixed point encode";
      EXPECT_EQ(sh.glsl.find("- 0.5"), std::string::npos) << "centered fp32 path must be gone";
      // Fused: the scan warps the depth itself; the linear warp only, no splits image.
      EXPECT_NE(sh.glsl.find("shadowDepth"), std::string::npos);
      EXPECT_EQ(sh.glsl.find("momentsIn"), std::string::npos);
      EXPECT_EQ(sh.glsl.find("exp("), std::string::npos) << "linear warp must not carry the EVSM code";
      EXPECT_EQ(sh.glsl.find("splitsImage"), std::string::npos);
    }
  }
}

// The sibling: a broken specialization fails, and the message points into the template at the
// line that uses the constant (the #line after the specialization block keeps numbers right).
TEST(PrefilterPasses, ErrorsPointIntoTheTemplateLine) {
  Specialization l;
  l.add("SHADOWC_BLUR_RADIUS", 2LL);
  l.add("SHADOWC_BLUR_WEIGHTS", RealList{{1.0}});  // 1 weight, 3 needed
  const driver::CompiledShader sh = driver::compileShader("passes/blur.comp", l, {});
  ASSERT_FALSE(sh.ok);
  const std::string text(templateText("passes/blur.comp"));
  const size_t at = text.find("= SHADOWC_BLUR_WEIGHTS;");
  ASSERT_NE(at, std::string::npos);
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
  EXPECT_NE(sh.log.find("templates/passes/blur.comp:" + std::to_string(line) + ":"), std::string::npos) << sh.log;
}

TEST(PrefilterPasses, UnknownTemplateIsAnError) {
  const driver::CompiledShader sh = driver::compileShader("passes/nope.comp", {}, {});
  EXPECT_FALSE(sh.ok);
  EXPECT_NE(sh.log.find("template not found"), std::string::npos);
}

}  // namespace
}  // namespace shadowc

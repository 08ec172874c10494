// Golden files of the emitted GLSL (glslang's Test/baseResults habit): a change to emitted
// code is a reviewed diff. Update after review with SHADOWC_UPDATE_GOLDEN=1. Goldens live in
// tests/emit/golden/<filter>/<stem>.glsl.
#include <gtest/gtest.h>

#include <fstream>

#include "emit/emit_support.h"
#include "emit/filter_emitter.h"  // lookupFileName
#include "plan/test_specs.h"

namespace shadowc {
namespace {

void checkGoldens(const driver::Result& r, std::string dir = "") {
  ASSERT_TRUE(r.ok) << r.log;
  const FilterSpec& spec = r.artifact->spec;
  if (dir.empty()) dir = spec.name;
  int compared = 0;
  for (const EmittedFile& f : r.artifact->files) {
    if (!f.name.ends_with(".glsl") || f.name == lookupFileName(spec.name)) continue;  // lookup == shade's code
    const auto golden = test::sourceDir() / "tests" / "emit" / "golden" / dir / f.name;
    EXPECT_EQ(test::compareGolden(golden, f.bytes), "");
    ++compared;
  }
  EXPECT_GE(compared, 1);
}

TEST(EmitGolden, VssmAdaptiveSample) { checkGoldens(test::compileSample("vssm_adaptive")); }
TEST(EmitGolden, PcfPoisson16Sample) { checkGoldens(test::compileSample("pcf_poisson16")); }
TEST(EmitGolden, LayeredVsmUniformSample) { checkGoldens(test::compileSample("layered_vsm_uniform")); }
TEST(EmitGolden, PcssPoissonSample) { checkGoldens(test::compileSample("pcss_poisson")); }
TEST(EmitGolden, PcfDepthOnly) { checkGoldens(driver::compileSpec(test::pcfSpec())); }
TEST(EmitGolden, VssmInt32WithMinMax) { checkGoldens(driver::compileSpec(test::vssmInt32Spec())); }
TEST(EmitGolden, LayeredEvsm4Fp16) { checkGoldens(driver::compileSpec(test::layeredEvsmSpec())); }
TEST(EmitGolden, PowerCdfBlurMips) { checkGoldens(driver::compileSpec(test::blurMipSpec())); }
TEST(EmitGolden, MsmUnorm16Sample) { checkGoldens(test::compileSample("msm_unorm16")); }
// `compile --generic` (plan/generic_block.h): the same sample with its options in the uniform block.
TEST(EmitGolden, PcfPoisson16Generic) {
  driver::Options o;
  o.generic = true;
  checkGoldens(driver::compileFile(test::samplePath("pcf_poisson16").string(), o), "pcf_poisson16_generic");
}

// The sibling that proves the comparison can fail.
TEST(EmitGolden, AChangedByteIsReported) {
  const auto dir = test::freshTempDir("golden-sibling");
  const auto file = dir / "x.glsl";
  { std::ofstream(file) << "void main() {}\n"; }
  if (const char* u = std::getenv("SHADOWC_UPDATE_GOLDEN"); u && std::string(u) == "1") GTEST_SKIP() << "update mode";
  EXPECT_NE(test::compareGolden(file, "void main() { }\n"), "");
  EXPECT_EQ(test::compareGolden(file, "void main() {}\n"), "");
}

}  // namespace
}  // namespace shadowc

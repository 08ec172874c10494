// --emit hlsl,msl: every sample filter gets HLSL and MSL for every pass and for the lookup, and
// every HLSL file compiles back to SPIR-V with glslang's HLSL front end and passes spirv-val,
// unless hlsl_roundtrip_exceptions.txt gives the reason for that file (an entry that now passes
// is an error too, so the list cannot go stale). MSL cannot be compiled here (no Metal
// compiler on Linux): its check is structural.
#include "driver/cross_outputs.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>

#include "backend/cross_compile.h"
#include "backend/spirv_backend.h"
#include "emit/emit_support.h"

namespace shadowc {
namespace {

// "<sample>/<file>: reason" lines; '#' starts a comment.
std::map<std::string, std::string> exceptions() {
  std::map<std::string, std::string> out;
  std::ifstream in(test::sourceDir() / "tests" / "engine" / "hlsl_roundtrip_exceptions.txt");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const size_t colon = line.find(": ");
    if (colon != std::string::npos) out[line.substr(0, colon)] = line.substr(colon + 2);
  }
  return out;
}

driver::Result compileWithCross(const std::string& sample) {
  driver::Options o;
  o.engineOutputs = {driver::OutputKind::Hlsl, driver::OutputKind::Msl};
  return driver::compileFile(test::samplePath(sample).string(), o);
}

class CrossOutputs : public ::testing::TestWithParam<std::string> {};

TEST_P(CrossOutputs, HlslAndMslForEveryPassAndTheLookupAndTheHlslRoundTrips) {
  const driver::Result r = compileWithCross(GetParam());
  ASSERT_TRUE(r.ok) << r.log;
  const Manifest& m = r.artifact->manifest;
  std::set<std::string> stems{m.shade.glsl.substr(0, m.shade.glsl.rfind('.'))};
  for (const Pass& p : m.passes) stems.insert(p.spirv.substr(0, p.spirv.rfind('.')));
  const auto known = exceptions();
  for (const std::string& stem : stems) {
    const bool lookup = stem + ".glsl" == m.shade.glsl;
    const std::string* hlsl = r.artifact->file(stem + ".hlsl");
    const std::string* msl = r.artifact->file(stem + ".metal");
    ASSERT_TRUE(hlsl && msl) << stem;
    EXPECT_EQ(driver::outputKindOf(stem + ".hlsl"), driver::OutputKind::Hlsl);
    // MSL: a compute kernel; the lookup keeps its function under its own name.
    EXPECT_NE(msl->find(std::string("kernel void ") + (lookup ? kLookupProbeEntry : "main0")), std::string::npos)
        << stem << ".metal";
    if (lookup) {
      EXPECT_NE(msl->find("float " + m.shade.function + "("), std::string::npos);
      EXPECT_NE(hlsl->find("float " + m.shade.function + "(float3 worldPos, float3 worldNormal)"), std::string::npos)
          << "the HLSL lookup keeps the GLSL signature";
    }
    const SpirvResult back =
        compileHlsl(*hlsl, ShaderStage::Compute, stem + ".hlsl", lookup ? kLookupProbeEntry : "main");
    const std::string key = GetParam() + "/" + stem + ".hlsl";
    if (known.count(key))
      EXPECT_FALSE(back.ok) << key << " is listed in hlsl_roundtrip_exceptions.txt but now round-trips: remove it";
    else
      EXPECT_TRUE(back.ok) << key << ":\n" << back.log;
    if (back.ok) {
      EXPECT_EQ(validateSpirv(back.words), "") << key;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, CrossOutputs, ::testing::ValuesIn(test::sampleFilterNames()),
                         [](const auto& info) { return info.param; });

// The round-trip check can fail: HLSL the front end rejects, and HLSL that parses but uses a
// texture it never declared.
TEST(CrossOutputs, TheHlslRoundTripRejectsBrokenHlsl) {
  const driver::Result r = compileWithCross("pcf_grid5x5");
  ASSERT_TRUE(r.ok) << r.log;
  std::string hlsl = *r.artifact->file("shade.hlsl");
  ASSERT_TRUE(compileHlsl(hlsl, ShaderStage::Compute, "shade.hlsl", "main").ok);
  EXPECT_FALSE(compileHlsl(hlsl.substr(0, hlsl.size() / 2), ShaderStage::Compute, "half.hlsl", "main").ok);
  const size_t decl = hlsl.find("Texture2D<float4> shadowc_shadowDepth");
  ASSERT_NE(decl, std::string::npos);
  hlsl.erase(decl, hlsl.find('\n', decl) - decl);
  EXPECT_FALSE(compileHlsl(hlsl, ShaderStage::Compute, "undeclared.hlsl", "main").ok);
}

// --frame-external: the HLSL and MSL lookups take the frame as arguments, for every light type
// (a spot sample, a sun with cascades, a point light), declare no frame block, and round-trip.
struct ExternalCase {
  std::string name, source;
};
std::vector<ExternalCase> externalCases() {
  const std::string pcss = test::readFile(test::samplePath("pcss_poisson"));
  std::string sun = test::withLight(pcss, "light sun(angle: 0.53)");
  sun.insert(sun.rfind('}'), "    cascades 4\n");
  return {{"spot", test::readFile(test::samplePath("vssm_pcf_fallback"))},
          {"cascaded_sun", sun},
          {"point", test::withLight(test::readFile(test::samplePath("pcf_poisson16")), "light point(radius: 0.1)")}};
}

driver::Result compileExternal(const ExternalCase& c, bool external) {
  driver::Options o;
  o.engineOutputs = {driver::OutputKind::Hlsl, driver::OutputKind::Msl};
  o.frameExternal = external;
  return driver::compileSource(c.source, c.name + ".shadow", o);
}

TEST(CrossOutputs, TheExternalFrameLookupTakesTheFrameAsArgumentsForEveryLightType) {
  for (const ExternalCase& c : externalCases()) {
    const driver::Result r = compileExternal(c, true);
    ASSERT_TRUE(r.ok) << c.name << ":\n" << r.log;
    const Manifest& m = r.artifact->manifest;
    const std::string stem = m.shade.glsl.substr(0, m.shade.glsl.rfind('.'));
    const std::string* hlsl = r.artifact->file(stem + ".hlsl");
    const std::string* msl = r.artifact->file(stem + ".metal");
    ASSERT_TRUE(hlsl && msl) << c.name;
    const bool cascaded = c.name == "cascaded_sun";
    const std::string signature = std::string("float ") + kLookupExternalFunction +
                                  "(float3 worldPos, float3 worldNormal, shadowc_Frame frame" +
                                  (cascaded ? ", shadowc_Cascades cascades)" : ")");
    EXPECT_NE(hlsl->find(signature), std::string::npos) << c.name << ": " << signature;
    EXPECT_NE(msl->find(std::string("float ") + kLookupExternalFunction + "(thread const float3& worldPos"),
              std::string::npos)
        << c.name;
    for (const std::string* text : {hlsl, msl}) {
      EXPECT_EQ(text->find("shadowc_frameBlock"), std::string::npos) << c.name << ": the block is left out";
      EXPECT_NE(text->find("struct shadowc_Frame"), std::string::npos) << c.name;
    }
    const SpirvResult back = compileHlsl(*hlsl, ShaderStage::Compute, stem + ".hlsl", kLookupProbeEntry);
    ASSERT_TRUE(back.ok) << c.name << ":\n" << back.log;
    EXPECT_EQ(validateSpirv(back.words), "") << c.name;
    // The sibling: without the option the same lookup declares our block and no frame argument.
    const driver::Result block = compileExternal(c, false);
    ASSERT_TRUE(block.ok) << block.log;
    const std::string* blockHlsl = block.artifact->file(stem + ".hlsl");
    ASSERT_TRUE(blockHlsl);
    EXPECT_NE(blockHlsl->find("shadowc_frameBlock"), std::string::npos) << c.name;
    EXPECT_EQ(blockHlsl->find(kLookupExternalFunction), std::string::npos) << c.name;
  }
}

TEST(CrossOutputs, TheExternalFrameWithoutHlslOrMslIsOneMessage) {
  const test::CliResult c = test::runShadowc("compile " + test::samplePath("pcf_grid5x5").string() + " -o " +
                                             test::freshTempDir("frame-external").string() + " --frame-external");
  EXPECT_NE(c.code, 0);
  EXPECT_NE(c.err.find("--frame-external changes the HLSL and MSL lookups"), std::string::npos) << c.err;
}

TEST(CrossOutputs, NotAskedForNotProduced) {
  const driver::Result r = test::compileSample("pcf_grid5x5");
  ASSERT_TRUE(r.ok) << r.log;
  for (const EmittedFile& f : r.artifact->files) {
    EXPECT_FALSE(f.name.ends_with(".hlsl") || f.name.ends_with(".metal") || f.name.ends_with(".h")) << f.name;
  }
}

TEST(CrossOutputs, TheDependencyRuleListsTheEngineOutputs) {
  const auto dir = test::freshTempDir("cross-deps");
  const test::CliResult c = test::runShadowc("compile " + test::samplePath("pcf_grid5x5").string() + " -o " +
                                             dir.string() + " --emit hlsl,msl,cpp -M");
  ASSERT_EQ(c.code, 0) << c.err;
  for (const char* f : {"shade.hlsl", "shade.metal", "pcf_grid5x5_lookup.hlsl", "pcf_grid5x5.h"})
    EXPECT_NE(c.out.find((dir / f).string()), std::string::npos) << f << " in " << c.out;
  EXPECT_EQ(c.out.find("shade.spv"), std::string::npos) << "spirv was not asked for";
}

}  // namespace
}  // namespace shadowc

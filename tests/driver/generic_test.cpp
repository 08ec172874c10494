// `shadowc compile --generic` (driver::Options::generic, plan/generic_block.h): the shade pass's
// numeric options and tables move into a uniform block that the manifest records and the
// runtime fills, so that filters differing only in numbers compile to one shader; code-path
// switches stay compile-time; the output is deterministic. The GPU side (same visibility as the
// specialized shader, a wrong block value caught) is tests/gpu/generic_shader_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "driver/driver.h"
#include "emit/filter_emitter.h"  // kManifestFile
#include "plan/generic_block.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

std::string pcfPoisson(int taps, double constantBias) {
  return "filter pcf_g {\n  depth\n  kernel fixed(7)\n  sampling poisson(" + std::to_string(taps) +
         ", rotate: stable)\n  bias slope(0.005, constant: " + std::to_string(constantBias) + ")\n}\n";
}

driver::Artifact compile(const std::string& text, bool generic, const std::string& name = "pcf_g.shadow") {
  driver::Options o;
  o.generic = generic;
  const driver::Result r = driver::compileSource(text, name, o);
  EXPECT_TRUE(r.ok) << r.log;
  if (!r.artifact) throw std::runtime_error("did not compile: " + r.log);
  return *r.artifact;
}

const Pass& shadePass(const driver::Artifact& a) {
  return *std::find_if(a.manifest.passes.begin(), a.manifest.passes.end(),
                       [](const Pass& p) { return p.name == "shade"; });
}

const BlockMember* member(const ParameterBlock& b, const std::string& macro) {
  for (const BlockMember& m : b.members)
    if (m.macro == macro) return &m;
  return nullptr;
}

TEST(Generic, OptionsAndTablesBecomeABlockTheManifestRecords) {
  const driver::Artifact a = compile(pcfPoisson(16, 0.001), true);
  const Pass& shade = shadePass(a);
  ASSERT_TRUE(shade.parameters.has_value());
  const ParameterBlock& b = *shade.parameters;
  EXPECT_EQ(b.binding, kGenericBinding);
  EXPECT_EQ(b.size % 16, 0u);
  EXPECT_TRUE(std::any_of(shade.bindings.begin(), shade.bindings.end(), [](const Binding& x) {
    return x.binding == kGenericBinding && x.image == kParametersBinding && x.access == Access::Uniform;
  }));
  const BlockMember* taps = member(b, "SHADOWC_PCF_TAPS");
  ASSERT_NE(taps, nullptr);
  EXPECT_EQ(taps->type, ScalarType::I32);
  EXPECT_EQ(taps->values, std::vector<double>{16});
  const BlockMember* bias = member(b, "SHADOWC_BIAS_CONSTANT");
  ASSERT_NE(bias, nullptr);
  EXPECT_EQ(bias->values, std::vector<double>{0.001});
  const BlockMember* poisson = member(b, "shadowc_poissonPcf");
  ASSERT_NE(poisson, nullptr);
  EXPECT_EQ(poisson->count, uint32_t(kMaxGenericTaps));  // whatever the filter's count
  EXPECT_EQ(poisson->components, 2u);
  EXPECT_EQ(poisson->stride, 16u);
  EXPECT_EQ(poisson->values.size(), 32u);
  EXPECT_EQ(poisson->offset % 16, 0u);
  // The shader reads the block where the specialized one has literals; no macro is left.
  const std::string& glsl = *a.file("shade.glsl");
  EXPECT_NE(glsl.find("uniform shadowc_GenericBlock"), std::string::npos);
  EXPECT_NE(glsl.find("shadowc_generic . pcfTaps"), std::string::npos);
  EXPECT_NE(glsl.find("shadowc_generic . poissonPcf["), std::string::npos);
  EXPECT_EQ(glsl.find("#define"), std::string::npos);
  // The specialized twin has none of it (the sibling: the checks above can fail).
  const driver::Artifact s = compile(pcfPoisson(16, 0.001), false);
  EXPECT_FALSE(shadePass(s).parameters.has_value());
  EXPECT_EQ(s.file("shade.glsl")->find("shadowc_generic"), std::string::npos);
  // The manifest round-trips the block exactly.
  const Manifest back = manifestFromJson(nlohmann::json::parse(*a.file(kManifestFile)));
  EXPECT_EQ(shadePass(a).parameters, back.passes.back().parameters);
}

TEST(Generic, FiltersDifferingOnlyInNumbersShareOneShader) {
  const driver::Artifact a = compile(pcfPoisson(8, 0.001), true), b = compile(pcfPoisson(32, 0.004), true);
  EXPECT_EQ(*a.file("shade.spv"), *b.file("shade.spv"));
  EXPECT_EQ(*a.file("shade.glsl"), *b.file("shade.glsl"));
  EXPECT_NE(shadePass(a).parameters, shadePass(b).parameters);
  EXPECT_NE(a.manifest.contentHash, b.manifest.contentHash);  // the hash sees the values
  // Specialized, the same two filters are two shaders.
  const driver::Artifact sa = compile(pcfPoisson(8, 0.001), false), sb = compile(pcfPoisson(32, 0.004), false);
  EXPECT_NE(*sa.file("shade.spv"), *sb.file("shade.spv"));
}

TEST(Generic, CodePathSwitchesStayStaticAndOutputIsDeterministic) {
  // A different pattern (grid) is a different code path: a different generic shader.
  const std::string grid = "filter pcf_g {\n  depth\n  kernel fixed(7)\n  sampling grid(5x5)\n}\n";
  const driver::Artifact g = compile(grid, true), p = compile(pcfPoisson(16, 0.001), true);
  EXPECT_NE(*g.file("shade.spv"), *p.file("shade.spv"));
  const driver::Artifact again = compile(pcfPoisson(16, 0.001), true);
  ASSERT_EQ(again.files.size(), p.files.size());
  for (size_t i = 0; i < p.files.size(); ++i) EXPECT_EQ(again.files[i].bytes, p.files[i].bytes) << p.files[i].name;
}

TEST(Generic, UnrolledQuadtreeBecomesTheLoopWalk) {
  const std::string text = test::readFile(test::sourceDir() / "samples/filters/vssm_quadtree_unrolled.shadow");
  const driver::Artifact s = compile(text, false, "vssm_quadtree_unrolled.shadow");
  const driver::Artifact g = compile(text, true, "vssm_quadtree_unrolled.shadow");
  EXPECT_NE(s.file("shade.glsl")->find("shadowc_qtUnrolledKernel"), std::string::npos);  // the sibling
  EXPECT_EQ(g.file("shade.glsl")->find("shadowc_qtUnrolledKernel"), std::string::npos);
  const BlockMember* nodes = member(*shadePass(g).parameters, "SHADOWC_QT_NODES");
  ASSERT_NE(nodes, nullptr);
  EXPECT_EQ(nodes->values, std::vector<double>{1 + 4 + 16 + 64});  // height 3
  EXPECT_NE(member(*shadePass(g).parameters, "SHADOWC_KERNEL_HEIGHT"), nullptr);
  EXPECT_EQ(member(*shadePass(g).parameters, "SHADOWC_LAYERS"), nullptr);  // sizes arrays: static
}

TEST(Generic, TheLookupDeclaresTheBlockWhereThePlacementSays) {
  driver::Options o;
  o.generic = true;
  o.lookup = {2, 10};
  const driver::Result r = driver::compileSource(pcfPoisson(16, 0.001), "pcf_g.shadow", o);
  ASSERT_TRUE(r.ok) << r.log;
  const std::string& lookup = *r.artifact->file("pcf_g_lookup.glsl");
  EXPECT_NE(lookup.find("layout(set = 2, binding = 19, std140)uniform shadowc_GenericBlock"), std::string::npos)
      << lookup.substr(0, 1500);
  const auto& sb = r.artifact->manifest.shade.bindings;
  EXPECT_TRUE(std::any_of(sb.begin(), sb.end(),
                          [](const Binding& b) { return b.image == kParametersBinding && b.binding == 19; }));
}

TEST(Generic, ABlockMemberThatDoesNotFitIsAManifestError) {
  const driver::Artifact a = compile(pcfPoisson(16, 0.001), true);
  nlohmann::json j = nlohmann::json::parse(*a.file(kManifestFile));
  EXPECT_NO_THROW(manifestFromJson(j));
  j["passes"].back()["parameters"]["members"][0]["offset"] = 1u << 20;
  EXPECT_THROW(manifestFromJson(j), ManifestError);
}

}  // namespace
}  // namespace shadowc

// The generic shader (`shadowc compile --generic`, plan/generic_block.h) computes the visibility
// of the specialized one: the same filter, its options read from the uniform block the run
// harness fills from the manifest instead of folded literals. Per sample filter on two_planes
// (64x64 screen, 256 map), through the one run harness with validation on (the fixture fails
// on any message). Tolerance: max |generic - specialized| <= 1e-3 per pixel — the two differ
// only where the compilers fold constants (glslang/spirv-opt, lavapipe's LLVM) in another order;
// measured well below it (printed). The siblings edit one value of the block (the PCF tap count,
// the kernel width) and must move the visibility far past that tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

using GenericShaderTest = VulkanTest;

constexpr uint32_t kScreen = 64, kMap = 256;
constexpr double kTolerance = 1e-3;

const CompiledFilter* compileGeneric(const std::string& name) {
  static std::map<std::string, std::unique_ptr<CompiledFilter>> cache;
  if (auto it = cache.find(name); it != cache.end()) return it->second.get();
  driver::Options o;
  o.generic = true;
  const driver::Result r = driver::compileSource(sampleSource(name), name + ".shadow", o);
  if (!r.artifact) {
    ADD_FAILURE() << name << " --generic: " << r.log;
    return nullptr;
  }
  auto cf = std::make_unique<CompiledFilter>();
  cf->spec = r.artifact->spec;
  cf->passes = r.artifact->passes();
  return (cache[name] = std::move(cf)).get();
}

std::vector<double> visibility(rt::VulkanContext& ctx, const CompiledPasses& passes) {
  const rt::SceneRunResult run = rt::runOnScene(ctx, passes, sceneCase(ctx, "two_planes", kMap, kScreen, 2));
  return {run.outputs.visibility.begin(), run.outputs.visibility.end()};
}

BlockMember& member(CompiledPasses& c, const std::string& macro) {
  for (Pass& p : c.manifest.passes)
    if (p.parameters)
      for (BlockMember& m : p.parameters->members)
        if (m.macro == macro) return m;
  throw std::runtime_error("no block member " + macro);
}

class GenericMatchesSpecialized : public GenericShaderTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(GenericMatchesSpecialized, OnTwoPlanes) {
  const std::string name = GetParam();
  const CompiledFilter* s = compileFilterCached(name, sampleSource(name));
  const CompiledFilter* g = compileGeneric(name);
  ASSERT_TRUE(s && g);
  ASSERT_TRUE(g->passes.manifest.passes.back().parameters.has_value());
  const std::vector<double> vs = visibility(context(), s->passes), vg = visibility(context(), g->passes);
  const MaxError e = maxAbsError(vs, vg);
  fmt::print("{}: generic vs specialized max |diff| {:.3g} at pixel {}\n", name, e.error, e.index);
  EXPECT_LE(e.error, kTolerance) << name << " pixel " << e.index << ": specialized " << vs[e.index] << ", generic "
                                 << vg[e.index];
  // Not a trivially lit frame: the comparison sees shadow.
  EXPECT_LT(*std::min_element(vs.begin(), vs.end()), 0.5) << name;
}

INSTANTIATE_TEST_SUITE_P(Samples, GenericMatchesSpecialized,
                         ::testing::Values("hard_normal_offset_bias", "pcf_grid5x5", "pcf_bilinear3x3", "pcf_poisson16",
                                           "pcss_poisson", "pcss_grid_search", "vsm_chebyshev",
                                           "vsm_blur_mips_bleeding", "esm", "evsm4", "msm_plain", "power_cdf",
                                           "layered_vsm_uniform", "vssm_pcf_fallback", "vssm_uniform_kernel",
                                           "vssm_quadtree_table", "vssm_quadtree_unrolled", "vssm_blocker_quadtree",
                                           "vssm_contact", "vssm_minmax_early_out"),
                         [](const auto& info) { return std::string(info.param); });

// The siblings: the same generic shader with one wrong value in the block is caught.
TEST_F(GenericShaderTest, AWrongTapCountInTheBlockIsCaught) {
  const CompiledFilter* s = compileFilterCached("pcf_poisson16", sampleSource("pcf_poisson16"));
  const CompiledFilter* g = compileGeneric("pcf_poisson16");
  ASSERT_TRUE(s && g);
  CompiledPasses wrong = g->passes;
  BlockMember& taps = member(wrong, "SHADOWC_PCF_TAPS");
  ASSERT_EQ(taps.values, std::vector<double>{16});
  taps.values = {3};
  const MaxError e = maxAbsError(visibility(context(), s->passes), visibility(context(), wrong));
  EXPECT_GT(e.error, 50 * kTolerance);
}

// A filter whose lookup reads the kernel width: grid PCF (vsm_chebyshev without a SAT or mips
// reads one bilinear tap, so a wrong width there changes nothing).
TEST_F(GenericShaderTest, AWrongKernelWidthInTheBlockIsCaught) {
  const CompiledFilter* s = compileFilterCached("pcf_grid5x5", sampleSource("pcf_grid5x5"));
  const CompiledFilter* g = compileGeneric("pcf_grid5x5");
  ASSERT_TRUE(s && g);
  CompiledPasses wrong = g->passes;
  BlockMember& width = member(wrong, "SHADOWC_KERNEL_FIXED_TEXELS");
  width.values = {width.values.at(0) * 4};
  const MaxError e = maxAbsError(visibility(context(), s->passes), visibility(context(), wrong));
  EXPECT_GT(e.error, 50 * kTolerance);
}

}  // namespace
}  // namespace shadowc::test

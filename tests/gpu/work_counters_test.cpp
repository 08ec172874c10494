// The instrumented build's work counters (plan/work_counters.h, docs/manifest.md "Work
// counters") against closed forms, exactly:
//  * PCF on a 5 x 5 grid reads 25 depth texels a receiver and Poisson PCF its 16 taps, on
//    two_planes at two screen sizes (the count a receiver does not depend on the screen);
//  * PCSS reads its search taps, and its kernel taps only when the search found a blocker: a lit,
//    a penumbra and an umbra receiver on crafted maps;
//  * VSM takes one filtered moment fetch and one Chebyshev bound a receiver;
//  * VSSM on a flat occluder: a lit receiver classifies one box (the blocker walk's root) and
//    evaluates no bound; an umbra receiver walks both uniform grids, (1 + m^2) + (1 + n^2) boxes,
//    two bounds (the blocker's normal group, the visibility's) and no depth texel;
//  * the counts of two runs are identical, and a plain build carries none.
// Siblings show the check can fail: a closed form one tap off, and a run without receivers.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

using WorkCountersTest = VulkanTest;

constexpr uint32_t kMap = 256;

// `source` compiled as the instrumented build, once per label.
const CompiledPasses* countedBuild(const std::string& label, const std::string& source) {
  const CompiledFilter* f = compileFilterCached(label, source, /*optimize=*/true, /*counters=*/true);
  return f ? &f->passes : nullptr;
}

// Every receiver counted `perReceiver` of `field`, exactly: total = perReceiver x receivers, and
// at least one receiver (a run that compared nothing proves nothing).
::testing::AssertionResult countsExactly(const std::optional<rt::WorkCounts>& work, const std::string& field,
                                         uint64_t perReceiver) {
  if (!work) return ::testing::AssertionFailure() << "the run carries no work counts";
  const std::optional<uint64_t> total = work->total(field);
  if (!total) return ::testing::AssertionFailure() << "the build does not count '" << field << "'";
  if (work->receivers() == 0) return ::testing::AssertionFailure() << "no receiver was counted";
  if (*total != perReceiver * work->receivers())
    return ::testing::AssertionFailure() << field << ": " << *total << " over " << work->receivers()
                                         << " receivers, expected " << perReceiver << " each ("
                                         << perReceiver * work->receivers() << ")";
  return ::testing::AssertionSuccess();
}

std::optional<rt::WorkCounts> sceneWork(rt::VulkanContext& ctx, const std::string& label, const std::string& source,
                                        uint32_t screen) {
  const CompiledPasses* passes = countedBuild(label, source);
  if (!passes) return std::nullopt;
  return rt::runOnScene(ctx, *passes, sceneCase(ctx, "two_planes", kMap, screen, 4)).outputs.work;
}

TEST_F(WorkCountersTest, PcfGridAndPoissonReadTheirTapsAtEveryScreenSize) {
  for (const uint32_t screen : {64u, 128u}) {
    const auto grid = sceneWork(context(), "pcf_grid5x5", sampleSource("pcf_grid5x5"), screen);
    EXPECT_TRUE(countsExactly(grid, "depth_fetches", 25)) << "screen " << screen;
    EXPECT_TRUE(countsExactly(grid, "moment_bounds", 0)) << "screen " << screen;
    const auto poisson = sceneWork(context(), "pcf_poisson16", sampleSource("pcf_poisson16"), screen);
    EXPECT_TRUE(countsExactly(poisson, "depth_fetches", 16)) << "screen " << screen;
    ASSERT_TRUE(grid.has_value());
    EXPECT_GT(grid->receivers(), screen * screen / 8) << "two_planes fills the screen";
  }
}

// The footprint counter: one tap a receiver is one block switch a receiver (the first fetch
// always switches); a 5 x 5 grid inside 8 x 8 blocks, read row by row, switches at most twice a
// row (a 5-texel row spans at most two blocks, and the next row may start in the other one), so
// between 1 and 10 a receiver, and fewer than its 25 fetches.
TEST_F(WorkCountersTest, DepthBlockSwitchesFollowTheFootprint) {
  const std::string oneTap = "filter one_tap {\n    depth\n    kernel fixed(1)\n    sampling grid(1x1)\n}\n";
  const auto one = sceneWork(context(), "one_tap", oneTap, 64);
  EXPECT_TRUE(countsExactly(one, "depth_fetches", 1));
  EXPECT_TRUE(countsExactly(one, "depth_block_switches", 1));
  const auto grid = sceneWork(context(), "pcf_grid5x5", sampleSource("pcf_grid5x5"), 64);
  ASSERT_TRUE(grid && grid->receivers() > 0);
  const uint64_t switches = *grid->total("depth_block_switches");
  EXPECT_GE(switches, grid->receivers());
  EXPECT_LE(switches, 10 * grid->receivers());
  EXPECT_LT(switches, *grid->total("depth_fetches"));
  // The sibling: a one-tap closed form is not met by the grid.
  EXPECT_FALSE(countsExactly(grid, "depth_block_switches", 1));
}

TEST_F(WorkCountersTest, SiblingsAClosedFormOneTapOffAndNoReceiversFail) {
  const auto grid = sceneWork(context(), "pcf_grid5x5", sampleSource("pcf_grid5x5"), 64);
  EXPECT_FALSE(countsExactly(grid, "depth_fetches", 24));
  EXPECT_FALSE(countsExactly(grid, "no_such_counter", 0));
  rt::WorkCounts none = grid.value_or(rt::WorkCounts{});
  for (size_t k = 0; k < none.fields.size(); ++k) none.totals[k] = 0;
  EXPECT_FALSE(countsExactly(none, "depth_fetches", 0)) << "zero receivers must not pass as zero fetches";
  EXPECT_FALSE(countsExactly(std::nullopt, "depth_fetches", 25));
}

TEST_F(WorkCountersTest, APlainBuildCarriesNoCounts) {
  const CompiledFilter* plain = compileFilterCached("pcf_grid5x5", sampleSource("pcf_grid5x5"));
  ASSERT_NE(plain, nullptr);
  EXPECT_EQ(rt::workCounterBuffer(plain->passes.manifest), nullptr);
  EXPECT_FALSE(rt::runOnScene(context(), plain->passes, sceneCase(context(), "two_planes", kMap, 64, 4))
                   .outputs.work.has_value());
}

TEST_F(WorkCountersTest, VsmTakesOneMomentFetchAndOneBound) {
  const auto work = sceneWork(context(), "vsm_chebyshev", sampleSource("vsm_chebyshev"), 64);
  EXPECT_TRUE(countsExactly(work, "moment_fetches", 1));
  EXPECT_TRUE(countsExactly(work, "moment_bounds", 1));
  EXPECT_TRUE(countsExactly(work, "depth_fetches", 0));
}

TEST_F(WorkCountersTest, CountsAreTheSameInTwoRuns) {
  for (const char* sample : {"pcss_poisson", "vssm_uniform_kernel", "vssm_minmax_early_out", "layered_vsm_uniform"}) {
    const CompiledPasses* passes = countedBuild(sample, sampleSource(sample));
    ASSERT_NE(passes, nullptr) << sample;
    const rt::PreparedScene& scene = sceneCase(context(), "two_planes", kMap, 64, 4);
    const auto first = rt::runOnScene(context(), *passes, scene).outputs.work;
    rt::RunOptions timed;  // warm-up and timed runs before the counted one add nothing to it
    timed.warmup = 1;
    timed.runs = 2;
    const auto second = rt::runOnScene(context(), *passes, scene, timed).outputs.work;
    ASSERT_TRUE(first && second) << sample;
    EXPECT_GT(first->receivers(), 0u) << sample;
    EXPECT_EQ(first->totals, second->totals)
        << sample << ": " << rt::workFields(*first) << " vs " << rt::workFields(*second);
  }
}

// One crafted receiver on a crafted map (accuracy_harness.h: identity light view).
std::optional<rt::WorkCounts> receiverWork(rt::VulkanContext& ctx, const CompiledPasses& passes,
                                           const std::vector<float>& depth, const Receiver& receiver) {
  const CraftedGBuffer g = craftGBuffer({receiver}, 8, 8);
  return rt::runPasses(ctx, passes, craftedInputs(kMap, 8, 8, identityFrame(kMap, 8, 8, 0.5f), depth, g)).work;
}

std::vector<float> flatMap(float depth) { return std::vector<float>(size_t(kMap) * kMap, depth); }

// The left half of the map an occluder at 0.3, the right half empty (1: nothing rendered).
std::vector<float> edgeMap() {
  std::vector<float> d(size_t(kMap) * kMap, 1.0f);
  for (uint32_t y = 0; y < kMap; ++y)
    for (uint32_t x = 0; x < kMap / 2; ++x) d[size_t(y) * kMap + x] = 0.3f;
  return d;
}

TEST_F(WorkCountersTest, PcssReadsKernelTapsOnlyWhereTheSearchFoundABlocker) {
  const std::string source = withSetting(sampleSource("pcss_poisson"), "light", "area(size: scene)");
  const CompiledPasses* passes = countedBuild("pcss_poisson_counted", source);
  ASSERT_NE(passes, nullptr);
  const nlohmann::json& spec = passes->manifest.spec;
  const uint64_t search = spec["blocker"]["taps"].get<uint64_t>(), kernel = spec["sampling"]["taps"].get<uint64_t>();
  ASSERT_EQ(search, 16u);
  ASSERT_EQ(kernel, 32u);
  struct Case {
    const char* name;
    std::vector<float> map;
    Receiver receiver;
    uint64_t fetches, blockers;
  };
  const std::vector<Case> cases = {
      {"lit (in front of the occluder)", flatMap(0.3f), {0.5, 0.5, 0.2}, search, 0},
      {"umbra (behind a flat occluder)", flatMap(0.3f), {0.5, 0.5, 0.69}, search + kernel, 1},
      {"penumbra (at the occluder's edge)", edgeMap(), {0.5, 0.5, 0.69}, search + kernel, 1},
  };
  for (const Case& c : cases) {
    const auto work = receiverWork(context(), *passes, c.map, c.receiver);
    EXPECT_TRUE(countsExactly(work, "depth_fetches", c.fetches)) << c.name;
    EXPECT_TRUE(countsExactly(work, "blockers_found", c.blockers)) << c.name;
    EXPECT_TRUE(countsExactly(work, "receivers", 1)) << c.name;
  }
}

TEST_F(WorkCountersTest, VssmClassifiesTheBoxesOfItsUniformWalks) {
  const std::string source = withSetting(sampleSource("vssm_uniform_kernel"), "light", "area(size: scene)");
  const CompiledPasses* passes = countedBuild("vssm_uniform_kernel_counted", source);
  ASSERT_NE(passes, nullptr);
  const nlohmann::json& spec = passes->manifest.spec;
  const uint64_t m = spec["blocker"]["uniform_m"].get<uint64_t>(), n = spec["kernel"]["uniform_n"].get<uint64_t>();
  const auto lit = receiverWork(context(), *passes, flatMap(0.3f), {0.5, 0.5, 0.2});
  EXPECT_TRUE(countsExactly(lit, "kernel_boxes", 1)) << "a fully lit root ends the walk";
  EXPECT_TRUE(countsExactly(lit, "moment_bounds", 0));
  EXPECT_TRUE(countsExactly(lit, "blockers_found", 0));
  const auto umbra = receiverWork(context(), *passes, flatMap(0.3f), {0.5, 0.5, 0.69});
  EXPECT_TRUE(countsExactly(umbra, "kernel_boxes", (1 + m * m) + (1 + n * n)));
  EXPECT_TRUE(countsExactly(umbra, "moment_bounds", 2));
  EXPECT_TRUE(countsExactly(umbra, "depth_fetches", 0)) << "no sub-kernel is non-planar: no PCF fallback";
  EXPECT_TRUE(countsExactly(umbra, "blockers_found", 1));
}

}  // namespace
}  // namespace shadowc::test

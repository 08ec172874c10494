// The run harness (runtime/harness/run_harness.h) with a hand-written one-pass manifest: inputs
// go to the images with their roles, the visibility comes back exact, timing only when asked,
// the requested intermediate images are read back; a role without an input is one clear error.
// Interleaved timing (light_bench) gives each run its own rounds, and refuses what runPasses does.
#include "runtime/harness/run_harness.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gpu/gpu_test_util.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

using RunHarnessTest = VulkanTest;

constexpr uint32_t kSide = 19;  // map = screen side; not a multiple of the local size

// visibility = 1 - depth + shadowc_frameBlock.mapInfo.y (the frame reaches the pass too).
constexpr const char* kShade = R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1, r32f) readonly uniform image2D depth;
layout(set = 0, binding = 2, r32f) writeonly uniform image2D visibility;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(visibility)))) return;
  imageStore(visibility, p, vec4(1.0 - imageLoad(depth, p).r + shadowc_frameBlock.mapInfo.y));
}
)";

CompiledPasses onePass() {
  CompiledPasses c;
  ImageDesc depth{"depth", ImageFormat::R32F, {SizeDomain::Map, 0}, 1, 1, ImageRole::InputDepth, false};
  ImageDesc vis{"visibility", ImageFormat::R32F, {SizeDomain::Screen, 0}, 1, 1, ImageRole::OutputVisibility, false};
  c.manifest.filter = "harness_test";
  c.manifest.images = {depth, vis};
  Pass p;
  p.name = "shade";
  p.kind = "shade";
  p.spirv = "shade.spv";
  p.dispatch.size.domain = SizeDomain::Screen;
  p.bindings = {{0, "frame", Access::Uniform, -1},
                {1, "depth", Access::StorageRead, -1},
                {2, "visibility", Access::StorageWrite, -1}};
  c.manifest.passes = {p};
  c.files["shade.spv"] = computeSpirv("shade.spv", kShade);
  return c;
}

rt::RunInputs inputs() {
  rt::RunInputs in;
  in.frame.mapInfo[1] = 0.125f;
  in.mapSize = in.width = in.height = kSide;
  std::vector<float> d(kSide * kSide);
  for (uint32_t i = 0; i < d.size(); ++i) d[i] = float(i % 7) / 8.0f;
  in.lightDepth = rt::HostImage::fromFloats(kSide, kSide, ImageFormat::R32F, d);
  return in;  // no G-buffer: the manifest has no position/normal roles
}

TEST_F(RunHarnessTest, InputsByRoleVisibilityOutExact) {
  rt::RunOptions options;
  options.downloads = {"depth"};
  const rt::RunOutputs out = rt::runPasses(context(), onePass(), inputs(), options);
  ASSERT_EQ(out.visibility.size(), size_t(kSide) * kSide);
  for (uint32_t i = 0; i < out.visibility.size(); ++i)
    ASSERT_EQ(out.visibility[i], 1.0f - float(i % 7) / 8.0f + 0.125f) << "pixel " << i;
  EXPECT_FALSE(out.timing.has_value()) << "runs = 0: no timing";
  ASSERT_EQ(out.images.count("depth"), 1u);
  EXPECT_EQ(out.images.at("depth").texel(3, 0), 3.0f / 8.0f);
  EXPECT_GE(out.pipelineCreateMs, 0.0);
}

TEST_F(RunHarnessTest, TimedRunsReportEveryPass) {
  rt::RunOptions options;
  options.warmup = 1;
  options.runs = 3;
  const rt::RunOutputs out = rt::runPasses(context(), onePass(), inputs(), options);
  ASSERT_TRUE(out.timing.has_value());
  EXPECT_EQ(out.timing->runs, 3);
  ASSERT_EQ(out.timing->passes.size(), 1u);
  EXPECT_EQ(out.timing->passes[0].name, "shade");
  EXPECT_EQ(out.visibility[0], 1.125f);  // the last timed run leaves the output
  ASSERT_EQ(out.timing->runTotalsMs.size(), 3u);
  EXPECT_EQ(out.timing->totalMs, rt::median(out.timing->runTotalsMs));
}

TEST_F(RunHarnessTest, InterleavedTimingGivesEachRunItsRounds) {
  const CompiledPasses passes = onePass();
  const rt::RunInputs a = inputs();
  rt::RunInputs b = inputs();
  b.frame.mapInfo[1] = 0.5f;
  const std::vector<rt::TimingResult> t = rt::timeInterleaved(context(), {{&passes, &a}, {&passes, &b}}, 1, 5);
  ASSERT_EQ(t.size(), 2u);
  for (const rt::TimingResult& r : t) {
    EXPECT_EQ(r.warmup, 1);
    EXPECT_EQ(r.runs, 5);
    ASSERT_EQ(r.runTotalsMs.size(), 5u);
    for (double ms : r.runTotalsMs) EXPECT_GT(ms, 0.0);
    EXPECT_EQ(r.totalMs, rt::median(r.runTotalsMs));
    ASSERT_EQ(r.passes.size(), 1u);
    EXPECT_EQ(r.passes[0].name, "shade");
    EXPECT_LE(r.passes[0].minMs, r.passes[0].medianMs);
  }
}

TEST_F(RunHarnessTest, InterleavedTimingRefusesAMissingInputAndNoRounds) {
  const CompiledPasses passes = onePass();
  const rt::RunInputs a = inputs();
  rt::RunInputs missing = inputs();
  missing.lightDepth = {};
  try {
    rt::timeInterleaved(context(), {{&passes, &a}, {&passes, &missing}}, 0, 3);
    FAIL() << "expected an error for the second run's missing input_depth";
  } catch (const rt::ExecutorError& e) {
    EXPECT_NE(std::string(e.what()).find("no such input"), std::string::npos) << e.what();
  }
  EXPECT_THROW(rt::timeInterleaved(context(), {{&passes, &a}}, 0, 0), rt::ExecutorError);
}

TEST_F(RunHarnessTest, ARoleWithoutAnInputIsAnError) {
  rt::RunInputs in = inputs();
  in.lightDepth = {};
  try {
    rt::runPasses(context(), onePass(), in);
    FAIL() << "expected an error for the missing input_depth";
  } catch (const rt::ExecutorError& e) {
    EXPECT_NE(std::string(e.what()).find("'depth'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no such input"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace shadowc::test

// `light_samples N` (docs/dsl.md "light_samples") against the Embree reference, 256^2 screen,
// 1024^2 map, 16 x 16 reference samples: the views are a midpoint rule over the light of the
// reference's own integrand, so
//  1. on large_penumbra (a 4-unit light 2 units over a thick box: no single-map filter reaches
//     0.02, docs/accuracy.md) the RMSE falls at every step N = 1, 4, 16, 64, and at 64 it meets
//     0.02, the bound the language's best filter of any kind must meet there;
//  2. the sibling: on lamp_table (a light as wide as its height over the tray, where the form
//     factor varies 2.5x across the light) the same 64 views counted uniformly (`weights
//     uniform`, the visible fraction of the light) miss 0.02 while the weighted ones meet it: the
//     bound tells the two estimators apart.
#include <gtest/gtest.h>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

using LightSamplesTest = VulkanTest;

constexpr uint32_t kScreen = 256, kMap = 1024;
constexpr int kReference = 16;
constexpr double kBound = 0.02;

rt::Metrics runViews(rt::VulkanContext& ctx, const std::string& scene, int views, const std::string& weights) {
  const std::string label = fmt::format("light_samples{}_{}", views, weights);
  const std::string source = withSetting(
      withSetting(sampleSource("light_samples64"), "light_samples", std::to_string(views)), "weights", weights);
  const CompiledFilter* cf = compileFilterCached(label, source);
  EXPECT_NE(cf, nullptr) << label;
  if (!cf) return {};
  const auto prepared = sceneCaseFor(ctx, scene, kMap, kScreen, kReference, cf->passes);
  EXPECT_EQ(prepared->setup.lightSampleViewProj.size(), size_t(views));
  const rt::Metrics m = rt::runOnScene(ctx, cf->passes, *prepared).metrics;
  EXPECT_GT(m.compared, kScreen * kScreen / 8) << "too few geometry pixels";
  EXPECT_EQ(m.nonFinite, 0u) << label;
  EXPECT_EQ(m.outOfRange, 0u) << label;
  return m;
}

TEST_F(LightSamplesTest, RmseFallsAsTheViewsGrowAndMeetsTheBound) {
  double previous = 1.0;
  for (int n : {1, 4, 16, 64}) {
    const double rmse = runViews(context(), "large_penumbra", n, "form_factor").rmse;
    RecordProperty("rmse_" + std::to_string(n), std::to_string(rmse));
    EXPECT_LT(rmse, previous) << n << " views";
    previous = rmse;
  }
  EXPECT_LE(previous, kBound) << "64 views on large_penumbra";
}

TEST_F(LightSamplesTest, UniformlyCountedViewsMissTheBoundTheWeightedMeet) {
  const double weighted = runViews(context(), "lamp_table", 64, "form_factor").rmse;
  const double uniform = runViews(context(), "lamp_table", 64, "uniform").rmse;
  EXPECT_LE(weighted, kBound);
  EXPECT_GT(uniform, kBound);
}

}  // namespace
}  // namespace shadowc::test

// Acne on the real-mesh scenes at the accuracy settings (256^2 screen, 1024^2 map, 16x16 reference
// samples, cached in the build dir): acne = `over_darkening`, the fraction of the pixels whose
// reference is > 0.95 that the filter darkens below 0.8; the bound is 0.005. Each check has
// a sibling that breaks the same bound on the same scene (numbers measured with `shadowc validate`
// at the same settings; docs/accuracy.md "Bias").
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

constexpr uint32_t kScreen = 256, kMap = 1024;
constexpr int kSamples = 16;
constexpr double kAcneBound = 0.005;

using MeshAcneTest = VulkanTest;

// `sample` with its bias line replaced by `bias` (accuracy_harness.h); the sample must have one.
std::string replacedBias(const std::string& sample, const std::string& bias) {
  EXPECT_TRUE(std::regex_search(sampleSource(sample), std::regex(R"(\n\s*bias\s[^\n]*)"))) << sample;
  return withBias(sample, bias);
}

rt::Metrics run(const std::string& label, const std::string& source, const std::string& scene) {
  return runOnBuiltinScene(VulkanTest::context(), label, source, scene, kMap, kScreen, kSamples);
}

// pcss_poisson's receiver plane with its slope clamped at 20 instead of the default 50: duck acne
// 0.0052 with 50 (the sibling), measured 0.0039 now. The 3-degree grazing floor (slope 19) stays
// inside the clamp: ReceiverPlaneBiasTest covers it with the default.
// The RMSE bound is the sibling's own RMSE (0.0907 with the clamp at 50; 0.0898 measured with 20):
// the clamp was adopted because it removes acne without costing accuracy, so the check is that
// comparison on the same scene and settings, not a margin on a number.
TEST_F(MeshAcneTest, PcssSampleKeepsTheDuckUnderTheAcneBoundAtIssueSettings) {
  const std::string sample = sampleSource("pcss_poisson");
  ASSERT_NE(sample.find("max_slope: 20"), std::string::npos);
  const rt::Metrics m = run("pcss_poisson", sample, "duck");
  const rt::Metrics clamp50 = run(
      "pcss_duck_slope50", replacedBias("pcss_poisson", "receiver_plane(constant: 0.001, normal_offset: 2)"), "duck");
  fmt::print("duck: max_slope 20 acne {:.4f} RMSE {:.4f}; 50 acne {:.4f} RMSE {:.4f}\n", m.overDarkening, m.rmse,
             clamp50.overDarkening, clamp50.rmse);
  EXPECT_LE(m.overDarkening, kAcneBound);
  EXPECT_LE(m.rmse, clamp50.rmse);
  EXPECT_GT(clamp50.overDarkening, kAcneBound);
}

// pcf_poisson16's slope bias with its floor at 0.004: spider acne 0.0052 with the former 0.002
// (the sibling), measured 0.0043 now.
TEST_F(MeshAcneTest, PcfSampleKeepsTheSpiderUnderTheAcneBoundAtIssueSettings) {
  const std::string sample = sampleSource("pcf_poisson16");
  ASSERT_NE(sample.find("slope(0.05, constant: 0.004)"), std::string::npos);
  EXPECT_LE(run("pcf_poisson16", sample, "spider").overDarkening, kAcneBound);
  EXPECT_GT(
      run("pcf_spider_c002", replacedBias("pcf_poisson16", "slope(0.05, constant: 0.002)"), "spider").overDarkening,
      kAcneBound);
}

}  // namespace
}  // namespace shadowc::test

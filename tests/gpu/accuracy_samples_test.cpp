// Every sample filter of samples/filters/ on three (or four; four samples also on the real-mesh
// scenes duck, spider, engine) built-in scenes against the Embree
// ground truth: per technique and scene, bounds on RMSE and on the light-bleeding fraction, and
// no NaN/Inf or out-of-range visibility. Small sizes keep it fast: 128^2 screen, 512^2 map, 8x8
// reference light samples (cached under the build dir). The bounds are the measured values
// x 1.5 + 0.01 (RMSE) and x 1.5 + 0.005 (bleeding); docs/accuracy.md lists both.
// Samples whose light size is folded into the shader are compared as a copy with
// `size: scene` (the reference traces the scene's light, so a different folded size would
// measure the mismatch, not the filter). Every sample is compiled at -O: on lavapipe -O0 made
// the quadtree samples slower overall (47 s vs 38 s for the suite), the JIT pays for it.
// SHADOWC_ACCURACY_REPORT=1 prints one markdown row per case (how docs/accuracy.md is made).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

constexpr uint32_t kScreen = 128, kMap = 512;
constexpr int kSamples = 8;

struct SceneBound {
  const char* scene;
  double rmse;      // bound
  double bleeding;  // bound on the light-bleeding fraction
};
struct SampleCase {
  const char* sample;
  const char* replaceFrom = nullptr;  // light line rewritten to `size: scene`
  const char* replaceTo = nullptr;
  bool optimize = true;
  std::vector<SceneBound> scenes;
};

// Readable ctest names ("GetParam() = vssm_contact" instead of a byte dump).
void PrintTo(const SampleCase& c, std::ostream* os) { *os << c.sample; }

std::string caseSource(const SampleCase& c) {
  std::string text = sampleSource(c.sample);
  if (c.replaceFrom) {
    const size_t at = text.find(c.replaceFrom);
    if (at == std::string::npos)
      ADD_FAILURE() << c.sample << ": '" << c.replaceFrom << "' not found";
    else
      text.replace(at, std::string(c.replaceFrom).size(), c.replaceTo);
  }
  return text;
}

// clang-format off
const std::vector<SampleCase>& cases() {
  static const std::vector<SampleCase> all = {
#include "gpu/accuracy_bounds.inc"
  };
  return all;
}
// clang-format on

class AccuracyTest : public VulkanTest, public ::testing::WithParamInterface<SampleCase> {};

TEST_P(AccuracyTest, AgainstEmbreeReference) {
  const SampleCase& c = GetParam();
  const bool report = std::getenv("SHADOWC_ACCURACY_REPORT") != nullptr;
  const CompiledFilter* cf = compileFilterCached(c.sample, caseSource(c), c.optimize);
  ASSERT_NE(cf, nullptr);
  ASSERT_TRUE(cf->spec.light.sizeFromScene || cf->spec.light.shape == LightShape::Point)
      << c.sample << " folds its light size: compare a copy with size: scene";
  for (const SceneBound& b : c.scenes) {
    SCOPED_TRACE(b.scene);
    const rt::PreparedScene& sc = sceneCase(context(), b.scene, kMap, kScreen, kSamples);
    const rt::Metrics m = rt::runOnScene(context(), cf->passes, sc).metrics;
    ASSERT_GT(m.compared, kScreen * kScreen / 8) << "too few geometry pixels";
    EXPECT_EQ(m.nonFinite, 0u);
    EXPECT_EQ(m.outOfRange, 0u);
    EXPECT_LE(m.rmse, b.rmse) << "bleeding " << m.lightBleeding;
    EXPECT_LE(m.lightBleeding, b.bleeding) << "rmse " << m.rmse;
    if (report)
      fmt::print("| {} | {} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.3f} |\n", c.sample, b.scene, m.rmse, b.rmse,
                 m.lightBleeding, b.bleeding, m.maxAbsError);
  }
}

std::string caseName(const ::testing::TestParamInfo<SampleCase>& info) { return info.param.sample; }

INSTANTIATE_TEST_SUITE_P(Samples, AccuracyTest, ::testing::ValuesIn(cases()), caseName);

// Sibling: the bounds discriminate. PCSS on two_planes is close to exact; the same result with
// its penumbra hardened (v rounded to 0/1) or darkened must break the PCSS bound.
TEST_F(VulkanTest, AccuracyBoundsRejectAWrongResult) {
  const SampleCase* pcss = nullptr;
  for (const auto& c : cases())
    if (std::string(c.sample) == "pcss_poisson") pcss = &c;
  ASSERT_NE(pcss, nullptr);
  const CompiledFilter* cf = compileFilterCached(pcss->sample, caseSource(*pcss), pcss->optimize);
  ASSERT_NE(cf, nullptr);
  const rt::PreparedScene& sc = sceneCase(context(), "two_planes", kMap, kScreen, kSamples);
  const rt::SceneRunResult run = rt::runOnScene(context(), cf->passes, sc);
  const double bound = pcss->scenes[0].rmse;
  ASSERT_STREQ(pcss->scenes[0].scene, "two_planes");
  EXPECT_LE(run.metrics.rmse, bound);
  const std::vector<float>& result = run.outputs.visibility;
  std::vector<float> hard = result, dark = result;
  for (float& v : hard) v = v < 0.5f ? 0.0f : 1.0f;
  for (float& v : dark) v = v < 1.0f ? 0.5f * v : v;
  EXPECT_GT(rt::computeMetrics(hard, sc.reference, sc.mask).rmse, bound);
  EXPECT_GT(rt::computeMetrics(dark, sc.reference, sc.mask).rmse, bound);
}

// Every sample in samples/filters/ has a case (a new sample must get bounds).
TEST(AccuracyCoverage, EverySampleHasACase) {
  std::vector<std::string> missing;
  for (const auto& entry : std::filesystem::directory_iterator(sourceDir() / "samples" / "filters")) {
    if (entry.path().extension() != ".shadow") continue;
    bool found = false;
    for (const auto& c : cases()) found = found || entry.path().stem() == c.sample;
    if (!found) missing.push_back(entry.path().stem().string());
  }
  std::string all;
  for (const auto& m : missing) all += " " + m;
  EXPECT_TRUE(missing.empty()) << "samples without accuracy bounds:" << all;
}

}  // namespace
}  // namespace shadowc::test

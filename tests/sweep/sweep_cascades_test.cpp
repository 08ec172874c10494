// `sweep` runs cascaded sun filters: each case's scene is prepared once, and again per
// cascade configuration a variant's manifest asks for (rt::prepareSceneForFilter: the atlas of
// cascades fitted to the camera, the reference shared). The rows must be what
// tests/gpu/cascades_test.cpp measures for the same filters, sizes and scene: sun_outdoor_long at
// screen 512, a 2048^2 atlas of 4 cascades, a 16^2 reference (there: 4 cascades 0.0918 vs one
// 2048^2 map 0.1010), measured here the way that test does (prepareScene with the manifest's
// cascades, runOnScene) and compared within kTolerance. Siblings: the one-map row and the
// `blend: 0` row are not within kTolerance of the cascaded measurement (the check tells cascade
// configurations apart), and the cascaded filter on the scene prepared without cascades is
// refused with runOnScene's mismatch message (what a sweep gave before).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "driver/driver.h"
#include "runtime/harness/scene_run.h"
#include "runtime/scene/cascade_setup.h"
#include "runtime/vulkan/vulkan_context.h"
#include "support/test_support.h"
#include "sweep/sweep_run.h"
#include "sweep/sweep_spec.h"

namespace shadowc {
namespace {

constexpr uint32_t kScreen = 512, kMap = 2048;
constexpr int kSamples = 16;
// lavapipe runs the same SPIR-V on the same inputs the same way; the rest is float summation
// order in the metrics.
constexpr double kTolerance = 1e-4;

// cascades_test.cpp's filter: pcss_poisson as a sun with a 1.5-texel normal offset.
std::string sunPcssSet(const std::string& cascades) {
  std::string set = R"J("light": "sun(angle: scene)", "bias": "normal_offset(1.5, constant: 0.0002)")J";
  if (!cascades.empty()) set += R"J(, "cascades": ")J" + cascades + "\"";
  return "{" + set + "}";
}

std::string sweepJson() {
  const std::string f = (test::sourceDir() / "samples/filters/pcss_poisson.shadow").string();
  auto filter = [&](const std::string& name, const std::string& cascades) {
    return R"J({"name": ")J" + name + R"J(", "file": ")J" + f + R"J(", "set": )J" + sunPcssSet(cascades) + "}";
  };
  return R"J({"name": "cascades", "filters": [)J" + filter("cascades4", "practical(4, lambda: 0.5, blend: 0.1)") +
         ", " + filter("cascades4_noblend", "practical(4, blend: 0)") + ", " + filter("single", "") +
         R"J(], "scenes": ["sun_outdoor_long"], "screen": 512, "map": 2048, "reference_samples": 16, "runs": 1,
  "warmup": 0})J";
}

const sweep::Row* rowOf(const sweep::Results& r, const std::string& base) {
  for (const sweep::Row& row : r.rows)
    if (row.base == base) return &row;
  return nullptr;
}

TEST(SweepCascades, CascadedRowsMatchTheHarnessMeasurement) {
  const auto dir = test::freshTempDir("sweep-cascades");
  // The reference cache the GPU tests use (next to the binary), so cascades_test's trace is reused.
  setenv("SHADOWC_CACHE_DIR",
         (std::filesystem::path(test::shadowcBinary()).parent_path() / "accuracy-reference-cache").c_str(), 1);
  const sweep::SweepSpec spec = sweep::parseSweepSpec(sweepJson(), "cascades.json", dir);
  sweep::SweepOptions o;
  o.outDir = dir / "out";
  o.jobs = 2;
  o.tty = 0;
  const sweep::SweepOutcome out = sweep::runSweep(spec, o, stderr);
  for (const sweep::Skipped& s : out.results.skipped) ADD_FAILURE() << s.variant << ": " << s.message;
  const sweep::Row* cascaded = rowOf(out.results, "cascades4");
  const sweep::Row* noblend = rowOf(out.results, "cascades4_noblend");
  const sweep::Row* single = rowOf(out.results, "single");
  ASSERT_TRUE(cascaded && noblend && single);
  EXPECT_EQ(cascaded->spec["cascades"]["count"], 4);

  // cascades_test.cpp's measurement of the cascaded filter: compiled, the scene prepared with its
  // manifest's cascades, run through the harness.
  driver::Options dopt;
  const driver::Result compiled = driver::compileSource(cascaded->filterText, "cascades4", dopt);
  ASSERT_TRUE(compiled.ok && compiled.artifact) << compiled.log;
  const CompiledPasses passes = compiled.artifact->passes();
  rt::VulkanContext ctx;
  rt::SceneSettings s;
  s.scene = "sun_outdoor_long";
  s.screen = kScreen;
  s.map = kMap;
  s.referenceSamples = kSamples;
  s.cascades = rt::cascadeConfigFromSpec(passes.manifest.spec);
  const auto scene = rt::prepareScene(ctx, s);
  ASSERT_EQ(scene->setup.cascadeCount, 4);
  const double direct = rt::runOnScene(ctx, passes, *scene).metrics.rmse;
  fmt::print(
      "sun_outdoor_long {}^2, atlas {}^2: sweep rows 4 cascades {:.4f}, blend 0 {:.4f}, one map {:.4f}; "
      "harness {:.4f}\n",
      kScreen, kMap, cascaded->metrics.rmse, noblend->metrics.rmse, single->metrics.rmse, direct);
  EXPECT_NEAR(cascaded->metrics.rmse, direct, kTolerance);
  // cascades_test's bound: 4 cascades within 1.5x of one map of the same texel count.
  EXPECT_LE(cascaded->metrics.rmse, 1.5 * single->metrics.rmse);
  // Siblings: other cascade configurations measure outside the tolerance.
  EXPECT_GT(std::abs(single->metrics.rmse - direct), kTolerance);
  EXPECT_GT(std::abs(noblend->metrics.rmse - direct), kTolerance);

  // Sibling: the scene prepared without the cascades is refused, naming them.
  rt::SceneSettings plain = s;
  plain.cascades = {};
  const auto bare = rt::prepareScene(ctx, plain);
  try {
    rt::runOnScene(ctx, passes, *bare);
    ADD_FAILURE() << "a cascaded filter ran on a scene prepared without cascades";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("has 4 cascades"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace shadowc

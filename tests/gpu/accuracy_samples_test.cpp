// Every sample filter of samples/filters/ on three (or four; four samples also on the real-mesh
// scenes duck, spider, engine) built-in scenes against the Embree
// ground truth: per technique and scene, bounds on RMSE and on the light-bleeding fraction, and
// no NaN/Inf or out-of-range visibility. Small sizes keep it fast: 128^2 screen, 512^2 map, 8x8
// reference light samples (cached under the build dir).
// This is a golden test: each measurement is held to its row of the measured table
// gpu/accuracy_measured.inc to 1e-5 (the measurements are deterministic), which
// `scripts/accuracy_report.py --only bounds` writes from this test's own report mode
// (SHADOWC_ACCURACY_REPORT=1 prints one row per case) together with the table of docs/accuracy.md;
// review a change of the table as a golden file's diff. The bounds (boundOf, one formula of the
// table) are what docs/accuracy.md publishes; while the table is current the golden match implies
// them, so they are checked here only as the published limit a regenerated table must not pass
// unnoticed (the sibling below shows they discriminate).
// Samples whose light size is folded into the shader are compared as a copy with
// `size: scene` (the reference traces the scene's light, so a different folded size would
// measure the mismatch, not the filter). Every sample is compiled at -O: on lavapipe -O0 made
// the quadtree samples slower overall (47 s vs 38 s for the suite), the JIT pays for it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

constexpr uint32_t kScreen = 128, kMap = 512;
constexpr int kSamples = 8;

struct SampleCase {
  const char* sample;
  const char* replaceFrom = nullptr;  // light line rewritten to `size: scene`
  const char* replaceTo = nullptr;
  bool optimize = true;
  std::vector<const char*> scenes;
};

// One row of the measured table: RMSE and light-bleeding fraction of a sample on a scene.
struct Measured {
  const char* sample;
  const char* scene;
  double rmse, bleeding;
};

// The one bound formula, for both metrics: the measurement plus 10 % of it plus 0.002. The
// measurements are deterministic (lavapipe, a cached reference; the table check below holds them to
// 1e-5), so the margin is not noise: it is how much worse a row may become before it breaks its
// bound (10 % of its error; 0.002 where the error is near 0, about 20 of the ~10^4 geometry pixels
// for the bleeding fraction). Every bound it gives is tighter than the one this test held before
// the table was generated (the closest: pcss_grid_search on large_penumbra, 0.1636 for 0.2).
constexpr double kRelative = 0.1, kAbsolute = 0.002;
constexpr double boundOf(double measured) { return measured * (1 + kRelative) + kAbsolute; }

// A measurement equals its table row to the table's printed precision (5 decimals).
constexpr double kTableTolerance = 1e-5;

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
    {"hard_constant_bias", nullptr, nullptr, true, {"small_penumbra", "two_planes", "contact"}},
    {"hard_normal_offset_bias", nullptr, nullptr, true, {"small_penumbra", "two_planes", "contact"}},
    {"hard_slope_bias", nullptr, nullptr, true, {"small_penumbra", "two_planes", "contact"}},
    {"pcf_bilinear3x3", nullptr, nullptr, true, {"small_penumbra", "two_planes", "contact"}},
    {"pcf_grid5x5", nullptr, nullptr, true, {"small_penumbra", "two_planes", "contact"}},
    {"pcf_poisson16", nullptr, nullptr, true, {"small_penumbra", "two_planes", "contact", "duck", "spider", "engine"}},
    {"pcss_grid_search", "disk(size: 0.05)", "area(size: scene)", true, {"two_planes", "contact", "overlapping_occluders", "large_penumbra"}},
    {"pcss_poisson", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders", "large_penumbra", "duck", "spider", "engine"}},
    {"vsm_chebyshev", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"vsm_blur_mips_bleeding", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"vsm_fp16", "area(size: 0.05)", "area(size: scene)", true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"esm", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"evsm2", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"evsm4", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"power_cdf", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"power_cdf_layered", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"layered_vsm_uniform", nullptr, nullptr, true, {"two_planes", "stacked_planes", "overlapping_occluders"}},
    {"layered_vsm_explicit", nullptr, nullptr, true, {"two_planes", "stacked_planes", "overlapping_occluders"}},
    {"layered_vsm_lloyd", nullptr, nullptr, true, {"two_planes", "stacked_planes", "overlapping_occluders"}},
    {"sat_fp32_naive", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders"}},
    {"vssm_int32_sat", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders", "large_penumbra", "duck", "spider", "engine"}},
    {"vssm_fp32_centered_sat", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders"}},
    {"vssm_uniform_kernel", "area(size: 0.04)", "area(size: scene)", true, {"two_planes", "contact", "overlapping_occluders"}},
    {"vssm_adaptive", "area(size: 0.04)", "area(size: scene)", true, {"two_planes", "contact", "overlapping_occluders"}},
    {"vssm_blocker_quadtree", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders"}},
    {"vssm_contact", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders"}},
    {"vssm_minmax_early_out", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders"}},
    {"vssm_pcf_fallback", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders", "duck", "spider", "engine"}},
    {"vssm_form_factor", nullptr, nullptr, true, {"large_penumbra", "lamp_table", "two_planes", "duck"}},
    {"light_samples16", nullptr, nullptr, true, {"large_penumbra", "lamp_table", "two_planes", "duck"}},
    {"light_samples64", nullptr, nullptr, true, {"large_penumbra", "lamp_table", "two_planes", "duck"}},
    {"vssm_quadtree_table", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders"}},
    {"vssm_quadtree_unrolled", nullptr, nullptr, true, {"two_planes", "contact", "overlapping_occluders"}},
    {"msm_plain", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"msm_blur", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra", "overlapping_occluders"}},
    {"msm_unorm16", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra"}},
    {"msm_sat_int32", nullptr, nullptr, true, {"two_planes", "stacked_planes", "small_penumbra", "overlapping_occluders"}},
  };
  return all;
}

// Generated by scripts/accuracy_report.py --only bounds; never edited by hand.
const std::vector<Measured>& measuredTable() {
  static const std::vector<Measured> table = {
#include "gpu/accuracy_measured.inc"
  };
  return table;
}
// clang-format on

const Measured* measured(const std::string& sample, const std::string& scene) {
  for (const Measured& m : measuredTable())
    if (sample == m.sample && scene == m.scene) return &m;
  return nullptr;
}

class AccuracyTest : public VulkanTest, public ::testing::WithParamInterface<SampleCase> {};

TEST_P(AccuracyTest, AgainstEmbreeReference) {
  const SampleCase& c = GetParam();
  const bool report = std::getenv("SHADOWC_ACCURACY_REPORT") != nullptr;
  const CompiledFilter* cf = compileFilterCached(c.sample, caseSource(c), c.optimize);
  ASSERT_NE(cf, nullptr);
  ASSERT_TRUE(cf->spec.light.sizeFromScene || cf->spec.light.shape == LightShape::Point)
      << c.sample << " folds its light size: compare a copy with size: scene";
  for (const char* scene : c.scenes) {
    SCOPED_TRACE(scene);
    const auto sc = sceneCaseFor(context(), scene, kMap, kScreen, kSamples, cf->passes);
    const rt::Metrics m = rt::runOnScene(context(), cf->passes, *sc).metrics;
    ASSERT_GT(m.compared, kScreen * kScreen / 8) << "too few geometry pixels";
    EXPECT_EQ(m.nonFinite, 0u);
    EXPECT_EQ(m.outOfRange, 0u);
    if (report)
      fmt::print("ACCURACY_ROW\t{}{}\t{}\t{:.5f}\t{:.4f}\t{:.5f}\t{:.4f}\t{:.3f}\n", c.sample,
                 c.replaceFrom ? " (size: scene copy)" : "", scene, m.rmse, boundOf(m.rmse), m.lightBleeding,
                 boundOf(m.lightBleeding), m.maxAbsError);
    const Measured* t = measured(c.sample, scene);
    if (!t) {
      ADD_FAILURE() << c.sample << " on " << scene
                    << " is not in the measured table: scripts/accuracy_report.py --only bounds";
      continue;
    }
    // The golden: the table is this measurement (rerun scripts/accuracy_report.py --only bounds after
    // a change that moves it, and review the diff of the table as a golden file's).
    EXPECT_NEAR(m.rmse, t->rmse, kTableTolerance) << "golden mismatch: stale measured table";
    EXPECT_NEAR(m.lightBleeding, t->bleeding, kTableTolerance) << "golden mismatch: stale measured table";
    // The published limit (implied by the golden above while the table is current).
    EXPECT_LE(m.rmse, boundOf(t->rmse)) << "bleeding " << m.lightBleeding;
    EXPECT_LE(m.lightBleeding, boundOf(t->bleeding)) << "rmse " << m.rmse;
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
  ASSERT_STREQ(pcss->scenes[0], "two_planes");
  const Measured* t = measured("pcss_poisson", "two_planes");
  ASSERT_NE(t, nullptr);
  const double bound = boundOf(t->rmse);
  EXPECT_LE(run.metrics.rmse, bound);
  const std::vector<float>& result = run.outputs.visibility;
  std::vector<float> hard = result, dark = result;
  for (float& v : hard) v = v < 0.5f ? 0.0f : 1.0f;
  for (float& v : dark) v = v < 1.0f ? 0.5f * v : v;
  EXPECT_GT(rt::computeMetrics(hard, sc.reference, sc.mask).rmse, bound);
  EXPECT_GT(rt::computeMetrics(dark, sc.reference, sc.mask).rmse, bound);
}

// Moment shadow maps bleed less than plain VSM where two occluders overlap (Peters & Klein 2015
// sec. 3; lauritzen2008 Fig. 2): on stacked_planes, the mean visibility over the pixels the
// reference puts in umbra (< 0.05), both with the same gaussian(2) prefilter and fp32 storage.
double umbraLeak(const std::vector<float>& result, const rt::PreparedScene& sc) {
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < result.size(); ++i)
    if (sc.mask[i] && sc.reference[i] < 0.05f) sum += result[i], ++n;
  return n ? sum / double(n) : 0.0;
}

TEST_F(VulkanTest, MsmBleedsLessThanVsmOnStackedPlanes) {
  const rt::PreparedScene& sc = sceneCase(context(), "stacked_planes", kMap, kScreen, kSamples);
  double leak[2] = {0, 0};
  const char* names[2] = {"vsm_chebyshev", "msm_blur"};
  for (int i = 0; i < 2; ++i) {
    const CompiledFilter* cf = compileFilterCached(names[i], sampleSource(names[i]));
    ASSERT_NE(cf, nullptr);
    ASSERT_EQ(cf->spec.prefilter.blur, BlurKind::Gaussian);
    ASSERT_EQ(cf->spec.prefilter.blurRadius, 2);
    leak[i] = umbraLeak(rt::runOnScene(context(), cf->passes, sc).outputs.visibility, sc);
  }
  fmt::print("stacked_planes umbra leak: vsm_chebyshev {:.5f}, msm_blur {:.5f}\n", leak[0], leak[1]);
  EXPECT_GT(leak[0], 1e-3);  // not vacuous: VSM does leak here
  EXPECT_LT(leak[1], 0.5 * leak[0]);
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

// The table and the cases agree both ways: every case's scene has a row, every row a case (a row
// left behind by a removed case would be a bound on nothing).
TEST(AccuracyCoverage, TheMeasuredTableHoldsExactlyTheCases) {
  size_t rows = 0;
  for (const auto& c : cases())
    for (const char* scene : c.scenes) {
      ++rows;
      EXPECT_NE(measured(c.sample, scene), nullptr) << c.sample << " on " << scene;
    }
  EXPECT_EQ(measuredTable().size(), rows);
}

// docs/accuracy.md's generated bounds table is this table under this formula: a bound edited there
// (or a row edited here) fails. Its rows: | sample | scene | RMSE | RMSE bound | bleeding | bleeding
// bound | max abs error |, the measurements to 5 decimals and the bounds to 4. A docs bound is the
// formula of the unrounded measurement rounded to 4 decimals, the table's row is rounded to 5, so
// they agree to 5e-5 + (1 + kRelative) 5e-6.
constexpr double kDocsBoundTolerance = 5e-5 + (1 + kRelative) * 5e-6 + 1e-9;
TEST(AccuracyCoverage, TheDocsBoundsAreTheFormulaOfTheTable) {
  const std::string doc = readFile(sourceDir() / "docs" / "accuracy.md");
  const std::string begin = "<!-- generated by: scripts/accuracy_report.py --only bounds -->";
  const size_t from = doc.find(begin), to = doc.find("<!-- end generated: accuracy_bounds -->");
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  std::istringstream lines(doc.substr(from, to - from));
  const std::regex row(
      R"(^\| (\w+)(?: \(size: scene copy\))? \| (\w+) \| ([0-9.]+) \| ([0-9.]+) \| ([0-9.]+) \| ([0-9.]+) \|)");
  size_t seen = 0;
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    ++seen;
    const Measured* t = measured(m[1].str(), m[2].str());
    ASSERT_NE(t, nullptr) << line;
    EXPECT_NEAR(std::stod(m[3].str()), t->rmse, 5e-6) << line;
    EXPECT_NEAR(std::stod(m[4].str()), boundOf(t->rmse), kDocsBoundTolerance) << line;
    EXPECT_NEAR(std::stod(m[5].str()), t->bleeding, 5e-6) << line;
    EXPECT_NEAR(std::stod(m[6].str()), boundOf(t->bleeding), kDocsBoundTolerance) << line;
  }
  EXPECT_EQ(seen, measuredTable().size());
}

}  // namespace
}  // namespace shadowc::test

// Every sample filter loads with zero errors, and zero warnings unless the sample says it is
// meant to warn (a "# expect: Wxxxx at L:C" directive, as in the negative tests).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "spec/load_filter.h"
#include "support/test_support.h"

namespace fs = std::filesystem;
using namespace shadowc;

namespace {
std::vector<std::string> samples() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(test::sourceDir() / "samples/filters"))
    if (e.path().extension() == ".shadow") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class Sample : public ::testing::TestWithParam<std::string> {};

TEST_P(Sample, LoadsCleanly) {
  const fs::path path = test::sourceDir() / "samples/filters" / (GetParam() + ".shadow");
  const std::string text = test::readFile(path);
  const LoadResult r = loadFilterFile(path.string());
  EXPECT_EQ(r.errorCount(), 0) << formatDiagnostics(r);
  ASSERT_TRUE(r.spec.has_value());
  EXPECT_EQ(r.spec->name, GetParam()) << "the filter is named after its file";
  EXPECT_EQ(text.rfind("#", 0), 0u) << "every sample starts with a comment saying what it is";
  // Normalization's contract: layers+1 split boundaries from 0 to 1, so nobody downstream
  // needs a fallback (planner, lookup, stability reference read spec.moments.splits).
  const std::vector<double>& splits = r.spec->moments.splits;
  ASSERT_EQ(splits.size(), static_cast<size_t>(r.spec->moments.layers + 1));
  EXPECT_EQ(splits.front(), 0.0);
  EXPECT_EQ(splits.back(), 1.0);
  std::smatch m;
  if (std::regex_search(text, m, std::regex(R"(# expect: (W\d{4}) at (\d+):(\d+))"))) {
    ASSERT_EQ(r.warningCount(), 1) << formatDiagnostics(r);
    EXPECT_EQ(r.diagnostics[0].code, m[1].str());
    EXPECT_EQ(r.diagnostics[0].location.line, std::stoi(m[2]));
    EXPECT_EQ(r.diagnostics[0].location.column, std::stoi(m[3]));
  } else {
    EXPECT_EQ(r.warningCount(), 0) << formatDiagnostics(r);
  }
  // Checking the normalized spec again through JSON is stable: same text, same bytes.
  const LoadResult again = loadFilterSource(text, path.string());
  ASSERT_TRUE(again.spec.has_value());
  EXPECT_EQ(specToJson(*r.spec).dump(), specToJson(*again.spec).dump());
}

INSTANTIATE_TEST_SUITE_P(Files, Sample, ::testing::ValuesIn(samples()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(Samples, AtLeast22AndTheDesignExample) {
  const auto names = samples();
  EXPECT_GE(names.size(), 22u);
  EXPECT_NE(std::find(names.begin(), names.end(), "vssm_adaptive"), names.end());
}

TEST(Samples, DesignExampleIsVerbatim) {
  // docs/dsl.md's example must stay valid as written there.
  const std::string design = test::readFile(test::sourceDir() / "samples/filters/vssm_adaptive.shadow");
  EXPECT_NE(design.find("kernel     quadtree(height: 3)"), std::string::npos);
  const LoadResult r = loadFilterSource(design, "vssm_adaptive.shadow");
  ASSERT_TRUE(r.spec);
  EXPECT_EQ(r.spec->kernel.subdivision, Subdivision::Quadtree);
  EXPECT_EQ(r.spec->storage.sat, SatKind::Int32);
  EXPECT_EQ(r.spec->blocker.kind, BlockerKind::Moments);
  EXPECT_TRUE(r.spec->fallback.pcf);
  EXPECT_TRUE(r.spec->contact.enabled);
  EXPECT_TRUE(r.spec->earlyOutMinMax);
  EXPECT_DOUBLE_EQ(r.spec->moments.bleedingReduction, 0.2);
  EXPECT_DOUBLE_EQ(r.spec->light.size, 0.04);
}
}  // namespace

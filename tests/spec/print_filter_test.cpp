// printFilter round trip: every sample's normalized spec prints as a filter description whose
// load gives back the same spec (compared as specToJson), with no error; the sibling shows the
// comparison catches a field the printed variant cannot express.
#include "spec/print_filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

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

FilterSpec loadSample(const std::string& name) {
  const LoadResult r = loadFilterFile((test::sourceDir() / "samples/filters" / (name + ".shadow")).string());
  EXPECT_TRUE(r.spec) << formatDiagnostics(r);
  return r.spec.value_or(FilterSpec{});
}

LoadResult reload(const FilterSpec& spec) { return loadFilterSource(printFilter(spec), spec.name + ".printed"); }

class PrintFilter : public ::testing::TestWithParam<std::string> {};

TEST_P(PrintFilter, SampleRoundTripsToTheSameSpec) {
  const FilterSpec spec = loadSample(GetParam());
  const std::string printed = printFilter(spec);
  const LoadResult back = reload(spec);
  ASSERT_TRUE(back.spec) << printed << formatDiagnostics(back);
  EXPECT_EQ(back.errorCount(), 0);
  EXPECT_EQ(specToJson(*back.spec).dump(2), specToJson(spec).dump(2)) << printed;
  // A fixed point: printing the reloaded spec gives the same bytes.
  EXPECT_EQ(printFilter(*back.spec), printed);
}

INSTANTIATE_TEST_SUITE_P(Samples, PrintFilter, ::testing::ValuesIn(samples()),
                         [](const auto& info) { return info.param; });

TEST(PrintFilterSibling, FieldTheVariantCannotExpressShowsAsADifference) {
  FilterSpec spec = loadSample("vssm_adaptive");  // blocker moments: no syntax for search taps
  spec.blocker.taps = 7;
  const LoadResult back = reload(spec);
  ASSERT_TRUE(back.spec) << formatDiagnostics(back);
  EXPECT_NE(specToJson(*back.spec).dump(), specToJson(spec).dump());
  EXPECT_EQ(back.spec->blocker.taps, 16);
}

TEST(PrintFilterSibling, AnInvalidSpecPrintsToADescriptionTheCheckerRejects) {
  FilterSpec spec = loadSample("vssm_adaptive");
  spec.kernel.quadtreeHeight = 6;  // hand-built: outside 1..5
  const LoadResult back = reload(spec);
  EXPECT_FALSE(back.spec);
  ASSERT_FALSE(back.diagnostics.empty());
  EXPECT_EQ(back.diagnostics[0].code, "E0314") << formatDiagnostics(back);
}

TEST(PrintFilter, WritesEveryArgumentNamed) {
  const std::string printed = printFilter(loadSample("vssm_adaptive"));
  EXPECT_NE(printed.find("kernel     quadtree(height: 3, traversal: table, max: 4096, lit_threshold: 0.0001)"),
            std::string::npos)
      << printed;
  EXPECT_NE(printed.find("storage    sat(kind: int32, format: fp32)"), std::string::npos) << printed;
}

}  // namespace

// A stability row that compares nothing fails (docs/stability.md): a NaN worst error is planted
// into settle(), into a case run by the suite, and produced by a filter the intent reference does
// not model; each has a sibling that compares something and passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "gpu/vulkan_fixture.h"
#include "validation/stability/case_support.h"
#include "validation/stability/stability_suite.h"

namespace shadowc::test {
namespace {

using validation::CaseResult;

CaseResult row(double worstError, double bound, bool naive) {
  CaseResult r;
  r.caseName = "planted";
  r.filter = "f";
  r.worstError = worstError;
  r.bound = bound;
  r.naive = naive;
  r.values = 4;
  validation::settle(r);
  return r;
}

TEST(StabilitySettle, ARowThatComparedNothingFails) {
  const CaseResult planted = row(NAN, 1e-6, false);
  EXPECT_FALSE(planted.pass);
  EXPECT_EQ(planted.detail.rfind("nothing compared", 0), 0u) << planted.detail;
  // A naive row must fail its bound by a measured error; a NaN one demonstrates nothing.
  EXPECT_FALSE(row(NAN, 1e-6, true).pass);
  EXPECT_FALSE(row(NAN, INFINITY, false).pass);
  // Siblings: the same rows with a finite error.
  EXPECT_TRUE(row(5e-7, 1e-6, false).pass);
  EXPECT_FALSE(row(2e-6, 1e-6, false).pass);
  EXPECT_TRUE(row(2e-6, 1e-6, true).pass);
  EXPECT_FALSE(row(5e-7, 1e-6, true).pass);
}

TEST(StabilitySettle, TheReportCountsThePlantedRowAsFailed) {
  const std::vector<CaseResult> rows = {row(NAN, 1e-6, false), row(5e-7, 1e-6, false)};
  EXPECT_EQ(validation::resultsJson(rows)["failed"], 1);
  const std::string table = validation::markdownTable(rows);
  EXPECT_NE(table.find("| n/a | 1e-06 | 0 | 0 | FAIL |"), std::string::npos) << table;
  EXPECT_NE(table.find("| 5e-07 | 1e-06 | 0 | 0 | pass |"), std::string::npos) << table;
}

TEST(StabilitySettle, WorstOutsideMeasuresTheDistanceFromTheRange) {
  EXPECT_EQ(validation::worstOutside({0.0f, 0.5f, 1.0f}), 0.0);
  EXPECT_NEAR(validation::worstOutside({0.5f, 1.25f, -0.5f}), 0.5, 1e-7);
  EXPECT_TRUE(std::isinf(validation::worstOutside({0.5f, NAN})));
}

using StabilityNothingComparedTest = VulkanTest;

const validation::StabilityCase& grazingCase() {
  for (const auto& c : validation::stabilityCases())
    if (c.name == "grazing_light") return c;
  throw std::runtime_error("no grazing_light case");
}

// Planted through the suite: a case whose run reports a NaN error fails in runCase's results.
TEST_F(StabilityNothingComparedTest, APlantedNanCaseFailsInTheSuite) {
  validation::SuiteContext ctx{context()};
  const auto run = [](validation::SuiteContext&, const FilterSpec& s) {
    CaseResult r;
    r.filter = s.name;
    r.bound = 1e-6;
    r.worstError = NAN;
    validation::settle(r);
    return r;
  };
  const FilterSpec spec = validation::libraryFilter("pcf_grid3", "depth\nsampling grid(3x3)");
  const validation::StabilityCase planted =
      validation::makeCase("planted_nan", "a row with a NaN error", {spec}, {}, run);
  const auto rs = validation::runCase(ctx, planted);
  ASSERT_EQ(rs.size(), 1u);
  EXPECT_FALSE(rs[0].pass) << rs[0].detail;
}

// A filter the intent reference does not model (Poisson taps) on a real case: its row compared
// nothing and fails; the grid PCF beside it compares every receiver and passes.
TEST_F(StabilityNothingComparedTest, AnUnmodelledFilterFailsWhereAModelledOnePasses) {
  validation::SuiteContext ctx{context()};
  const FilterSpec poisson = validation::libraryFilter("pcf_poisson8", "depth\nsampling poisson(taps: 8)");
  ASSERT_FALSE(validation::intentModels(poisson));
  const auto unmodelled = validation::runCase(ctx, grazingCase(), &poisson);
  ASSERT_EQ(unmodelled.size(), 1u);
  EXPECT_FALSE(unmodelled[0].pass);
  EXPECT_TRUE(std::isnan(unmodelled[0].worstError));
  EXPECT_NE(unmodelled[0].detail.find("nothing compared"), std::string::npos) << unmodelled[0].detail;

  const FilterSpec grid = validation::libraryFilter("pcf_grid3", "depth\nsampling grid(3x3)");
  const auto modelled = validation::runCase(ctx, grazingCase(), &grid);
  ASSERT_EQ(modelled.size(), 1u);
  EXPECT_TRUE(modelled[0].pass) << modelled[0].detail;
  EXPECT_TRUE(std::isfinite(modelled[0].worstError));
}

// The normal offset is modelled (the receiver moved along N as bias.glsl does): its grazing row
// compares, and a reference without the move misses it.
TEST_F(StabilityNothingComparedTest, NormalOffsetIsComparedAgainstTheMovedReceiver) {
  validation::SuiteContext ctx{context()};
  const FilterSpec offset =
      validation::libraryFilter("pcf_normal_offset3", "depth\nsampling grid(3x3)\nbias normal_offset(3)");
  ASSERT_TRUE(validation::intentModels(offset));
  const auto rs = validation::runCase(ctx, grazingCase(), &offset);
  ASSERT_EQ(rs.size(), 1u);
  EXPECT_TRUE(rs[0].pass) << rs[0].detail;
  EXPECT_TRUE(std::isfinite(rs[0].worstError));

  // Sibling: the GPU's results against the unmoved receivers (the same filter, constant bias).
  const validation::LightFrame light;
  const validation::DepthMap map = validation::noiseMap(128, 16, 0.1, 0.9);
  std::vector<validation::Receiver> receivers;
  for (int i = 0; i < 32; ++i) {
    validation::Receiver r = validation::atTexel(128, 5 + 3 * i, 64, 0.3 + 0.02 * i);
    const auto p = validation::receiverPosition(light, r);
    const double len = std::sqrt(p[0] * p[0] + p[2] * p[2]);
    r.normal = std::array<double, 3>{p[2] / len, 0.0, -p[0] / len};  // N.L = 0: the move is sideways
    receivers.push_back(r);
  }
  const auto run = validation::runCrafted(context(), validation::compileCached(offset), map, receivers, light);
  FilterSpec unmoved = offset;
  unmoved.bias.kind = BiasKind::Constant;
  const validation::IntentReference moved(offset, map, light), still(unmoved, map, light);
  double worstMoved = 0, worstStill = 0;
  for (size_t i = 0; i < receivers.size(); ++i) {
    worstMoved = std::max(worstMoved, std::fabs(run.visibility[i] - moved(receivers[i]).front()));
    worstStill = std::max(worstStill, std::fabs(run.visibility[i] - still(receivers[i]).front()));
  }
  EXPECT_LE(worstMoved, 1e-6);
  EXPECT_GT(worstStill, 0.1);  // a 3x3 count off by at least one tap of nine
}

}  // namespace
}  // namespace shadowc::test

// The stability suite (validation/stability, docs/stability.md) as gtest cases on lavapipe with
// the validation layers on: one test per case (every filter it applies to must pass: finite, in
// [0, 1], within its stated bound; naive rows must FAIL), siblings showing the naive forms fail
// where ours pass, and seeded random filters.
#include "validation/stability/stability_suite.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

using validation::CaseResult;

std::vector<CaseResult> runNamed(const std::string& name) {
  validation::SuiteContext ctx{VulkanTest::context()};
  for (const auto& c : validation::stabilityCases())
    if (c.name == name) return validation::runCase(ctx, c);
  ADD_FAILURE() << "no case " << name;
  return {};
}

class StabilityCaseTest : public VulkanTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(StabilityCaseTest, EveryFilterPasses) {
  const auto results = runNamed(GetParam());
  ASSERT_FALSE(results.empty());
  for (const CaseResult& r : results) {
    EXPECT_TRUE(r.pass) << r.caseName << " / " << r.filter << (r.naive ? " (naive)" : "") << ": worst error "
                        << r.worstError << " (bound " << r.bound << "), " << r.nonFinite << " NaN/Inf, " << r.outOfRange
                        << " out of range; " << r.detail;
    if (!r.naive) {
      EXPECT_EQ(r.nonFinite, 0u) << r.filter;
      EXPECT_EQ(r.outOfRange, 0u) << r.filter;
    }
  }
}

std::vector<std::string> caseNames() {
  std::vector<std::string> names;
  for (const auto& c : validation::stabilityCases()) names.push_back(c.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Suite, StabilityCaseTest, ::testing::ValuesIn(caseNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string n = info.param;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

using StabilityNaiveTest = VulkanTest;

const CaseResult& find(const std::vector<CaseResult>& rs, bool naive) {
  for (const CaseResult& r : rs)
    if (r.naive == naive) return r;
  static CaseResult none;
  ADD_FAILURE() << "no " << (naive ? "naive" : "guarded") << " row";
  return none;
}

// Plain fp32 SAT on 2048^2 depths near 1: box means off by > 1e-3 while int32 stays < 7.7e-6.
TEST_F(StabilityNaiveTest, PlainFp32SatFailsWhereInt32Passes) {
  const auto rs = runNamed("sat_box_mean_2048");
  const CaseResult& naive = find(rs, true);
  EXPECT_GT(naive.worstError, 1e-2) << naive.detail;
  bool int32Seen = false;
  for (const CaseResult& r : rs)
    if (r.filter == "vsm_sat_int32") {
      int32Seen = true;
      EXPECT_LE(r.worstError, 7.7e-6) << r.detail;
    }
  EXPECT_TRUE(int32Seen);
}

// Whole-texel SAT corners hold the visibility constant across a texel and jump
// at its boundary; fractional corners follow the continuous box (each technique's pair).
TEST_F(StabilityNaiveTest, TexelCornersStepWhereFractionalCornersFollowTheBox) {
  const auto rs = runNamed("sat_fractional_corners");
  ASSERT_EQ(rs.size(), 4u);
  for (const CaseResult& r : rs) {
    EXPECT_EQ(r.nonFinite + r.outOfRange, 0u) << r.filter;
    if (r.naive)
      EXPECT_GT(r.worstError, 1e-2) << r.filter << ": " << r.detail;
    else
      EXPECT_LE(r.worstError, r.bound) << r.filter << ": " << r.detail;
  }
}

// EVSM4 negative exponent 48 in fp32 (checker: E0404) vs 42: the naive one leaves its bound.
TEST_F(StabilityNaiveTest, UnclampedExponentFailsWhereLimitPasses) {
  const auto rs = runNamed("exponent_limit_evsm4_fp32");
  const CaseResult& ours = find(rs, false);
  const CaseResult& naive = find(rs, true);
  EXPECT_LE(ours.worstError, ours.bound) << ours.detail;
  EXPECT_EQ(ours.nonFinite, 0u);
  EXPECT_NE(naive.detail.find("E0404"), std::string::npos) << naive.detail;
  EXPECT_TRUE(naive.nonFinite > 0 || naive.worstError > naive.bound) << naive.detail;
}

// Eq. 4 unguarded at P -> 1: raw blocker depths non-finite or outside [0, 1]; guarded passes.
TEST_F(StabilityNaiveTest, UnguardedBlockerFailsWhereGuardedPasses) {
  const auto rs = runNamed("vssm_blocker_unguarded");
  const CaseResult& ours = find(rs, false);
  const CaseResult& naive = find(rs, true);
  EXPECT_LE(ours.worstError, ours.bound) << ours.detail;
  EXPECT_EQ(ours.nonFinite + ours.outOfRange, 0u);
  EXPECT_GT(naive.nonFinite + naive.outOfRange, 0u) << naive.detail;
}

using StabilityRandomTest = VulkanTest;

TEST_F(StabilityRandomTest, RandomValidFiltersStayFiniteAndInRange) {
  constexpr uint64_t kSeed = 20240501;
  validation::SuiteContext ctx{context()};
  for (int i = 0; i < 12; ++i) {
    const CaseResult r = validation::runRandomFilter(ctx, kSeed, i);
    EXPECT_TRUE(r.pass) << "seed " << kSeed << " index " << i << ": " << r.detail << "\nfilter:\n"
                        << validation::randomFilterSource(kSeed, i);
    EXPECT_GT(r.values, 0u);
  }
}

// The generator is reproducible: same seed and index, same text.
TEST(StabilityRandomGenerator, SeededAndReproducible) {
  EXPECT_EQ(validation::randomFilterSource(7, 3), validation::randomFilterSource(7, 3));
  EXPECT_NE(validation::randomFilterSource(7, 3), validation::randomFilterSource(8, 3));
}

}  // namespace
}  // namespace shadowc::test

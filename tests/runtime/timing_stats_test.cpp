// The median's order-statistic interval (docs/runtime.md "Timing statistics"): the ranks come from
// the Binomial(n, 1/2) CDF. Worked by hand for n = 10: P(B <= 1) = (1 + 10) / 1024, so ranks 2 and 9
// cover 1 - 22/1024 = 0.978515625; rank 3 would cover 1 - 2 (1 + 10 + 45) / 1024 = 0.890625 < 0.95.
// The tests check against a brute-force sum over all 2^n sign patterns, not the code's own formula.
#include "runtime/executor/timing_stats.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace shadowc::test {
namespace {

// P(X_(j) <= median <= X_(k)) by enumerating which of the n samples fall below the median: the
// median lies in [X_(j), X_(k)] exactly when at least j and fewer than k samples are below it.
double bruteCoverage(int n, int j, int k) {
  uint64_t hits = 0;
  for (uint64_t mask = 0; mask < (uint64_t{1} << n); ++mask) {
    const int below = __builtin_popcountll(mask);
    if (below >= j && below < k) ++hits;
  }
  return static_cast<double>(hits) / static_cast<double>(uint64_t{1} << n);
}

TEST(TimingStats, TenSamplesUseRanksTwoAndNine) {
  const rt::MedianRanks r = rt::medianRanks(10);
  EXPECT_EQ(r.low, 2);
  EXPECT_EQ(r.high, 9);
  EXPECT_DOUBLE_EQ(r.coverage, 1 - 22.0 / 1024);
  EXPECT_NEAR(r.coverage, bruteCoverage(10, 2, 9), 1e-12);
}

// Sibling: the next rank inward is below 95 %, so choosing it would be wrong; the brute force says so.
TEST(TimingStats, RankThreeOfTenFallsShort) {
  EXPECT_LT(bruteCoverage(10, 3, 8), 0.95);
  EXPECT_NE(rt::medianRanks(10).low, 3);
}

// For every n the chosen ranks reach 95 % and one rank further in does not (the largest such j).
TEST(TimingStats, RanksAreTheTightestReaching95Percent) {
  for (int n = 6; n <= 20; ++n) {
    const rt::MedianRanks r = rt::medianRanks(n);
    EXPECT_EQ(r.low + r.high, n + 1) << n;
    EXPECT_NEAR(r.coverage, bruteCoverage(n, r.low, r.high), 1e-12) << n;
    EXPECT_GE(r.coverage, 0.95) << n;
    if (2 * (r.low + 1) <= n + 1) {
      EXPECT_LT(bruteCoverage(n, r.low + 1, r.high - 1), 0.95) << n;
    }
  }
}

// n < 6: even [min, max] covers less than 95 % (n = 5: 1 - 2/32 = 0.9375); the struct says so.
TEST(TimingStats, FewSamplesGiveTheFullRangeAndItsCoverage) {
  const rt::TimingStats s = rt::timingStats({5, 1, 4, 2, 3});
  EXPECT_EQ(s.ciLowMs, 1);
  EXPECT_EQ(s.ciHighMs, 5);
  EXPECT_DOUBLE_EQ(s.ciCoverage, 1 - 2.0 / 32);
  EXPECT_LT(s.ciCoverage, 0.95);
  EXPECT_GE(rt::medianRanks(6).coverage, 0.95);  // 1 - 2/64
}

// Samples 1..10 (shuffled): median 5.5, p90 the 9th = 9, interval [X_(2), X_(9)] = [2, 9], mean 5.5,
// sample variance sum((i - 5.5)^2) / 9 = 82.5 / 9.
TEST(TimingStats, SummaryOfOneToTen) {
  const rt::TimingStats s = rt::timingStats({7, 3, 10, 1, 5, 9, 2, 8, 4, 6});
  EXPECT_EQ(s.n, 10);
  EXPECT_EQ(s.minMs, 1);
  EXPECT_EQ(s.maxMs, 10);
  EXPECT_DOUBLE_EQ(s.medianMs, 5.5);
  EXPECT_EQ(s.p90Ms, 9);
  EXPECT_EQ(s.ciLowMs, 2);
  EXPECT_EQ(s.ciHighMs, 9);
  EXPECT_DOUBLE_EQ(s.meanMs, 5.5);
  EXPECT_DOUBLE_EQ(s.stddevMs * s.stddevMs, 82.5 / 9);
  EXPECT_DOUBLE_EQ(s.cv, s.stddevMs / 5.5);
  EXPECT_DOUBLE_EQ(s.relativeHalfWidth(), 3.5 / 5.5);
}

TEST(TimingStats, EmptyIsAllZero) {
  const rt::TimingStats s = rt::timingStats({});
  EXPECT_EQ(s.n, 0);
  EXPECT_EQ(s.medianMs, 0);
  EXPECT_EQ(s.ciCoverage, 0);
}

// The JSON round trip with a distinct non-zero value in every field, so that two fields written
// under each other's names, or one dropped, cannot come back equal (all-zero stats could).
TEST(TimingStats, JsonRoundTripKeepsEveryFieldApart) {
  rt::TimingStats s;
  s.n = 7;
  s.minMs = 1.25;
  s.medianMs = 2.5;
  s.p90Ms = 3.75;
  s.maxMs = 4.125;
  s.meanMs = 2.625;
  s.stddevMs = 0.375;
  s.cv = 0.142857;
  s.ciLowMs = 1.5;
  s.ciHighMs = 3.5;
  s.ciCoverage = 0.984375;
  const std::vector<double> values = {double(s.n), s.minMs, s.medianMs, s.p90Ms,    s.maxMs,     s.meanMs,
                                      s.stddevMs,  s.cv,    s.ciLowMs,  s.ciHighMs, s.ciCoverage};
  for (size_t i = 0; i < values.size(); ++i)
    for (size_t k = i + 1; k < values.size(); ++k) ASSERT_NE(values[i], values[k]) << i << " " << k;
  const rt::TimingStats back = rt::timingStatsFromJson(rt::toJson(s));
  EXPECT_EQ(back.n, s.n);
  EXPECT_EQ(back.minMs, s.minMs);
  EXPECT_EQ(back.medianMs, s.medianMs);
  EXPECT_EQ(back.p90Ms, s.p90Ms);
  EXPECT_EQ(back.maxMs, s.maxMs);
  EXPECT_EQ(back.meanMs, s.meanMs);
  EXPECT_EQ(back.stddevMs, s.stddevMs);
  EXPECT_EQ(back.cv, s.cv);
  EXPECT_EQ(back.ciLowMs, s.ciLowMs);
  EXPECT_EQ(back.ciHighMs, s.ciHighMs);
  EXPECT_EQ(back.ciCoverage, s.ciCoverage);
  // Sibling: the same JSON with two names swapped reads back different values.
  nlohmann::ordered_json swapped = rt::toJson(s);
  std::swap(swapped["ci_low_ms"], swapped["ci_high_ms"]);
  EXPECT_NE(rt::timingStatsFromJson(swapped).ciLowMs, s.ciLowMs);
}

// Coverage labels never claim more than the interval covers: floored to a tenth of a percent.
TEST(TimingStats, IntervalLabelsSayTheCoverageTheyHave) {
  EXPECT_EQ(rt::coverageText(rt::medianRanks(5).coverage), "93.7 %");  // 1 - 2/32 = 0.9375
  EXPECT_EQ(rt::coverageText(rt::medianRanks(2).coverage), "50 %");
  EXPECT_EQ(rt::coverageText(rt::medianRanks(10).coverage), "97.8 %");  // 1 - 22/1024 = 0.9785
  EXPECT_EQ(rt::intervalLabel({0.9375, 0.9375}), "93.7 % interval");
  EXPECT_EQ(rt::intervalLabel({0.978515625, 0.9375}), ">= 93.7 % interval");
  EXPECT_EQ(rt::intervalLabel({}), "interval");
}

}  // namespace
}  // namespace shadowc::test

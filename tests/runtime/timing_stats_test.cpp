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

}  // namespace
}  // namespace shadowc::test

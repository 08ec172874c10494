// The frontier: exactly the rows nothing beats on both time and RMSE.
#include "sweep/pareto.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <sstream>

#include "support/test_support.h"
#include "sweep/plot.h"

namespace shadowc::sweep {
namespace {

Row row(const std::string& name, double ms, double rmse, size_t caseIndex = 0) {
  Row r;
  r.variant = name;
  r.totalMs = ms;
  r.metrics.rmse = rmse;
  r.metrics.compared = 100;
  r.caseIndex = caseIndex;
  return r;
}

std::vector<std::string> names(const std::vector<Row>& rows, const std::vector<size_t>& idx) {
  std::vector<std::string> out;
  for (size_t i : idx) out.push_back(rows[i].variant);
  return out;
}

TEST(Pareto, APredictedFrameRanksInPlaceOfTheMeasuredOne) {
  // Measured on a loaded machine "noisy" looks as fast as "cheap"; the profile's prediction
  // from its work says it is 4x slower, so with predictions it falls off the frontier.
  std::vector<Row> rows = {row("cheap", 1.0, 0.1), row("noisy", 0.9, 0.1), row("exact", 8, 0.01)};
  EXPECT_EQ(names(rows, frontiers(rows).at(0)), (std::vector<std::string>{"noisy", "exact"}));
  rows[0].predictedMs = 1.0;
  rows[1].predictedMs = 4.0;
  rows[2].predictedMs = 8.0;
  rows[1].total.n = 5;  // a measured interval wide enough to tie is not what ranks a predicted row
  rows[1].total.ciLowMs = 0.1;
  rows[1].total.ciHighMs = 9;
  EXPECT_EQ(names(rows, frontiers(rows).at(0)), (std::vector<std::string>{"cheap", "exact"}));
  EXPECT_EQ(frontierMarks(rows)[1].membership, Membership::Off);
  EXPECT_EQ(rankedMs(rows[1]), 4.0);
  // A row the profile could not price is another device's time: left off, never compared.
  rows.push_back(row("unpriced", 0.01, 0.001));
  EXPECT_EQ(frontierMarks(rows)[3].membership, Membership::Off);
  EXPECT_EQ(names(rows, frontiers(rows).at(0)), (std::vector<std::string>{"cheap", "exact"}));
}

TEST(Pareto, KnownFrontierByTime) {
  const std::vector<Row> rows = {row("slow_exact", 10, 0.01),     row("cheap", 1, 0.1),  row("dominated", 5, 0.2),
                                 row("middle", 3, 0.05),          row("tie_a", 7, 0.03), row("tie_b", 7, 0.03),
                                 row("other_case", 0.1, 0.001, 1)};
  const auto f = frontiers(rows);
  EXPECT_EQ(names(rows, f.at(0)), (std::vector<std::string>{"cheap", "middle", "tie_a", "tie_b", "slow_exact"}));
  EXPECT_EQ(names(rows, f.at(1)), (std::vector<std::string>{"other_case"}));  // cases never mix
}

TEST(Pareto, NoFrontierRowIsDominated) {
  std::vector<Row> rows;
  for (int i = 0; i < 200; ++i)
    rows.push_back(row("r" + std::to_string(i), (i * 37) % 101 + 1, ((i * 53) % 97 + 1) * 1e-3));
  const auto f = frontiers(rows).at(0);
  ASSERT_FALSE(f.empty());
  for (size_t i : f)
    for (const Row& other : rows) EXPECT_FALSE(dominates(other, rows[i])) << rows[i].variant << " by " << other.variant;
  // The sibling: every row off the frontier is dominated by some row (so the check above can fail).
  for (size_t i = 0; i < rows.size(); ++i) {
    if (std::find(f.begin(), f.end(), i) != f.end()) continue;
    bool beaten = false;
    for (const Row& other : rows) beaten = beaten || dominates(other, rows[i]);
    EXPECT_TRUE(beaten) << rows[i].variant;
  }
}

TEST(Pareto, NonFiniteOutputNeverOnTheFrontier) {
  std::vector<Row> rows = {row("nan_fast", 0.5, 0.0), row("ok", 1, 0.1)};
  rows[0].metrics.nonFinite = 3;
  EXPECT_EQ(names(rows, frontiers(rows).at(0)), std::vector<std::string>{"ok"});
}

Row timed(const std::string& name, double low, double ms, double high, double rmse) {
  Row r = row(name, ms, rmse);
  r.total.n = 10;
  r.total.medianMs = ms;
  r.total.ciLowMs = low;
  r.total.ciHighMs = high;
  return r;
}

TEST(ParetoTies, OverlappingIntervalsTieInsteadOfOrdering) {
  // fast_coarse and slow_fine overlap on time: either may be the faster, and slow_fine is more
  // accurate, so the two are tied, each naming the other (a tie is symmetric). clear_loser's
  // interval lies wholly above fast_coarse's and its error is worse: off for certain. cheapest
  // lies wholly below all.
  const std::vector<Row> rows = {timed("cheapest", 0.9, 1.0, 1.1, 0.2), timed("fast_coarse", 1.9, 2.0, 2.3, 0.1),
                                 timed("slow_fine", 2.1, 2.2, 2.5, 0.05), timed("clear_loser", 2.4, 2.6, 2.8, 0.15)};
  const std::vector<FrontierMark> m = frontierMarks(rows);
  EXPECT_EQ(m[0].membership, Membership::On);
  EXPECT_EQ(m[1].membership, Membership::Tied);
  EXPECT_EQ(m[1].tiedWith, (std::vector<size_t>{2}));
  EXPECT_EQ(m[2].membership, Membership::Tied);
  EXPECT_EQ(m[2].tiedWith, (std::vector<size_t>{1}));
  EXPECT_EQ(m[3].membership, Membership::Off);
  EXPECT_EQ(names(rows, frontiers(rows).at(0)), (std::vector<std::string>{"cheapest", "fast_coarse", "slow_fine"}));
}

TEST(ParetoTies, TheSameRowsWithPointTimesGiveTheClassicFrontier) {
  // Sibling: without intervals fast_coarse is faster, so nothing ties and the marks are On/Off only.
  std::vector<Row> rows = {row("cheapest", 1.0, 0.2), row("fast_coarse", 2.0, 0.1), row("slow_fine", 2.2, 0.05),
                           row("clear_loser", 2.6, 0.15)};
  const std::vector<FrontierMark> m = frontierMarks(rows);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(m[i].membership, Membership::On) << rows[i].variant;
  EXPECT_EQ(m[3].membership, Membership::Off);
  EXPECT_TRUE(m[1].tiedWith.empty());
}

TEST(ParetoTies, ARowCertainlyBeatenIsOffEvenWhenItOverlapsAnother) {
  // slower overlaps fast's interval but is also wholly above cheap_exact, which is more accurate.
  const std::vector<Row> rows = {timed("cheap_exact", 0.5, 0.6, 0.7, 0.01), timed("fast", 0.9, 1.0, 1.2, 0.1),
                                 timed("slower", 1.1, 1.3, 1.5, 0.05)};
  const std::vector<FrontierMark> m = frontierMarks(rows);
  EXPECT_EQ(m[0].membership, Membership::On);
  EXPECT_EQ(m[1].membership, Membership::Off);
  EXPECT_EQ(m[2].membership, Membership::Off);
}

}  // namespace
// A tie is symmetric over many planted rows: whenever a names b, b names a, and both are Tied.
TEST(ParetoTies, TiesAreSymmetric) {
  std::vector<Row> rows;
  for (int i = 0; i < 40; ++i) {
    const double ms = 1.0 + 0.05 * ((i * 7) % 40), rmse = 0.01 + 0.002 * ((i * 13) % 40);
    rows.push_back(timed("r" + std::to_string(i), ms - 0.03 * (i % 3), ms, ms + 0.04 * (i % 4), rmse));
  }
  const std::vector<FrontierMark> m = frontierMarks(rows);
  size_t ties = 0;
  for (size_t a = 0; a < rows.size(); ++a)
    for (size_t b : m[a].tiedWith) {
      ++ties;
      EXPECT_EQ(m[a].membership, Membership::Tied) << rows[a].variant;
      EXPECT_EQ(m[b].membership, Membership::Tied) << rows[b].variant;
      EXPECT_NE(std::find(m[b].tiedWith.begin(), m[b].tiedWith.end(), a), m[b].tiedWith.end())
          << rows[a].variant << " names " << rows[b].variant << " but not the other way";
    }
  EXPECT_GT(ties, 0u) << "no tie among the planted rows: nothing compared";
}

// The plot's frontier line runs through the frontier rows by median time and falls in RMSE: the
// tied row slow_coarse (median above fast_fine's, RMSE above too) is drawn and numbered with the
// frontier, but the line does not climb to it.
TEST(ParetoPlot, TheFrontierLineFallsInRmse) {
  Results res;
  res.sweep = "t";
  res.rows = {timed("fast_fine", 0.9, 1.0, 1.3, 0.02), timed("slow_coarse", 1.0, 1.2, 1.4, 0.03),
              timed("slowest_exact", 2.0, 2.1, 2.2, 0.001)};
  for (Row& r : res.rows) r.caseLabel = "case";
  const std::vector<FrontierMark> m = frontierMarks(res.rows);
  ASSERT_EQ(m[1].membership, Membership::Tied);  // fast_fine may beat it, none for certain
  const auto dir = test::freshTempDir("pareto-plot");
  writePlots(dir, res);
  const std::string frontier = test::readFile(dir / "plots/case0_frontier.dat");
  const std::string line = test::readFile(dir / "plots/case0_line.dat");
  EXPECT_NE(frontier.find("slow_coarse"), std::string::npos) << frontier;
  EXPECT_EQ(line.find("slow_coarse"), std::string::npos) << line;
  EXPECT_NE(line.find("fast_fine"), std::string::npos) << line;
  EXPECT_NE(line.find("slowest_exact"), std::string::npos) << line;
  // The line's RMSE column falls from row to row.
  std::istringstream in(line);
  double last = 1e300;
  int points = 0;
  for (std::string l; std::getline(in, l);) {
    if (l.empty() || l[0] == '#') continue;
    std::istringstream f(l);
    double ms = 0, rmse = 0;
    f >> ms >> rmse;
    EXPECT_LT(rmse, last) << l;
    last = rmse;
    ++points;
  }
  EXPECT_EQ(points, 2);
}

}  // namespace shadowc::sweep

// The frontier: exactly the rows nothing beats on both time and RMSE.
#include "sweep/pareto.h"

#include <gtest/gtest.h>

#include <limits>

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

}  // namespace
}  // namespace shadowc::sweep

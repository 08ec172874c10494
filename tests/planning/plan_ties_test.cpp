// The planner's choice among confirmed candidates (planning/planner.h chooseMeasured, and
// replacesChosen for two): certainly slower than another that meets the bound drops out; of the
// rest the more accurate wins, so medians that jitter inside overlapping intervals between reruns
// do not change the plan, and the order the candidates were measured in does not either
// (docs/planning.md "Ties").
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "planning/planner.h"

namespace shadowc {
namespace {

planning::Measurement measured(double ms, double low, double high, double rmse, std::string name = "") {
  planning::Measurement m;
  m.variant = std::move(name);
  m.worstMs = ms;
  m.worstLowMs = low;
  m.worstHighMs = high;
  m.worstRmse = rmse;
  return m;
}

TEST(PlanTies, CertainlyFasterReplacesEvenWhenLessAccurate) {
  const auto chosen = measured(2.0, 1.9, 2.1, 0.02);
  EXPECT_TRUE(planning::replacesChosen(measured(1.0, 0.9, 1.1, 0.03), chosen, false));
  EXPECT_FALSE(planning::replacesChosen(measured(3.0, 2.9, 3.1, 0.01), chosen, false));  // certainly slower
}

TEST(PlanTies, TiedOnTimeTheMoreAccurateStays) {
  // The candidate's median is lower, but the intervals overlap: the runs do not order them, and
  // the chosen one is more accurate, so a rerun whose medians swap plans the same filter.
  const auto chosen = measured(2.0, 1.6, 2.4, 0.02);
  const auto faster = measured(1.8, 1.5, 2.2, 0.03);
  EXPECT_FALSE(planning::replacesChosen(faster, chosen, false));
  EXPECT_TRUE(planning::replacesChosen(chosen, faster, false));  // either order gives the same pick
}

TEST(PlanTies, SiblingPointTimesCompareMedians) {
  // Without intervals (a measurement from before them) the lower median wins, as it always did:
  // the tie rule above is the intervals' doing.
  const auto chosen = measured(2.0, 2.0, 2.0, 0.02);
  EXPECT_TRUE(planning::replacesChosen(measured(1.8, 1.8, 1.8, 0.03), chosen, false));
}

TEST(PlanTies, BudgetOnlyTheMoreAccurateWins) {
  const auto chosen = measured(1.0, 0.9, 1.1, 0.05);
  EXPECT_TRUE(planning::replacesChosen(measured(1.9, 1.8, 2.0, 0.04), chosen, true));
  EXPECT_FALSE(planning::replacesChosen(measured(0.5, 0.4, 0.6, 0.06), chosen, true));
}

// Overlap is not transitive: A [1.0, 1.2] and B [1.1, 1.5] tie, B and C [1.4, 1.6] tie, but C is
// certainly slower than A. A pairwise walk returned C for the order A, B, C and A for C, B, A;
// the set rule drops C (certainly slower than A) and takes B (tied with A, more accurate) in
// every order. D is fastest and most accurate but misses the bound: never chosen.
TEST(PlanTies, TheChoiceDoesNotDependOnTheOrderCandidatesAreMeasured) {
  std::vector<planning::Measurement> tried = {measured(1.1, 1.0, 1.2, 0.03, "A"), measured(1.3, 1.1, 1.5, 0.02, "B"),
                                              measured(1.5, 1.4, 1.6, 0.01, "C")};
  std::sort(tried.begin(), tried.end(), [](const auto& a, const auto& b) { return a.variant < b.variant; });
  int orders = 0;
  do {
    ++orders;
    const auto pick = planning::chooseMeasured(tried, 0.04, std::nullopt);
    ASSERT_TRUE(pick.has_value());
    std::string order;
    for (const auto& m : tried) order += m.variant;
    EXPECT_EQ(tried[*pick].variant, "B") << "order " << order;
    std::vector<planning::Measurement> withD = tried;
    withD.insert(withD.begin() + orders % 4, measured(0.5, 0.4, 0.6, 0.105, "D"));  // misses 0.04
    const auto pickD = planning::chooseMeasured(withD, 0.04, std::nullopt);
    ASSERT_TRUE(pickD.has_value());
    EXPECT_EQ(withD[*pickD].variant, "B") << "order " << order << " with D";
  } while (std::next_permutation(tried.begin(), tried.end(),
                                 [](const auto& a, const auto& b) { return a.variant < b.variant; }));
  EXPECT_EQ(orders, 6);
}

TEST(PlanTies, SiblingThePairwiseWalkDependsOnTheOrder) {
  // What the set rule replaces: keeping the first and letting each next one replace it by the
  // two-candidate rule gives C for A, B, C (B replaces A as tied and more accurate, C replaces B
  // likewise) and A for C, B, A: the reason the rule is on the set.
  const auto a = measured(1.1, 1.0, 1.2, 0.03, "A"), b = measured(1.3, 1.1, 1.5, 0.02, "B"),
             c = measured(1.5, 1.4, 1.6, 0.01, "C");
  auto walk = [](std::vector<planning::Measurement> order) {
    planning::Measurement chosen = order.front();
    for (size_t i = 1; i < order.size(); ++i)
      if (planning::replacesChosen(order[i], chosen, false)) chosen = order[i];
    return chosen.variant;
  };
  EXPECT_EQ(walk({a, b, c}), "C");
  EXPECT_EQ(walk({c, b, a}), "A");
  EXPECT_FALSE(planning::chooseMeasured({a, b, c}, 0.001, std::nullopt).has_value()) << "none meets 0.001";
}

}  // namespace
}  // namespace shadowc

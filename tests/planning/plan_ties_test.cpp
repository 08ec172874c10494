// The planner's choice between two confirmed candidates that both meet the bound
// (planning/planner.h replacesChosen): certainly faster wins; tied on time (overlapping
// intervals), the more accurate wins, so medians that jitter inside the overlap between reruns
// do not change the plan (docs/planning.md "Ties").
#include <gtest/gtest.h>

#include "planning/planner.h"

namespace shadowc {
namespace {

planning::Measurement measured(double ms, double low, double high, double rmse) {
  planning::Measurement m;
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

}  // namespace
}  // namespace shadowc

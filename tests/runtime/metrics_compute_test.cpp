// Metrics on hand-computable inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "runtime/metrics/metrics.h"

namespace shadowc::rt {
namespace {

TEST(Metrics, HandComputedErrors) {
  const std::vector<float> ref = {0.0f, 0.0f, 1.0f, 1.0f, 0.5f};
  const std::vector<float> res = {0.0f, 0.5f, 1.0f, 0.5f, 0.5f};
  const Metrics m = computeMetrics(res, ref, {});
  EXPECT_EQ(m.pixels, 5u);
  EXPECT_EQ(m.compared, 5u);
  EXPECT_NEAR(m.mae, 1.0 / 5, 1e-12);
  EXPECT_NEAR(m.rmse, std::sqrt(0.5 / 5), 1e-12);
  EXPECT_DOUBLE_EQ(m.maxAbsError, 0.5);
  EXPECT_DOUBLE_EQ(m.p99AbsError, 0.5);          // nearest rank: ceil(0.99 * 5) = 5th smallest
  EXPECT_NEAR(m.lightBleeding, 1.0 / 5, 1e-12);  // pixel 1: ref 0, result 0.5
  EXPECT_NEAR(m.overDarkening, 1.0 / 5, 1e-12);  // pixel 3: ref 1, result 0.5
  EXPECT_EQ(m.nonFinite, 0u);
  EXPECT_EQ(m.outOfRange, 0u);
}

TEST(Metrics, PercentileIsNearestRank) {
  std::vector<float> ref(200, 0.0f), res(200);
  for (int i = 0; i < 200; ++i) res[i] = float(i) / 1000.0f;  // errors 0 .. 0.199
  const Metrics m = computeMetrics(res, ref, {});
  EXPECT_FLOAT_EQ(float(m.p99AbsError), 0.197f);  // 198th smallest
  EXPECT_FLOAT_EQ(float(m.maxAbsError), 0.199f);
}

TEST(Metrics, MaskSelectsPixels) {
  const std::vector<float> ref = {0, 0, 0};
  const std::vector<float> res = {1, 0.25f, 1};
  const Metrics m = computeMetrics(res, ref, {0, 1, 0});
  EXPECT_EQ(m.pixels, 1u);
  EXPECT_DOUBLE_EQ(m.maxAbsError, 0.25);
  EXPECT_DOUBLE_EQ(m.lightBleeding, 1.0);
  EXPECT_THROW(computeMetrics(res, ref, {1, 1}), std::invalid_argument);
  EXPECT_THROW(computeMetrics(res, {0, 0}, {}), std::invalid_argument);
  EXPECT_EQ(geometryMask({1, 2, 3, 1, 4, 5, 6, 0}), (std::vector<uint8_t>{1, 0}));
}

TEST(Metrics, NanIsCountedNotPropagated) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const std::vector<float> ref = {0.5f, 0.5f, 0.5f, 0.5f, nan};
  const std::vector<float> res = {nan, inf, 0.75f, 1.5f, 0.5f};
  const Metrics m = computeMetrics(res, ref, {});
  EXPECT_EQ(m.nonFinite, 2u);
  EXPECT_EQ(m.invalidReference, 1u);
  EXPECT_EQ(m.compared, 2u);
  EXPECT_EQ(m.outOfRange, 1u);  // 1.5
  EXPECT_TRUE(std::isfinite(m.rmse));
  EXPECT_DOUBLE_EQ(m.maxAbsError, 1.0);
  EXPECT_NEAR(m.mae, (0.25 + 1.0) / 2, 1e-12);
  // Sibling: without the non-finite pixels nothing is counted.
  EXPECT_EQ(computeMetrics({0.75f}, {0.5f}, {}).nonFinite, 0u);
}

TEST(Metrics, JsonHasFixedKeys) {
  const auto j = toJson(computeMetrics({0.5f}, {0.25f}, {}));
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"pixels", "compared", "rmse", "mae", "max_abs_error", "p99_abs_error",
                                            "light_bleeding", "over_darkening", "non_finite", "out_of_range",
                                            "invalid_reference"}));
  EXPECT_DOUBLE_EQ(j["rmse"].get<double>(), 0.25);
  EXPECT_EQ(j["pixels"].get<uint64_t>(), 1u);
}

}  // namespace
}  // namespace shadowc::rt

// `light_samples N` in the front end: the views' offsets on the light (the one table the shader
// and the runtime share, FilterSpec lightSampleOffsets), the setting's JSON and printed form.
// The refusals are negative tests (tests/dsl/negative/light_samples_*.shadow).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "spec/load_filter.h"
#include "spec/print_filter.h"

using namespace shadowc;

namespace {
FilterSpec load(const std::string& body) {
  const LoadResult r = loadFilterSource("filter t {\n" + body + "\n}\n", "t.shadow");
  EXPECT_EQ(r.errorCount(), 0) << formatDiagnostics(r);
  return r.spec.value_or(FilterSpec{});
}
}  // namespace

// A rect's views are the centres of a k x k grid: for k = 4, x and y each take the four values
// (j + 1/2)/4 - 1/2, every pair once, and their mean is the light's centre.
TEST(LightSamples, RectViewsAreTheCellCentres) {
  const auto o = lightSampleOffsets(16, false);
  ASSERT_EQ(o.size(), 16u);
  std::set<std::pair<double, double>> distinct(o.begin(), o.end());
  EXPECT_EQ(distinct.size(), 16u);
  double mx = 0, my = 0;
  for (const auto& [x, y] : o) {
    for (double v : {x, y}) {
      const double j = (v + 0.5) * 4 - 0.5;  // the cell index this coordinate is the centre of
      EXPECT_NEAR(j, std::round(j), 1e-12) << v;
      EXPECT_GE(j, -1e-12);
      EXPECT_LE(j, 3 + 1e-12);
    }
    mx += x / 16, my += y / 16;
  }
  EXPECT_NEAR(mx, 0, 1e-12);
  EXPECT_NEAR(my, 0, 1e-12);
  EXPECT_EQ(lightSampleOffsets(1, false), (std::vector<std::pair<double, double>>{{0.0, 0.0}}));
}

// A disk's views are the concentric map of the same centres: all inside the disk of diameter 1,
// and equal areas: the inner (k/2)^2 cells of the square (|a|, |b| < 1/2) land inside radius 1/4,
// a quarter of the disk's area, so exactly a quarter of the views lie there.
TEST(LightSamples, DiskViewsAreEqualAreasOfTheDisk) {
  const auto o = lightSampleOffsets(64, true);
  ASSERT_EQ(o.size(), 64u);
  int inner = 0;
  double mx = 0, my = 0;
  for (const auto& [x, y] : o) {
    const double r = std::hypot(x, y);
    EXPECT_LE(r, 0.5 + 1e-12);
    inner += r < 0.25 ? 1 : 0;
    mx += x / 64, my += y / 64;
  }
  EXPECT_EQ(inner, 16);
  EXPECT_NEAR(mx, 0, 1e-12);
  EXPECT_NEAR(my, 0, 1e-12);
}

TEST(LightSamples, SpecJsonListsTheViewsOnlyWhenSampled) {
  const std::string body = "light disk(size: scene)\nkernel fixed(1)\n";
  const nlohmann::ordered_json off = specToJson(load(body));
  EXPECT_FALSE(off.contains("light_samples"));
  const FilterSpec s = load(body + "light_samples 9\n");
  EXPECT_EQ(s.lightSamples, 9);
  const nlohmann::ordered_json on = specToJson(s);
  ASSERT_TRUE(on.contains("light_samples"));
  EXPECT_EQ(on["light_samples"]["count"], 9);
  EXPECT_EQ(on["light_samples"]["grid"], 3);
  const auto expected = lightSampleOffsets(9, true);
  ASSERT_EQ(on["light_samples"]["offsets"].size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_DOUBLE_EQ(on["light_samples"]["offsets"][i][0].get<double>(), expected[i].first);
    EXPECT_DOUBLE_EQ(on["light_samples"]["offsets"][i][1].get<double>(), expected[i].second);
  }
}

TEST(LightSamples, PrintedFilterReadsBackTheSame) {
  const FilterSpec s = load("light area(size: scene)\nkernel fixed(1)\nweights form_factor\nlight_samples 64\n");
  const std::string printed = printFilter(s);
  EXPECT_NE(printed.find("light_samples 64"), std::string::npos) << printed;
  const LoadResult back = loadFilterSource(printed, "printed.shadow");
  ASSERT_TRUE(back.spec) << formatDiagnostics(back);
  EXPECT_EQ(specToJson(*back.spec), specToJson(s));
}

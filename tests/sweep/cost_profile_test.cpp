// Device cost profiles (sweep/cost_profile.h, docs/cost.md): the fit recovers the coefficients
// that made the times, prediction prices every pass, and malformed profiles are refused.
#include "sweep/cost_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "support/test_support.h"

namespace shadowc::sweep {
namespace {

// A device whose times are exactly linear in the work: shade = 0.05 ms + 2 ms/Mpixel +
// 0.3 ms per million depth fetches + 1.5 ms per million SAT fetches; sat_rows = 0.02 ms +
// 0.4 ms/Mtexel; moments = 0.01 ms + 0.25 ms/Mtexel.
CostSample sample(uint32_t screen, uint32_t map, uint64_t depthPerPixel, uint64_t satPerPixel) {
  CostSample s;
  s.variant = "v" + std::to_string(depthPerPixel) + "_" + std::to_string(satPerPixel);
  s.caseLabel = "c" + std::to_string(screen) + "_" + std::to_string(map);
  s.scene = "two_planes";
  s.screen = screen;
  s.map = map;
  const double px = double(screen) * screen, tx = double(map) * map;
  rt::WorkCounts w;
  w.pass = "shade";
  w.fields = {"receivers", "depth_fetches", "sat_fetches"};
  w.totals = {uint64_t(px), uint64_t(px) * depthPerPixel, uint64_t(px) * satPerPixel};
  s.work = w;
  const double shade = 0.05 + 2 * px * 1e-6 + 0.3 * double(w.totals[1]) * 1e-6 + 1.5 * double(w.totals[2]) * 1e-6;
  s.passes.push_back({"shade", "shade", shade});
  if (satPerPixel) {
    s.passes.push_back({"moments", "moments", 0.01 + 0.25 * tx * 1e-6});
    s.passes.push_back({"sat_rows", "sat", 0.02 + 0.4 * tx * 1e-6});
  }
  s.totalMs = 0;
  for (const PassTime& p : s.passes) s.totalMs += p.medianMs;
  return s;
}

std::vector<CostSample> grid() {
  std::vector<CostSample> out;
  for (auto [screen, map] : {std::pair{128u, 512u}, {256u, 1024u}, {512u, 2048u}})
    for (auto [d, t] : {std::pair{25ull, 0ull}, {16ull, 0ull}, {4ull, 40ull}, {1ull, 12ull}, {0ull, 80ull}})
      out.push_back(sample(screen, map, d, t));
  return out;
}

TEST(CostProfile, TheFitRecoversTheCoefficientsThatMadeTheTimes) {
  const CostProfile p = fitCostProfile(grid(), "exact", "test");
  EXPECT_NEAR(p.shade.msPerMcount.at("depth_fetches"), 0.3, 1e-6);
  EXPECT_NEAR(p.shade.msPerMcount.at("sat_fetches"), 1.5, 1e-6);
  EXPECT_NEAR(p.passes.at("sat_rows").msPerMtexel, 0.4, 1e-6);
  EXPECT_NEAR(p.passes.at("sat_rows").fixedMs, 0.02, 1e-6);
  const FitQuality q = assessFit(p, grid());
  EXPECT_EQ(q.priced, grid().size());
  EXPECT_EQ(q.within, q.priced);
  EXPECT_LT(q.maxAbsLog, 1e-5);
  // A size it was not fitted at is predicted from the same coefficients.
  const CostSample big = sample(1024, 4096, 4, 40);
  EXPECT_NEAR(*p.frameMs(big) / big.totalMs, 1.0, 1e-5);
}

TEST(CostProfile, ASampleItCannotPriceIsCountedNotGuessed) {
  const CostProfile p = fitCostProfile(grid(), "exact", "test");
  CostSample uncounted = sample(256, 1024, 7, 3);
  uncounted.work.reset();
  EXPECT_FALSE(p.frameMs(uncounted));
  CostSample unknownPass = sample(256, 1024, 25, 0);
  unknownPass.passes.push_back({"blur_h", "blur", 1.0});
  EXPECT_FALSE(p.frameMs(unknownPass));
  const FitQuality q = assessFit(p, {uncounted, unknownPass, sample(256, 1024, 25, 0)});
  EXPECT_EQ(q.priced, 1u);
  EXPECT_EQ(q.unpriced, 2u);
  // Counts from elsewhere make it priceable: they are the same on every device.
  std::vector<CostSample> s = {uncounted};
  EXPECT_EQ(attachCounts(s, grid()), 1u);  // the grid has no sample of this variant and case...
  std::vector<CostSample> counted = {sample(256, 1024, 7, 3)};
  EXPECT_EQ(attachCounts(s, counted), 0u);  // ...this one has
  EXPECT_NEAR(*p.frameMs(s[0]) / s[0].totalMs, 1.0, 1e-5);
}

TEST(CostProfile, AWrongProfileIsMeasuredAsWrong) {
  // The sibling of the exact fit: the same profile with the SAT fetches priced at a third is
  // judged off by the quality measure on the SAT samples.
  CostProfile p = fitCostProfile(grid(), "exact", "test");
  p.shade.msPerMcount["sat_fetches"] /= 3;
  const FitQuality q = assessFit(p, grid());
  EXPECT_LT(q.within, q.priced);
  EXPECT_GT(std::exp(q.maxAbsLog), 1.5);
}

TEST(CostProfile, JsonRoundTripsAndBadProfilesAreRefused) {
  const CostProfile p = fitCostProfile(grid(), "exact", "test");
  const std::string text = costProfileToJson(p);
  const CostProfile back = parseCostProfile(text, "p.json");
  EXPECT_EQ(costProfileToJson(back), text);
  EXPECT_THROW(fitCostProfile({}, "none", "test"), std::runtime_error);
  auto errorOf = [](const std::string& t) {
    try {
      parseCostProfile(t, "p.json");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(errorOf("{").find("p.json: error: malformed cost profile JSON"), std::string::npos);
  EXPECT_NE(errorOf(R"({"format": "other", "version": 1})").find("not a cost profile"), std::string::npos);
  std::string negative = text;
  negative.insert(negative.find("\"fixed_ms\": ") + 12, "-");
  EXPECT_NE(errorOf(negative).find("must be finite and >= 0"), std::string::npos) << negative.substr(0, 300);
  EXPECT_EQ(errorOf(text), "");
}

TEST(CostProfile, BuiltInProfilesAreTheStoredOnesByName) {
  // An installed shadowc names the stored profiles without the source tree: each built-in one
  // is samples/cost/<name>.json, byte for byte once written back.
  const std::vector<std::string> names = builtInCostProfiles();
  ASSERT_EQ(names, (std::vector<std::string>{"h200", "lavapipe"}));
  for (const std::string& n : names) {
    std::ifstream in(test::sourceDir() / "samples/cost" / (n + ".json"));
    std::stringstream stored;
    stored << in.rdbuf();
    ASSERT_FALSE(stored.str().empty()) << n;
    EXPECT_EQ(costProfileToJson(resolveCostProfile(n)), stored.str()) << n;
  }
  // A path is a file even when its stem is a built-in name; an unknown name lists the names.
  EXPECT_THROW(resolveCostProfile("./lavapipe"), std::runtime_error);
  try {
    resolveCostProfile("h100");
    ADD_FAILURE() << "an unknown profile name was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("h100: error: not a built-in cost profile (h200, lavapipe)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace shadowc::sweep

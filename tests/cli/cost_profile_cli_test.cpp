// `shadowc cost-profile` (docs/cost.md, docs/cli.md): fits a profile to sweep results and checks
// one against them; each mistake is one error before anything is written, each with a sibling
// that succeeds.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_expect.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

using test::expectOneError;

// Rows of a device whose shade pass costs 0.1 ms + 0.5 ms per million depth fetches and whose
// blur costs 2 ms per million map texels: the fit must find it exactly.
std::filesystem::path writeResults(const std::filesystem::path& dir, bool counted) {
  nlohmann::json rows = nlohmann::json::array();
  for (uint32_t screen : {128u, 256u, 512u})
    for (uint64_t taps : {9ull, 25ull, 49ull}) {
      const uint64_t px = uint64_t(screen) * screen, map = 4 * screen;
      const double shade = 0.1 + 0.5 * double(px * taps) * 1e-6, blur = 2.0 * double(map * map) * 1e-6;
      nlohmann::json r = {{"variant", fmt::format("pcf{}", taps)},
                          {"case", fmt::format("two_planes {}px map {}", screen, map)},
                          {"scene", "two_planes"},
                          {"device", "synthetic"},
                          {"screen", screen},
                          {"map", map},
                          {"total_ms", shade + blur},
                          {"passes",
                           {{{"name", "blur_h"}, {"kind", "blur"}, {"median_ms", blur}},
                            {{"name", "shade"}, {"kind", "shade"}, {"median_ms", shade}}}}};
      if (counted)
        r["work"] = {{"pass", "shade"},
                     {"fields", {"receivers", "depth_fetches"}},
                     {"totals", {{"receivers", px}, {"depth_fetches", px * taps}}}};
      rows.push_back(r);
    }
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "results.json") << nlohmann::json{{"rows", rows}}.dump();
  return dir;
}

TEST(CostProfileCli, FitsAProfileThatPredictsItsRows) {
  const auto dir = test::freshTempDir("cost-fit");
  const auto results = writeResults(dir / "sweep", true);
  const auto profile = dir / "p.json";
  const test::CliResult fit = test::runShadowc("cost-profile " + results.string() + " -o " + profile.string());
  ASSERT_EQ(fit.code, 0) << fit.err;
  EXPECT_NE(fit.out.find("fitted on: 9 frames"), std::string::npos) << fit.out;
  EXPECT_NE(fit.out.find("9 of 9 (100.0 %) within 1.5x"), std::string::npos) << fit.out;
  const nlohmann::json p = nlohmann::json::parse(std::ifstream(profile));
  EXPECT_EQ(p.at("device"), "synthetic");
  EXPECT_NEAR(p.at("shade").at("ms_per_mcount").at("depth_fetches").get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(p.at("passes").at("blur_h").at("ms_per_mtexel").get<double>(), 2.0, 1e-6);
  // Check mode prices the same rows; uncounted rows priced with counts from the counted ones.
  const auto bare = writeResults(dir / "bare", false);
  const test::CliResult check = test::runShadowc("cost-profile " + bare.string() + " --counts-from " +
                                                 results.string() + " --profile " + profile.string());
  ASSERT_EQ(check.code, 0) << check.err;
  EXPECT_NE(check.out.find("9 frames"), std::string::npos) << check.out;
  EXPECT_NE(check.out.find("largest 1.00x"), std::string::npos) << check.out;
}

TEST(CostProfileCli, MistakesAreOneErrorAndWriteNothing) {
  const auto dir = test::freshTempDir("cost-mistakes");
  const auto profile = dir / "p.json";
  expectOneError(test::runShadowc("cost-profile " + (dir / "missing").string() + " -o " + profile.string()),
                 "no such sweep results");
  const auto bare = writeResults(dir / "bare", false);
  expectOneError(test::runShadowc("cost-profile " + bare.string() + " -o " + profile.string()),
                 "no shade pass with work counts to fit");
  expectOneError(test::runShadowc("cost-profile " + bare.string()), "give exactly one of -o");
  expectOneError(test::runShadowc("cost-profile " + bare.string() + " --profile " + (bare / "results.json").string()),
                 "not a cost profile");
  EXPECT_FALSE(std::filesystem::exists(profile));
  // A sweep with a profile that is not there stops before it runs anything.
  const auto sweepOut = dir / "sweep";
  expectOneError(test::runShadowc("sweep " + (test::sourceDir() / "samples/sweeps/default.json").string() + " -o " +
                                  sweepOut.string() + " --cost-profile " + profile.string()),
                 "cannot read the cost profile");
  EXPECT_FALSE(std::filesystem::exists(sweepOut / "results.json"));
}

}  // namespace
}  // namespace shadowc

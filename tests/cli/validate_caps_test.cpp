// `shadowc validate` says where a penumbra kernel's `max` cuts the scene (the
// PCSS blocker search and kernel are not truncated silently): on large_penumbra a PCSS filter
// with max 8 is cut on many penumbra pixels; the sibling with max 4096 on none; a fixed kernel
// has no cap to report.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "support/test_support.h"

namespace shadowc {
namespace {

const std::string kSmall = " --screen 64 --map 256 --samples 2 --runs 1 --warmup 0 --no-reference-cache";

std::string pcss(int max) {
  return "filter pcss_cap {\n    light area(size: scene)\n    depth\n    blocker search(16, pattern: poisson)\n"
         "    kernel penumbra(max: " +
         std::to_string(max) + ")\n    sampling poisson(16, rotate: stable)\n}\n";
}

struct Caps {
  long over = -1, of = -1;
};

Caps validateCaps(const std::string& tag, const std::string& text) {
  const auto path = test::freshTempDir(tag) / "f.shadow";
  std::ofstream(path, std::ios::binary) << text;
  const test::CliResult r = test::runShadowc("validate " + path.string() + " --scene large_penumbra" + kSmall);
  EXPECT_EQ(r.code, 0) << r.err;
  std::smatch m;
  const std::regex line(R"(caps     kernel max \S+ texels: the penumbra is wider on (\d+) of (\d+) penumbra pixels)");
  Caps c;
  if (std::regex_search(r.out, m, line)) c = {std::stol(m[1]), std::stol(m[2])};
  return c;
}

TEST(ValidateCaps, ASmallKernelMaxIsReportedWhereItCuts) {
  const Caps c = validateCaps("caps-8", pcss(8));
  ASSERT_GT(c.of, 0) << "no caps line";
  EXPECT_GT(c.over, c.of / 2);  // large_penumbra: penumbrae of tens of texels at 256^2
}

TEST(ValidateCaps, SiblingTheWholeMapCutsNothing) {
  const Caps c = validateCaps("caps-4096", pcss(4096));
  ASSERT_GT(c.of, 0) << "no caps line";
  EXPECT_EQ(c.over, 0);
}

TEST(ValidateCaps, AFixedKernelHasNoCapLine) {
  const auto path = test::freshTempDir("caps-fixed") / "f.shadow";
  std::ofstream(path, std::ios::binary) << "filter pcf_fixed {\n    depth\n    kernel fixed(5)\n}\n";
  const test::CliResult r = test::runShadowc("validate " + path.string() + " --scene large_penumbra" + kSmall);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rmse"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("caps "), std::string::npos) << r.out;
}

}  // namespace
}  // namespace shadowc

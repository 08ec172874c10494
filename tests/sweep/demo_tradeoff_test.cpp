// `shadowc demo` ends with a trade-off table (cheap PCF to VSSM on its scene). Its rows agree
// with `shadowc validate` of the same filter on the same scene and sizes: same RMSE within
// 1e-5 (both print 5 decimals; the runs are the same passes on the same inputs against the same
// cached reference, so only the printing rounds). The frontier marks are consistent with the
// printed numbers.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "support/test_support.h"

namespace shadowc {
namespace {

struct TableRow {
  bool frontier = false;
  std::string variant;
  double ms = 0, rmse = 0;
};

std::vector<TableRow> tradeoffRows(const std::string& out) {
  const std::regex row(R"(^\s+([*]?)=?\s+(\w+)\s+([0-9.]+)\s+\[[0-9.]+, [0-9.]+\]\s+([0-9.]+)\s)");
  std::vector<TableRow> rows;
  std::istringstream in(out.substr(std::min(out.size(), out.find("trade-off "))));
  for (std::string l; std::getline(in, l);) {
    std::smatch m;
    if (std::regex_search(l, m, row)) rows.push_back({m[1] == "*", m[2], std::stod(m[3]), std::stod(m[4])});
  }
  return rows;
}

double validateRmse(const std::string& out) {
  std::smatch m;
  const std::regex rmse(R"(rmse ([0-9.]+))");
  return std::regex_search(out, m, rmse) ? std::stod(m[1]) : -1;
}

TEST(DemoTradeoff, RowsAgreeWithValidate) {
  const auto dir = test::freshTempDir("demo-tradeoff");
  const test::CliResult demo = test::runShadowc("demo --screen 48 --out " + dir.string());
  ASSERT_EQ(demo.code, 0) << demo.out << demo.err;
  const std::vector<TableRow> rows = tradeoffRows(demo.out);
  ASSERT_EQ(rows.size(), 4u) << demo.out;
  EXPECT_NE(demo.out.find("shadowc sweep samples/sweeps/default.json"), std::string::npos);
  const test::CliResult v =
      test::runShadowc("validate " + (test::sourceDir() / "samples/filters/pcss_poisson.shadow").string() +
                       " --scene two_planes --screen 48 --map 1024 --samples 16 --runs 1 --warmup 0");
  ASSERT_EQ(v.code, 0) << v.err;
  bool found = false;
  for (const TableRow& r : rows)
    if (r.variant == "pcss_poisson") {
      found = true;
      EXPECT_NEAR(r.rmse, validateRmse(v.out), 1e-5) << demo.out << v.out;
    }
  EXPECT_TRUE(found) << demo.out;
  // The demo's own filter (validated first, then a table row) agrees with itself too.
  for (const TableRow& r : rows)
    if (r.variant == "vssm_pcf_fallback") {
      EXPECT_NEAR(r.rmse, validateRmse(demo.out), 1e-5);
    }
  // Marks: an unmarked row is beaten on both by some row; a marked one by none.
  for (const TableRow& r : rows) {
    bool beaten = false;
    for (const TableRow& o : rows)
      beaten = beaten || (o.ms <= r.ms && o.rmse <= r.rmse && (o.ms < r.ms || o.rmse < r.rmse));
    EXPECT_EQ(r.frontier, !beaten) << r.variant;
  }
}

}  // namespace
}  // namespace shadowc

// `shadowc demo` ends with a trade-off table (cheap PCF to VSSM on its scene). Its rows agree
// with `shadowc validate` of the same filter on the same scene and sizes: same RMSE within
// 1e-5 (both print 5 decimals; the runs are the same passes on the same inputs against the same
// cached reference, so only the printing rounds). The frontier marks follow the sweep's tie rule
// (docs/sweep.md "Ties"), judged here from the rows' exact intervals in the demo's results.json:
// a row is off when another is below its whole interval and no less accurate, tied (=) when a
// frontier row whose interval overlaps may beat it or be beaten by it; medians that swap inside
// an overlap on a loaded machine change neither.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <sstream>

#include "support/test_support.h"
#include "sweep/results_io.h"

namespace shadowc {
namespace {

struct TableRow {
  bool frontier = false, tied = false;
  std::string variant;
  double ms = 0, rmse = 0;
};

std::vector<TableRow> tradeoffRows(const std::string& out) {
  const std::regex row(R"(^\s+([*]?)(=?)\s+(\w+)\s+([0-9.]+)\s+\[[0-9.]+, [0-9.]+\]\s+([0-9.]+)\s)");
  std::vector<TableRow> rows;
  std::istringstream in(out.substr(std::min(out.size(), out.find("trade-off "))));
  for (std::string l; std::getline(in, l);) {
    std::smatch m;
    if (std::regex_search(l, m, row))
      rows.push_back({m[1] == "*", m[2] == "=", m[3], std::stod(m[4]), std::stod(m[5])});
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
  // Marks by the tie rule, on the exact intervals of the rows the demo's sweep cached (the table
  // rounds them).
  std::vector<sweep::Row> written;
  for (const auto& e : std::filesystem::directory_iterator(dir / "tradeoff" / "cache"))
    if (const auto r = sweep::readCachedRow(dir / "tradeoff", e.path().stem().string())) written.push_back(*r);
  ASSERT_EQ(written.size(), rows.size());
  struct Exact {
    double low, high, rmse;
  };
  std::map<std::string, Exact> exact;
  for (const sweep::Row& r : written) {
    ASSERT_GT(r.total.n, 0) << r.variant << ": no interval";
    exact[r.variant] = {r.total.ciLowMs, r.total.ciHighMs, r.metrics.rmse};
  }
  auto beats = [](const Exact& a, const Exact& b) {  // for certain
    return a.high <= b.low && a.rmse <= b.rmse && (a.high < b.low || a.rmse < b.rmse);
  };
  auto mayBeat = [](const Exact& a, const Exact& b) {
    return a.low <= b.high && a.rmse <= b.rmse && (a.low < b.high || a.rmse < b.rmse);
  };
  std::map<std::string, bool> off;
  for (const TableRow& r : rows) {
    ASSERT_EQ(exact.count(r.variant), 1u) << r.variant;
    off[r.variant] = false;
    for (const TableRow& o : rows) off[r.variant] = off[r.variant] || beats(exact[o.variant], exact[r.variant]);
  }
  for (const TableRow& r : rows) {
    bool tied = false;
    for (const TableRow& o : rows)
      tied = tied || (o.variant != r.variant && !off[r.variant] && !off[o.variant] &&
                      (mayBeat(exact[o.variant], exact[r.variant]) || mayBeat(exact[r.variant], exact[o.variant])));
    EXPECT_EQ(r.frontier, !off[r.variant]) << r.variant << "\n" << demo.out;
    EXPECT_EQ(r.tied, tied) << r.variant << "\n" << demo.out;
  }
}

}  // namespace
}  // namespace shadowc

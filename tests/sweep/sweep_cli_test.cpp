// `shadowc sweep` end to end on a tiny sweep (32x32 screen, 256 map, 2x2 reference samples, so
// the whole file runs in seconds): the frontier on the terminal equals the CSV's and the
// report's (loaded in headless Chromium), no frontier row is dominated, invalid combinations are
// counted under the checker's codes, an interrupted sweep re-runs nothing that finished, and
// shards merged equal one process.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <vector>

#include "support/test_support.h"
#include "sweep/pareto.h"
#include "sweep/results_io.h"

namespace shadowc {
namespace {

using nlohmann::json;

// Four valid variants (hard, two PCF tap counts, PCSS) and one the checker rejects (E0416: a
// point light cannot size a blocker search).
std::string tinySweep(const std::string& shaders = R"(["specialized"])") {
  const std::string f = (test::sourceDir() / "samples/filters").string();
  return R"J({
  "name": "tiny",
  "filters": [
    ")J" +
         f + R"J(/hard_constant_bias.shadow",
    {"name": "pcf", "file": ")J" +
         f + R"J(/pcf_poisson16.shadow", "set": {"sampling": "poisson(${taps}, rotate: stable)"}},
    {"file": ")J" +
         f + R"J(/pcss_poisson.shadow"},
    {"name": "point_pcss", "file": ")J" +
         f + R"J(/pcss_poisson.shadow", "set": {"light": "point"}}
  ],
  "params": {"taps": [4, 16]},
  "scenes": ["two_planes"],
  "screen": 32, "map": 256, "reference_samples": 2, "runs": 2, "warmup": 1,
  "shaders": )J" +
         shaders + "\n}\n";
}

std::filesystem::path writeSweep(const std::string& tag, const std::string& text) {
  const auto dir = test::freshTempDir(tag);
  std::ofstream(dir / "sweep.json") << text;
  return dir;
}

test::CliResult runSweep(const std::filesystem::path& dir, const std::string& out, const std::string& extra = "",
                         const std::string& env = "") {
  return test::runShadowc("sweep " + (dir / "sweep.json").string() + " -o " + (dir / out).string() + " " + extra, env);
}

json results(const std::filesystem::path& out) { return json::parse(test::readFile(out / "results.json")); }

// CSV rows with frontier == 1 as (variant, total_ms, rmse, key), in file order.
struct CsvRow {
  std::string variant, key;
  double ms = 0, rmse = 0;
  bool frontier = false;
};
std::vector<CsvRow> csvRows(const std::filesystem::path& out) {
  std::istringstream in(test::readFile(out / "results.csv"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("case,scene,screen,map,variant,", 0), 0u) << line;
  std::vector<CsvRow> rows;
  while (std::getline(in, line)) {
    // Split the simple leading fields (none of ours holds a quote before the spec column).
    std::vector<std::string> f;
    std::string cur;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted) {
        f.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
    f.push_back(cur);
    rows.push_back({f.at(4), f.at(19), std::stod(f.at(8)), std::stod(f.at(9)), f.at(16) == "1"});
  }
  return rows;
}

TEST(SweepCli, FrontierOnTerminalEqualsCsvAndReport) {
  const auto dir = writeSweep("sweep-frontier", tinySweep());
  const test::CliResult r = runSweep(dir, "out");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  // Terminal: the lines of the frontier block, "  <rank>[=]  <variant>  <ms>  [<low>, <high>]  <rmse>  ...".
  const std::regex line(R"(^\s+(\d+)=?\s+(\S+)\s+([0-9.]+)\s+\[([0-9.]+), ([0-9.]+)\]\s+([0-9.]+)\s)");
  std::vector<std::tuple<std::string, double, double>> printed;
  std::istringstream out(r.out);
  for (std::string l; std::getline(out, l);) {
    std::smatch m;
    if (!std::regex_search(l, m, line)) continue;
    printed.emplace_back(m[2], std::stod(m[3]), std::stod(m[6]));
    // The median lies inside its own interval (rounded to the printed 3 decimals).
    EXPECT_LE(std::stod(m[4]), std::stod(m[3])) << l;
    EXPECT_LE(std::stod(m[3]), std::stod(m[5])) << l;
  }
  std::vector<CsvRow> csvFrontier;
  for (const CsvRow& c : csvRows(dir / "out"))
    if (c.frontier) csvFrontier.push_back(c);
  std::stable_sort(csvFrontier.begin(), csvFrontier.end(), [](auto& a, auto& b) { return a.ms < b.ms; });
  ASSERT_FALSE(printed.empty()) << r.out;
  ASSERT_EQ(printed.size(), csvFrontier.size()) << r.out;
  for (size_t i = 0; i < printed.size(); ++i) {
    EXPECT_EQ(std::get<0>(printed[i]), csvFrontier[i].variant);
    EXPECT_NEAR(std::get<1>(printed[i]), csvFrontier[i].ms, 1e-3);    // printed with 3 decimals
    EXPECT_NEAR(std::get<2>(printed[i]), csvFrontier[i].rmse, 1e-5);  // printed with 5 decimals
  }
  // The report, rendered by headless Chromium: its frontier rows, in order, are the CSV's.
  const auto profile = test::freshTempDir("sweep-chromium");
  const std::string cmd = "chromium --headless --no-sandbox --disable-gpu --user-data-dir=" + profile.string() +
                          " --dump-dom file://" + (dir / "out/report.html").string() + " 2>/dev/null";
  FILE* p = ::popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string dom;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) dom.append(buf, n);
  ASSERT_EQ(::pclose(p), 0) << "chromium failed (scripts/install-deps.sh installs it)";
  const std::regex tr(
      R"re(<tr class="frontier-row" data-case="[^"]*" data-key="([0-9a-f]+)"><td>\d+(?: <span class="tie"[^>]*>=</span>)?</td><td>([^<]+)</td>)re");
  std::vector<std::pair<std::string, std::string>> reported;
  for (auto it = std::sregex_iterator(dom.begin(), dom.end(), tr); it != std::sregex_iterator(); ++it)
    reported.emplace_back((*it)[1], (*it)[2]);
  ASSERT_EQ(reported.size(), csvFrontier.size()) << dom.substr(0, 2000);
  for (size_t i = 0; i < reported.size(); ++i) {
    EXPECT_EQ(reported[i].first, csvFrontier[i].key);
    EXPECT_EQ(reported[i].second, csvFrontier[i].variant);
  }
  EXPECT_NE(dom.find("plots/case0.svg"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "out/plots/case0.svg"));
  EXPECT_TRUE(std::filesystem::exists(dir / "out/plots/case0.png"));
}

TEST(SweepCli, NoFrontierRowIsDominatedAndInvalidOnesAreCounted) {
  const auto dir = writeSweep("sweep-dominated", tinySweep());
  const test::CliResult r = runSweep(dir, "out");
  ASSERT_EQ(r.code, 0) << r.err;
  const sweep::Results res = sweep::readResultsJson(dir / "out/results.json");
  ASSERT_EQ(res.rows.size(), 4u);
  for (const auto& row : res.rows)  // each row stores its filter normalized (printFilter)
    EXPECT_EQ(row.normalizedText.rfind("filter ", 0), 0u) << row.normalizedText;
  const auto front = sweep::frontiers(res.rows).at(0);
  for (size_t i : front)
    for (const auto& other : res.rows) EXPECT_FALSE(sweep::dominates(other, res.rows[i])) << res.rows[i].variant;
  const json j = results(dir / "out");
  for (size_t i = 0; i < res.rows.size(); ++i)  // results.json marks exactly those rows
    EXPECT_EQ(j["rows"][i]["frontier"].get<bool>(), std::find(front.begin(), front.end(), i) != front.end());
  ASSERT_EQ(res.skipped.size(), 1u);
  EXPECT_EQ(res.skipped[0].variant, "point_pcss");
  EXPECT_EQ(res.skipped[0].code, "E0416");
  EXPECT_NE(r.err.find("skipped 1 variant(s): 1 x E0416"), std::string::npos) << r.err;
}

// `shaders: ["specialized", "generic"]`: every valid variant runs both ways; each pair's
// specialized / generic ratio is the quotient of its two rows' times, in the CSV, the JSON and
// on the terminal; the generic twin computes the same visibility (same RMSE within 1e-3).
TEST(SweepCli, GenericShadersRunBesideSpecializedWithTheirRatio) {
  const auto dir = writeSweep("sweep-generic", tinySweep(R"(["specialized", "generic"])"));
  const test::CliResult r = runSweep(dir, "out");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = results(dir / "out");
  std::map<std::string, int> codes;
  for (const auto& s : j["skipped"]) ++codes[s["code"].get<std::string>()];
  EXPECT_EQ(codes["E0416"], 2);  // the invalid variant, in both kinds: the checker speaks first
  EXPECT_EQ(codes.size(), 1u);
  ASSERT_EQ(j["rows"].size(), 8u);
  std::map<std::string, const json*> specialized;
  for (const auto& row : j["rows"])
    if (row["shader"] == "specialized") specialized[row["variant"].get<std::string>()] = &row;
  int pairs = 0;
  for (const auto& row : j["rows"]) {
    ASSERT_TRUE(row.contains("specialized_over_generic")) << row["variant"];
    if (row["shader"] != "generic") continue;
    std::string label = row["variant"].get<std::string>();
    label = label.substr(0, label.rfind(" (generic)"));
    ASSERT_TRUE(specialized.count(label)) << label;
    const json& s = *specialized[label];
    EXPECT_NEAR(row["specialized_over_generic"].get<double>(),
                s["total_ms"].get<double>() / row["total_ms"].get<double>(), 1e-9);
    EXPECT_EQ(s["specialized_over_generic"], row["specialized_over_generic"]);
    EXPECT_NEAR(row["metrics"]["rmse"].get<double>(), s["metrics"]["rmse"].get<double>(), 1e-3) << label;
    EXPECT_NE(row["content_hash"], s["content_hash"]);  // a different shader
    EXPECT_NE(r.out.find("  " + label + " "), std::string::npos) << r.out;
    ++pairs;
  }
  EXPECT_EQ(pairs, 4);
  EXPECT_NE(r.out.find("specialized vs generic two_planes"), std::string::npos) << r.out;
  // The CSV's specialized_over_generic column is the same ratio, on both rows of a pair.
  std::istringstream csv(test::readFile(dir / "out/results.csv"));
  std::string line;
  std::getline(csv, line);
  const auto fields = [](const std::string& l) {
    std::vector<std::string> f(1);  // RFC 4180: a comma inside quotes is the field's
    bool quoted = false;
    for (char c : l) {
      if (c == '"') quoted = !quoted;
      if (c == ',' && !quoted)
        f.emplace_back();
      else
        f.back().push_back(c);
    }
    return f;
  };
  const std::vector<std::string> header = fields(line);
  const auto column = std::find(header.begin(), header.end(), "specialized_over_generic");
  ASSERT_NE(column, header.end()) << line;
  const size_t at = size_t(column - header.begin());
  int filled = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = fields(line);
    ASSERT_EQ(f.size(), header.size()) << line;
    filled += !f[at].empty();
  }
  EXPECT_EQ(filled, 8);
}

TEST(SweepCli, InterruptedSweepRerunsNothingFinished) {
  const auto dir = writeSweep("sweep-resume", tinySweep());
  const test::CliResult killed = runSweep(dir, "out", "", "SHADOWC_SWEEP_STOP_AFTER=2");
  EXPECT_EQ(killed.code, 3) << killed.err;  // ended abruptly, like a kill: no results written
  EXPECT_FALSE(std::filesystem::exists(dir / "out/results.json"));
  size_t cached = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir / "out/cache"))
    cached += e.path().extension() == ".json";
  EXPECT_EQ(cached, 2u);
  const test::CliResult resumed = runSweep(dir, "out");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const json j = results(dir / "out");
  EXPECT_EQ(j["stats"]["cached"], 2);
  EXPECT_EQ(j["stats"]["ran"], 2);  // only the two that had not finished
  const test::CliResult again = runSweep(dir, "out");
  ASSERT_EQ(again.code, 0);
  EXPECT_EQ(results(dir / "out")["stats"]["ran"], 0);
  // The sibling: a fresh folder runs all four, so the counts above are the cache's doing.
  const test::CliResult fresh = runSweep(dir, "fresh");
  ASSERT_EQ(fresh.code, 0);
  EXPECT_EQ(results(dir / "fresh")["stats"]["ran"], 4);
}

// Everything of a row but its times, their statistics and the busy warning (and the images'
// names, which carry the same key).
std::string measured(const sweep::Row& r) {
  json j = sweep::rowToJson(r);
  j.erase("total_ms");
  j.erase("total");
  j.erase("busy_warning");
  j.erase("passes");
  return j.dump();
}

TEST(SweepCli, ShardsMergedEqualOneProcess) {
  const auto dir = writeSweep("sweep-shards", tinySweep());
  ASSERT_EQ(runSweep(dir, "one").code, 0);
  for (int i = 0; i < 2; ++i)
    ASSERT_EQ(runSweep(dir, "s" + std::to_string(i), "--shard " + std::to_string(i) + "/2").code, 0);
  const test::CliResult m = test::runShadowc("sweep merge " + (dir / "s0").string() + " " + (dir / "s1").string() +
                                             " -o " + (dir / "merged").string());
  ASSERT_EQ(m.code, 0) << m.err;
  const sweep::Results one = sweep::readResultsJson(dir / "one/results.json");
  sweep::Results merged = sweep::readResultsJson(dir / "merged/results.json");
  const sweep::Results s0 = sweep::readResultsJson(dir / "s0/results.json");
  EXPECT_GT(s0.rows.size(), 0u);
  EXPECT_LT(s0.rows.size(), one.rows.size());  // a real slice
  ASSERT_EQ(merged.rows.size(), one.rows.size());
  for (size_t i = 0; i < one.rows.size(); ++i) EXPECT_EQ(measured(merged.rows[i]), measured(one.rows[i]));
  ASSERT_EQ(merged.skipped.size(), one.skipped.size());
  // Same frontier, times aside: with the one-process times and intervals the merged rows give its
  // frontier.
  for (size_t i = 0; i < one.rows.size(); ++i) {
    merged.rows[i].totalMs = one.rows[i].totalMs;
    merged.rows[i].total = one.rows[i].total;  // the intervals decide ties (docs/sweep.md "Ties")
  }
  EXPECT_EQ(sweep::frontiers(merged.rows), sweep::frontiers(one.rows));
  EXPECT_TRUE(std::filesystem::exists(dir / "merged/report.html"));
}

// Every place that shows the intervals says the coverage the runs give (docs/sweep.md "Ties"):
// [min, max] of 5 runs holds the median with probability 1 - 2^-4 = 93.75 %, of 2 runs 50 %, and
// the terminal's heading, report.html and the plot's legend say so, never "95 %".
TEST(SweepCli, EveryIntervalLabelSaysItsCoverage) {
  for (const auto& [runs, label] : {std::pair<int, std::string>{5, "93.7 % interval"}, {2, "50 % interval"}}) {
    std::string text = tinySweep();
    const std::string two = "\"runs\": 2";
    ASSERT_NE(text.find(two), std::string::npos);
    text.replace(text.find(two), two.size(), "\"runs\": " + std::to_string(runs));
    const auto dir = writeSweep("sweep-coverage-" + std::to_string(runs), text);
    const test::CliResult r = runSweep(dir, "out");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string report = test::readFile(dir / "out/report.html");
    const std::string plot = test::readFile(dir / "out/plots/case0.gp");
    EXPECT_NE(r.out.find(label), std::string::npos) << runs << " runs:\n" << r.out;
    EXPECT_NE(report.find(label), std::string::npos) << runs << " runs";
    EXPECT_NE(plot.find("variants (" + label + " of the median time)"), std::string::npos) << plot;
    for (const std::string* shown : {&r.out, &report, &plot})
      EXPECT_EQ(shown->find("95%"), std::string::npos) << runs << " runs: a label claims 95 %";
    ASSERT_TRUE(std::filesystem::exists(dir / "out/plots/case0.svg"));
    EXPECT_NE(test::readFile(dir / "out/plots/case0.svg").find(label), std::string::npos) << "the drawn legend";
  }
}

// "counters": true keeps each row's exact work beside its time (docs/sweep.md "Work counts"):
// Poisson PCF reads one depth texel a tap, so pcf[taps=4] is 4 fetches a receiver and
// pcf[taps=16] 16, in the JSON (totals = per receiver x receivers), the CSV and the report.
// Sibling: the same sweep without the key carries no counts and no column.
TEST(SweepCli, CountersKeepEachRowsExactWork) {
  std::string text = tinySweep();
  const std::string warm = "\"warmup\": 1";
  ASSERT_NE(text.find(warm), std::string::npos);
  text.replace(text.find(warm), warm.size(), warm + ", \"counters\": true");
  const auto dir = writeSweep("sweep-counters", text);
  const test::CliResult r = runSweep(dir, "out");
  ASSERT_EQ(r.code, 0) << r.err;
  const sweep::Results res = sweep::readResultsJson(dir / "out/results.json");
  std::map<std::string, uint64_t> fetches;
  for (const sweep::Row& row : res.rows) {
    ASSERT_TRUE(row.work.has_value()) << row.variant;
    ASSERT_GT(row.work->receivers(), 0u) << row.variant;
    fetches[row.variant] = row.work->total("depth_fetches").value_or(0);
    if (row.variant.rfind("pcf[", 0) == 0) {
      const uint64_t taps = row.variant == "pcf[taps=4]" ? 4 : 16;
      EXPECT_EQ(fetches[row.variant], taps * row.work->receivers()) << row.variant;
    }
  }
  ASSERT_EQ(fetches.count("pcf[taps=4]") + fetches.count("pcf[taps=16]"), 2u);
  const std::string csv = test::readFile(dir / "out/results.csv");
  EXPECT_NE(csv.find(",work_per_receiver,predicted_ms\n"), std::string::npos);
  EXPECT_NE(csv.find("depth_fetches=16"), std::string::npos) << csv;
  const std::string report = test::readFile(dir / "out/report.html");
  EXPECT_NE(report.find("shade work per receiver"), std::string::npos);
  EXPECT_NE(report.find("depth_fetches=4"), std::string::npos);
  // Sibling: without "counters" nothing is counted.
  const auto plain = writeSweep("sweep-no-counters", tinySweep());
  ASSERT_EQ(runSweep(plain, "out").code, 0);
  for (const sweep::Row& row : sweep::readResultsJson(plain / "out/results.json").rows)
    EXPECT_FALSE(row.work.has_value()) << row.variant;
  EXPECT_EQ(test::readFile(plain / "out/report.html").find("shade work per receiver"), std::string::npos);
}

// The intervals survive a merge: shards that find the one-process run's rows in their cache
// (its cache folder copied into theirs) merge into exactly its times, intervals and frontier
// marks, compared as they are, nothing overwritten.
TEST(SweepCli, ShardsMergedKeepTheOneProcessIntervals) {
  const auto dir = writeSweep("sweep-shard-intervals", tinySweep());
  ASSERT_EQ(runSweep(dir, "one").code, 0);
  for (int i = 0; i < 2; ++i) {
    const std::string shard = "s" + std::to_string(i);
    std::filesystem::create_directories(dir / shard);
    std::filesystem::copy(dir / "one/cache", dir / shard / "cache", std::filesystem::copy_options::recursive);
    ASSERT_EQ(runSweep(dir, shard, "--shard " + std::to_string(i) + "/2").code, 0);
  }
  const test::CliResult m = test::runShadowc("sweep merge " + (dir / "s0").string() + " " + (dir / "s1").string() +
                                             " -o " + (dir / "merged").string());
  ASSERT_EQ(m.code, 0) << m.err;
  const sweep::Results one = sweep::readResultsJson(dir / "one/results.json");
  const sweep::Results merged = sweep::readResultsJson(dir / "merged/results.json");
  EXPECT_EQ(results(dir / "s0")["stats"]["ran"], 0) << "the shard ran rows: its times are its own";
  ASSERT_EQ(merged.rows.size(), one.rows.size());
  for (size_t i = 0; i < one.rows.size(); ++i) {
    ASSERT_GT(one.rows[i].total.n, 0) << one.rows[i].variant << ": no interval to compare";
    EXPECT_EQ(merged.rows[i].totalMs, one.rows[i].totalMs) << one.rows[i].variant;
    EXPECT_EQ(rt::toJson(merged.rows[i].total).dump(), rt::toJson(one.rows[i].total).dump()) << one.rows[i].variant;
  }
  EXPECT_EQ(sweep::frontiers(merged.rows), sweep::frontiers(one.rows));
  const auto mergedMarks = sweep::frontierMarks(merged.rows), oneMarks = sweep::frontierMarks(one.rows);
  for (size_t i = 0; i < one.rows.size(); ++i) {
    EXPECT_EQ(mergedMarks[i].membership, oneMarks[i].membership) << one.rows[i].variant;
    EXPECT_EQ(mergedMarks[i].tiedWith, oneMarks[i].tiedWith) << one.rows[i].variant;
  }
}

}  // namespace
}  // namespace shadowc

namespace shadowc {
namespace {

// Bad input: one located message, a non-zero exit, nothing run. The sibling is every test above.
TEST(SweepCli, BadDescriptionIsOneLocatedError) {
  const auto dir = writeSweep("sweep-bad", R"({"filters": ["no_such.shadow"], "scenes": ["two_planes"]})");
  const test::CliResult r = runSweep(dir, "out");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("sweep.json: error: filters[0]: cannot read"), std::string::npos) << r.err;
  size_t errors = 0;
  for (size_t at = 0; (at = r.err.find("error:", at)) != std::string::npos; ++at) ++errors;
  EXPECT_EQ(errors, 1u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out/results.json"));
  const test::CliResult shard = runSweep(writeSweep("sweep-bad-shard", tinySweep()), "out", "--shard 2/2");
  EXPECT_EQ(shard.code, 1);
  EXPECT_NE(shard.err.find("--shard '2/2': need 0 <= I < N"), std::string::npos) << shard.err;
}

}  // namespace
}  // namespace shadowc

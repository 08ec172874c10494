// A sweep as a 2-task Slurm job array on a single-node Slurm started here (local_slurm.sh:
// munged, slurmctld, slurmd on 127.0.0.1, stopped and removed at the end), merged, equals the
// same sweep run in one process: same rows (keys, specs, content hashes, metrics), same skipped
// variants, same frontier (times aside: each run measures its own times). A cluster that does
// not come up fails the test within local_slurm.sh's start bound, with the daemons' own errors.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/test_support.h"
#include "sweep/pareto.h"
#include "sweep/results_io.h"

namespace shadowc {
namespace {

std::string shell(const std::string& cmd, int* code) {
  FILE* p = ::popen(cmd.c_str(), "r");
  std::string out;
  if (!p) return out;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  const int status = ::pclose(p);
  *code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

std::string lastLine(std::string s) {
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s.substr(s.rfind('\n') + 1);  // npos + 1 == 0: the whole text when it is one line
}

class LocalSlurm : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTempDir("slurm");
    int code = 0;
    const std::string out = shell(script_ + " start " + (dir_ / "cluster").string() + " 2>&1", &code);
    ASSERT_EQ(code, 0) << out;
    // The last line: munged may warn before it (e.g. that the host name does not resolve).
    conf_ = lastLine(out);
    ASSERT_TRUE(std::filesystem::exists(conf_)) << out;
  }
  std::string daemonLogs() {
    int code = 0;
    return shell(script_ + " logs " + (dir_ / "cluster").string() + " 2>&1", &code);
  }
  void TearDown() override {
    int code = 0;
    shell(script_ + " stop " + (dir_ / "cluster").string() + " 2>&1", &code);
    EXPECT_EQ(code, 0);
    EXPECT_FALSE(std::filesystem::exists(dir_ / "cluster"));  // daemons gone, state removed
    std::filesystem::remove_all(dir_);
  }
  std::filesystem::path dir_;
  std::string conf_;
  const std::string script_ = (test::sourceDir() / "tests/slurm/local_slurm.sh").string();
};

std::string measured(const sweep::Row& r) {
  nlohmann::ordered_json j = sweep::rowToJson(r);
  j.erase("total_ms");
  j.erase("total");
  j.erase("busy_warning");
  j.erase("passes");
  return j.dump();
}

// Its ~13 s are Slurm's (the daemons, scheduling, sbatch --wait's polling), not the sweep's:
// the rows are already the smallest that run (32² screen, 256² map, 2² samples, 2 runs).
TEST_F(LocalSlurm, JobArrayShardsMergedEqualOneProcess) {
  const std::string f = (test::sourceDir() / "samples/filters").string();
  std::ofstream(dir_ / "sweep.json") << R"J({
  "name": "slurm_tiny",
  "filters": [")J" + f + R"J(/hard_constant_bias.shadow",
    {"name": "pcf", "file": ")J" + f + R"J(/pcf_poisson16.shadow", "set": {"sampling": "poisson(${taps})"}},
    {"name": "point_pcss", "file": ")J" + f +
                                            R"J(/pcss_poisson.shadow", "set": {"light": "point"}}],
  "params": {"taps": [4, 16, 32]},
  "scenes": ["two_planes"],
  "screen": 32, "map": 256, "reference_samples": 2, "runs": 2, "warmup": 1
})J";
  const std::string spec = (dir_ / "sweep.json").string();
  const auto t0 = std::chrono::steady_clock::now();
  const test::CliResult one = test::runShadowc("sweep " + spec + " -o " + (dir_ / "one").string());
  ASSERT_EQ(one.code, 0) << one.err;
  const auto oneS = std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - t0).count();
  // Bound on the array: its 2 tasks may run one after the other (each asks for 2 CPUs), each
  // doing no more than the whole sweep did in one process, doubled for the load changing in
  // between; plus one periodic scheduling pass (sched_interval, 60 s) for a task the
  // event-driven pass missed, and sbatch --wait's longest poll (32 s).
  const long waitS = 2 * 2 * (oneS + 1) + 60 + 32;
  int code = 0;
  const std::string sbatch =
      shell("SLURM_CONF=" + conf_ + " SHADOWC=" + test::shadowcBinary() + " timeout " + std::to_string(waitS) +
                " sbatch --array=0-1 --wait -o " + (dir_ / "task-%a.log").string() + " " +
                (test::sourceDir() / "scripts/slurm/sweep.sbatch").string() + " " + spec + " " +
                (dir_ / "shards").string() + " 2>&1",
            &code);
  ASSERT_EQ(code, 0) << (code == 124 ? "sbatch --wait did not finish within " + std::to_string(waitS) + " s\n" : "")
                     << sbatch << test::readFile(dir_ / "task-0.log") << test::readFile(dir_ / "task-1.log")
                     << daemonLogs();
  const test::CliResult merge =
      test::runShadowc("sweep merge " + (dir_ / "shards/shard-0").string() + " " + (dir_ / "shards/shard-1").string() +
                       " -o " + (dir_ / "merged").string());
  ASSERT_EQ(merge.code, 0) << merge.err;

  const sweep::Results s0 = sweep::readResultsJson(dir_ / "shards/shard-0/results.json");
  const sweep::Results s1 = sweep::readResultsJson(dir_ / "shards/shard-1/results.json");
  sweep::Results merged = sweep::readResultsJson(dir_ / "merged/results.json");
  const sweep::Results single = sweep::readResultsJson(dir_ / "one/results.json");
  EXPECT_EQ(s0.shard, "0/2");
  EXPECT_EQ(s1.shard, "1/2");
  EXPECT_GT(s0.rows.size(), 0u);  // both tasks did real work
  EXPECT_GT(s1.rows.size(), 0u);
  ASSERT_EQ(single.rows.size(), 4u);
  ASSERT_EQ(merged.rows.size(), single.rows.size());
  for (size_t i = 0; i < single.rows.size(); ++i) EXPECT_EQ(measured(merged.rows[i]), measured(single.rows[i]));
  ASSERT_EQ(merged.skipped.size(), 1u);
  EXPECT_EQ(merged.skipped[0].code, single.skipped.at(0).code);
  EXPECT_EQ(merged.skipped[0].message, single.skipped[0].message);
  for (size_t i = 0; i < single.rows.size(); ++i) {
    merged.rows[i].totalMs = single.rows[i].totalMs;
    merged.rows[i].total = single.rows[i].total;  // the intervals decide ties (docs/sweep.md "Ties")
  }
  EXPECT_EQ(sweep::frontiers(merged.rows), sweep::frontiers(single.rows));
}

}  // namespace
}  // namespace shadowc

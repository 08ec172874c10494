// `shadowc sweep SPEC -o DIR`: what accuracy costs in time (docs/sweep.md). Expands a sweep
// description into filter variants, compiles them through the driver, runs each on each scene
// through the run harness, and writes results.csv/.json, plots and report.html; prints the
// Pareto frontier per case. `shadowc sweep merge DIR... -o OUT` joins shard outputs.
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "runtime/executor/pass_forms.h"
#include "sweep/cost_profile.h"
#include "sweep/expand.h"
#include "sweep/frontier_table.h"
#include "sweep/merge.h"
#include "sweep/outputs.h"
#include "sweep/shader_ratio.h"
#include "sweep/sweep_run.h"
#include "sweep/sweep_spec.h"

namespace shadowc::cli {
namespace {

struct SweepArgs {
  std::string spec, out, shard = "0/1", device, progress = "auto", costProfile;
  int jobs = 0;
  bool validation = false, noReferenceCache = false, counters = false;
  std::vector<std::string> mergeDirs;
  std::string mergeOut;
};

void printSkipped(const sweep::Results& r) {
  if (r.skipped.empty()) return;
  std::map<std::string, size_t> byCode;
  for (const auto& s : r.skipped) ++byCode[s.code];
  std::string counts;
  for (const auto& [code, n] : byCode) counts += fmt::format("{}{} x {}", counts.empty() ? "" : ", ", n, code);
  fmt::print(stderr, "sweep: skipped {} variant(s): {}\n", r.skipped.size(), counts);
  for (const auto& s : r.skipped) fmt::print(stderr, "  {}: {}\n", s.variant, s.message);
}

// The tables on stdout, the files after them.
int finish(const sweep::Results& r, const std::filesystem::path& dir) {
  const std::string warning = sweep::writeOutputs(dir, r);
  std::fflush(stderr);
  fmt::print("{}", sweep::formatFrontierTables(r));
  fmt::print("{}", sweep::formatShaderRatios(r));
  std::set<std::string> clocks;
  int rejected = 0;
  for (const sweep::Row& row : r.rows) {
    clocks.insert(row.clock);
    rejected += row.rejectedRuns;
  }
  if (!r.rows.empty())
    fmt::print("sweep: timed on {}, {} run(s) rejected as implausible\n", fmt::join(clocks, " and "), rejected);
  fmt::print("sweep: {} rows ({} ran, {} cached), {} skipped -> {}/results.csv, results.json, report.html{}\n",
             r.rows.size(), r.stats.ran, r.stats.cached, r.skipped.size(), dir.string(),
             warning.empty() ? ", plots/" : "");
  std::fflush(stdout);
  if (!warning.empty()) fmt::print(stderr, "sweep: warning: {}\n", warning);
  return 0;
}

int runSweepCommand(const SweepArgs& a) {
  if (a.spec.empty()) throw std::invalid_argument("sweep: give a sweep description (samples/sweeps/default.json)");
  sweep::SweepSpec spec = sweep::loadSweepSpec(a.spec);
  // A profile prices a row from its work counts, so it needs them; it is read before anything runs.
  std::optional<sweep::CostProfile> profile;
  if (!a.costProfile.empty()) profile = sweep::resolveCostProfile(a.costProfile);
  if (a.counters || profile) spec.counters = true;
  sweep::SweepOptions o;
  o.outDir = a.out;
  o.shard = sweep::parseShard(a.shard);
  o.jobs = a.jobs;
  o.device = a.device;
  o.validation = a.validation;
  o.useReferenceCache = !a.noReferenceCache;
  o.tty = a.progress == "bar" ? 1 : a.progress == "lines" ? 0 : -1;
  if (const char* stop = std::getenv("SHADOWC_SWEEP_STOP_AFTER")) o.stopAfter = std::strtoul(stop, nullptr, 10);
  sweep::SweepOutcome outcome = sweep::runSweep(spec, o, stderr);
  if (profile) {
    size_t unpriced = 0;
    for (sweep::Row& row : outcome.results.rows) {
      row.predictedMs = profile->frameMs(sweep::costSample(row));
      unpriced += row.predictedMs ? 0 : 1;
    }
    fmt::print(stderr, "sweep: ranked by the predicted frame on {} ({}){}\n", profile->device, a.costProfile,
               unpriced ? fmt::format("; {} row(s) it cannot price (a pass it was not fitted on) are left off the "
                                      "frontier",
                                      unpriced)
                        : std::string());
  }
  printSkipped(outcome.results);
  const int rc = finish(outcome.results, o.outDir);
  // No row is no answer: a sweep whose every variant was refused (or failed) must not exit 0.
  if (outcome.results.rows.empty() && !outcome.results.skipped.empty()) {
    fmt::print(stderr, "shadowc: error: nothing ran: all {} variant(s) of sweep '{}'{} were skipped (listed above)\n",
               outcome.results.skipped.size(), spec.name, o.shard.count > 1 ? " (shard " + a.shard + ")" : "");
    return 1;
  }
  if (outcome.validationMessages > 0) {
    fmt::print(stderr, "shadowc: error: the validation layer reported {} message(s)\n", outcome.validationMessages);
    return 1;
  }
  return rc;
}

}  // namespace

CommandRunner registerSweep(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  CLI::App* sub = app.add_subcommand("sweep",
                                     "Run a grid of filter variants over scenes: time vs error, the Pareto "
                                     "frontier, CSV/JSON, plots and an HTML report (docs/sweep.md)");
  sub->add_option("spec", a->spec, "Sweep description (.json, docs/sweep.md)");
  sub->add_option("-o,--out", a->out, "Output folder: results, plots, report.html, and the cache that resumes a sweep")
      ->required();
  addRenamedOption(sub, "--output", "-o/--out");
  sub->add_option("--shard", a->shard, "Run only slice I of N (jobs j with j mod N == I), e.g. 0/4")
      ->capture_default_str();
  sub->add_option("-j,--jobs", a->jobs, "Threads that compile variants (0 = one per hardware thread)")
      ->capture_default_str();
  sub->add_option("--device", a->device, "Vulkan device: index or name substring (default: llvmpipe)");
  sub->add_flag("--validate", a->validation, "Enable the Khronos validation layer; any message fails the sweep");
  sub->add_flag("--counters", a->counters,
                "Also count every row's work (as \"counters\": true; docs/manifest.md \"Work counters\")");
  sub->add_option("--cost-profile", a->costProfile,
                  "Rank by the frame this device cost profile predicts from the rows' work counts (docs/cost.md)");
  sub->add_flag("--no-reference-cache", a->noReferenceCache, "Trace every Embree reference again (no cache)");
  addRenamedOption(sub, "--no-cache", "--no-reference-cache", /*takesValue=*/false);
  sub->add_option("--progress", a->progress, "Progress display: auto (bar on a terminal), bar, lines")
      ->check(CLI::IsMember({"auto", "bar", "lines"}))
      ->capture_default_str();
  CLI::App* merge = sub->add_subcommand("merge", "Merge sweep folders (shards) by content hash into one result set");
  merge->add_option("dirs", a->mergeDirs, "Sweep output folders")->required();
  merge->add_option("-o,--out", a->mergeOut, "Merged output folder")->required();
  // `-o` belongs to merge when merge is given: the parent's is then not required.
  merge->preparse_callback([sub](size_t) { sub->get_option("--out")->required(false); });
  return [a, merge] {
    if (merge->parsed()) {
      std::vector<std::filesystem::path> dirs(a->mergeDirs.begin(), a->mergeDirs.end());
      const sweep::Results r = sweep::mergeResults(dirs, a->mergeOut);
      fmt::print(stderr, "sweep: merged {} folders: {} rows, {} skipped\n", dirs.size(), r.rows.size(),
                 r.skipped.size());
      printSkipped(r);
      return finish(r, a->mergeOut);
    }
    (void)rt::checkedPassForm("");  // SHADOWC_PASS_FORM misspelt: one message before any row runs
    return runSweepCommand(*a);
  };
}

}  // namespace shadowc::cli

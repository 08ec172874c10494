// shadowc stability: the numerical stability suite (validation/stability, docs/stability.md).
// Runs the hard cases on lavapipe for their filters (or for --filter F), optionally randomized
// filters, prints/writes a Markdown table and JSON; exit 1 when any row fails.
#include <fmt/core.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "driver/driver.h"
#include "runtime/images/atomic_file.h"
#include "runtime/vulkan/vulkan_context.h"
#include "validation/stability/stability_report.h"
#include "validation/stability/stability_suite.h"

namespace shadowc::cli {

CommandRunner registerStability(CLI::App& app) {
  struct Options {
    std::string filter, caseName, report, json;
    int random = 0;
    uint64_t seed = 1;
    bool list = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("stability", "Run the numerical stability suite (docs/stability.md)");
  sub->add_option("--filter", opt->filter, "Run the cases that apply to this filter description instead");
  sub->add_option("--case", opt->caseName, "Run only the case with this name");
  sub->add_option("--report", opt->report, "Write the Markdown report (docs/stability.md form) here");
  sub->add_option("--json", opt->json, "Write the results as JSON here");
  sub->add_option("--random", opt->random, "Also run N random valid filter descriptions")->check(CLI::Range(0, 100000));
  sub->add_option("--seed", opt->seed, "Seed of the random filters (reproducible)");
  sub->add_flag("--list", opt->list, "List the case names and exit");
  return [opt]() -> int {
    using namespace shadowc::validation;
    const auto& cases = stabilityCases();
    if (opt->list) {
      for (const auto& c : cases) fmt::print("{}\t{}\t{}\n", c.name, c.label, c.what);
      return 0;
    }
    std::optional<FilterSpec> userSpec;
    if (!opt->filter.empty()) {
      driver::Options check;
      check.stopAfter = driver::Stage::Check;
      const driver::Result loaded = driver::compileFile(opt->filter, check);
      if (!loaded.spec) {
        fmt::print(stderr, "{}", loaded.log);
        return 1;
      }
      userSpec = *loaded.spec;
    }
    bool known = opt->caseName.empty();
    for (const auto& c : cases) known = known || c.name == opt->caseName;
    if (!known) {
      fmt::print(stderr, "shadowc: error: unknown case '{}' (shadowc stability --list)\n", opt->caseName);
      return 2;
    }
    rt::VulkanContext vk;
    SuiteContext ctx{vk};
    std::vector<CaseResult> results;
    for (const auto& c : cases) {
      if (!opt->caseName.empty() && c.name != opt->caseName) continue;
      for (CaseResult& r : runCase(ctx, c, userSpec ? &*userSpec : nullptr)) {
        fmt::print("{:<34} {:<28} {}\n", r.caseName, r.filter + (r.naive ? " (naive)" : ""),
                   r.pass ? "ok" : "FAILED: " + r.detail);
        std::fflush(stdout);
        results.push_back(std::move(r));
      }
    }
    for (int i = 0; i < opt->random; ++i) {
      CaseResult r = runRandomFilter(ctx, opt->seed, i);
      fmt::print("{:<34} {:<28} {}\n", r.caseName, r.filter, r.pass ? "ok" : "FAILED: " + r.detail);
      if (!r.pass) fmt::print("  seed {} index {}; filter:\n{}\n", opt->seed, i, randomFilterSource(opt->seed, i));
      results.push_back(std::move(r));
    }
    size_t failed = 0;
    for (const auto& r : results) failed += r.pass ? 0 : 1;
    const std::string table = markdownTable(results);
    if (opt->report.empty()) fmt::print("\n{}", table);
    if (!opt->report.empty()) rt::writeFileAtomically(opt->report, stabilityReport(results));
    if (!opt->json.empty()) rt::writeFileAtomically(opt->json, resultsJson(results).dump(2) + "\n");
    fmt::print("{} rows, {} failed\n", results.size(), failed);
    return failed ? 1 : 0;
  };
}

}  // namespace shadowc::cli

// `shadowc cost-profile RESULTS... -o PROFILE.json`: fits a device cost profile (docs/cost.md,
// sweep/cost_profile.h) to the per-pass medians and work counts of measured sweeps, and says how
// well it predicts their frames; with --profile, only says how well an existing one does.
#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "runtime/images/atomic_file.h"
#include "sweep/cost_profile.h"

namespace shadowc::cli {

namespace {

std::filesystem::path resultsFile(const std::string& arg) {
  std::filesystem::path p(arg);
  if (std::filesystem::is_directory(p)) p /= "results.json";
  if (!std::filesystem::exists(p)) throw std::runtime_error(p.string() + ": error: no such sweep results");
  return p;
}

std::vector<sweep::CostSample> readAll(const std::vector<std::string>& args) {
  std::vector<sweep::CostSample> out;
  for (const std::string& a : args) {
    std::vector<sweep::CostSample> s = sweep::readCostSamples(resultsFile(a));
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

void printQuality(const std::string& what, const sweep::FitQuality& q) {
  if (q.priced == 0) {
    fmt::print("{}: no frame priced ({} without counts or with a pass the profile never saw)\n", what, q.unpriced);
    return;
  }
  fmt::print(
      "{}: {} frames, median |ln(predicted/measured)| {:.3f} ({:.2f}x), largest {:.2f}x, {} of {} ({:.1f} %) "
      "within 1.5x{}\n  worst: {}\n",
      what, q.priced, q.medianAbsLog, std::exp(q.medianAbsLog), std::exp(q.maxAbsLog), q.within, q.priced,
      100.0 * double(q.within) / double(q.priced),
      q.unpriced ? fmt::format(" ({} not priced: no counts)", q.unpriced) : std::string(), q.worst);
}

}  // namespace

CommandRunner registerCostProfile(CLI::App& app) {
  struct Options {
    std::vector<std::string> results, countsFrom, holdOut;
    std::string out, profile, device;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "cost-profile", "Fit a device cost profile to measured sweeps, or check one against them (docs/cost.md)");
  sub->add_option("results", o->results, "Sweep folders or results.json files (per-pass medians, work counts)")
      ->required();
  sub->add_option("-o,--output", o->out, "Write the fitted profile here (JSON)");
  sub->add_option("--profile", o->profile, "Check this profile against the results instead of fitting one");
  sub->add_option("--counts-from", o->countsFrom,
                  "Counted sweeps of the same variants and cases: counts for rows that have none");
  sub->add_option("--hold-out", o->holdOut, "Scene left out of the fit and predicted (repeatable)");
  sub->add_option("--device", o->device, "Device name recorded in the profile (default: the rows')");
  return [o]() -> int {
    if (o->out.empty() == o->profile.empty())
      throw std::invalid_argument("give exactly one of -o (fit a profile) and --profile (check one)");
    std::vector<sweep::CostSample> samples = readAll(o->results);
    if (samples.empty()) throw std::runtime_error("the sweep results hold no rows");
    if (!o->countsFrom.empty()) {
      const size_t missing = sweep::attachCounts(samples, readAll(o->countsFrom));
      if (missing) fmt::print("cost-profile: {} rows have no counts in --counts-from\n", missing);
    }
    if (!o->profile.empty()) {
      const sweep::CostProfile p = sweep::resolveCostProfile(o->profile);
      printQuality(fmt::format("{} ({})", o->profile, p.device), sweep::assessFit(p, samples));
      return 0;
    }
    std::vector<sweep::CostSample> fit, held;
    for (sweep::CostSample& s : samples)
      (std::find(o->holdOut.begin(), o->holdOut.end(), s.scene) != o->holdOut.end() ? held : fit).push_back(s);
    for (const std::string& h : o->holdOut)
      if (std::none_of(held.begin(), held.end(), [&](const sweep::CostSample& s) { return s.scene == h; }))
        throw std::invalid_argument("--hold-out " + h + ": no row of that scene in the results");
    const std::string device = !o->device.empty() ? o->device : fit.empty() ? std::string() : fit.front().device;
    std::string command = "shadowc cost-profile";
    for (const std::string& a : o->results) command += " " + a;
    for (const std::string& a : o->countsFrom) command += " --counts-from " + a;
    for (const std::string& a : o->holdOut) command += " --hold-out " + a;
    if (!o->device.empty()) command += " --device '" + o->device + "'";
    command += " -o " + o->out;
    const sweep::CostProfile p = sweep::fitCostProfile(fit, device, command);
    printQuality("fitted on", sweep::assessFit(p, fit));
    if (!held.empty()) printQuality("held out", sweep::assessFit(p, held));
    rt::writeFileAtomically(o->out, sweep::costProfileToJson(p));
    fmt::print("cost-profile: wrote {} ({} shade samples, {} prefilter passes)\n", o->out, p.shade.samples,
               p.passes.size());
    return 0;
  };
}

}  // namespace shadowc::cli

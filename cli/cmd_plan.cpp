// `shadowc plan --scene S [--scene S2 ...] --max-rmse E [--budget-ms T] -o FILE.shadow`: the
// cheapest filter description that meets the bound on every scene, confirmed against the ground
// truth (planning/planner.h, docs/planning.md). Also regenerates the model
// (`--calibrate samples/plan/model.json`) and the docs table (`--report docs/planning.md`) from
// one measured sweep (planning/calibration_sweep.h): run in process into --sweep-dir, or read
// from --from-sweep DIR; `--write-sweep FILE.json` writes that sweep's description.
#include <fmt/core.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/runs_option.h"
#include "planning/calibration.h"
#include "planning/calibration_sweep.h"
#include "planning/planner.h"
#include "runtime/executor/pass_forms.h"
#include "runtime/images/atomic_file.h"
#include "runtime/vulkan/vulkan_context.h"
#include "sweep/cost_profile.h"
#include "sweep/sweep_row.h"

namespace shadowc::cli {
namespace {

// A filter name from the output file's stem: [A-Za-z_][A-Za-z0-9_]*, at most 64 characters.
std::string filterNameFrom(const std::string& path) {
  std::string name;
  for (char ch : std::filesystem::path(path).stem().string())
    name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) name = "plan_" + name;
  return name.substr(0, 64);
}

}  // namespace

CommandRunner registerPlan(CLI::App& app) {
  struct Options {
    std::vector<std::string> scenes;
    double maxRmse = -1, budgetMs = -1;
    std::string out, model, calibrate, report, device, sweepDir = "plan-sweep", fromSweep, writeSweep, costProfile;
    uint32_t screen = 256, map = 1024, maxMap = 0;
    int samples = 16, warmup = 2;
    rt::RunCount runs = 5;
  };
  auto o = std::make_shared<Options>();
  // The command as the user could type it again (recorded in the written files).
  auto commandLine = [o] {
    std::string s = "shadowc plan";
    for (const std::string& sc : o->scenes) s += " --scene " + sc;
    if (o->maxRmse >= 0) s += fmt::format(" --max-rmse {:g}", o->maxRmse);
    if (o->budgetMs >= 0) s += fmt::format(" --budget-ms {:g}", o->budgetMs);
    if (!o->calibrate.empty()) s += " --calibrate " + o->calibrate;
    if (!o->report.empty()) s += " --report " + o->report;
    if (!o->writeSweep.empty()) s += " --write-sweep " + o->writeSweep;
    if (!o->fromSweep.empty())
      s += " --from-sweep " + o->fromSweep;
    else if (!o->calibrate.empty() || !o->report.empty())
      s += " --sweep-dir " + o->sweepDir;
    s += fmt::format(" --screen {} --map {} --samples {} --runs {} --warmup {}", o->screen, o->map, o->samples,
                     rt::toString(o->runs), o->warmup);
    if (o->maxMap > 0) s += fmt::format(" --max-map {}", o->maxMap);
    if (!o->costProfile.empty()) s += " --cost-profile " + o->costProfile;
    if (!o->out.empty()) s += " -o " + o->out;
    return s;
  };
  CLI::App* sub = app.add_subcommand("plan", "Cheapest filter description that meets an error bound on the scenes");
  sub->add_option("--scene", o->scenes, "Built-in scene name or scene .json file (repeat for several)");
  sub->add_option("--max-rmse", o->maxRmse, "Largest RMSE against the ground truth, on every scene");
  sub->add_option("--budget-ms", o->budgetMs, "Largest GPU time per frame (ms), on every scene");
  sub->add_option("-o,--out", o->out, "Write the planned filter description here");
  addRenamedOption(sub, "--output", "-o/--out");
  sub->add_option("--screen", o->screen, "Screen width and height in pixels")->capture_default_str();
  addRenamedOption(sub, "--size", "--screen");
  sub->add_option("--map", o->map, "Shadow-map side in texels")->capture_default_str();
  sub->add_option("--max-map", o->maxMap,
                  "Largest shadow-map side the plan may choose when no filter meets --max-rmse at --map (written as "
                  "the filter's `resolution`; docs/planning.md \"Map size\")");
  sub->add_option("--samples", o->samples, "Reference light samples per axis (N x N)")->capture_default_str();
  addRunsOption(sub, o->runs, "Timed runs per confirmation (the median counts)");
  sub->add_option("--warmup", o->warmup, "Untimed warm-up runs per confirmation")->capture_default_str();
  sub->add_option("--model", o->model, "Plan model JSON (default: the built-in samples/plan/model.json)");
  sub->add_option("--calibrate", o->calibrate,
                  "Fit the model from the calibration sweep (every candidate on the scenes, default: all built-ins) "
                  "and write it here");
  sub->add_option("--report", o->report,
                  "Write the table (plan vs everything on vs exhaustive) from the calibration sweep: between the "
                  "report markers of this file (docs/planning.md), or as the whole file");
  sub->add_option("--sweep-dir", o->sweepDir,
                  "Where --calibrate/--report run the calibration sweep (finished rows are cached: a rerun measures "
                  "only what changed)")
      ->capture_default_str();
  sub->add_option("--from-sweep", o->fromSweep,
                  "Read the calibration sweep's rows from DIR/results.json instead of running it");
  sub->add_option("--write-sweep", o->writeSweep,
                  "Write the calibration sweep's description (for `shadowc sweep FILE -o DIR`) and exit");
  sub->add_option("--device", o->device, "Vulkan device: index or name substring (default: llvmpipe)");
  sub->add_option("--cost-profile", o->costProfile,
                  "Time confirmations by this device cost profile's prediction from exact work counts (docs/cost.md)");
  return [o, commandLine]() -> int {
    if (o->screen == 0 || o->map == 0 || o->samples < 1 || !o->runs.any() || o->warmup < 0)
      throw std::invalid_argument("--screen, --map, --samples and --runs must be positive, --warmup >= 0");
    for (const std::string& s : o->scenes) (void)rt::loadScene(s);  // an unknown scene is one message, before any work
    (void)rt::checkedPassForm("");                                  // so is a misspelt SHADOWC_PASS_FORM
    auto log = [](const std::string& line) { fmt::print(stderr, "shadowc: {}\n", line); };
    const std::string command = commandLine();
    planning::CalibrationRequest c;
    c.scenes = o->scenes;
    c.screen = o->screen;
    c.map = o->map;
    c.samples = o->samples;
    c.runs = o->runs;
    c.warmup = o->warmup;
    c.command = command;
    c.log = log;
    if (!o->writeSweep.empty()) {
      rt::writeFileAtomically(o->writeSweep, planning::calibrationSweepJson(c));
      fmt::print("wrote the calibration sweep to {}\n", o->writeSweep);
      return 0;
    }
    if (!o->calibrate.empty() || !o->report.empty()) {
      const sweep::Results rows = o->fromSweep.empty() ? planning::calibrationRows(c, o->sweepDir, o->device)
                                                       : planning::sweepRows(o->fromSweep);
      rt::VulkanContext ctx(rt::VulkanOptions{o->device, false});
      // Calibrating starts from the rules' defaults (plan_model.h); a report alone reads the model.
      planning::PlanModel m = o->calibrate.empty() ? planning::loadModel(o->model) : planning::PlanModel{};
      const planning::SweepData data =
          planning::joinSweep(ctx, rows, o->fromSweep.empty() ? o->sweepDir : o->fromSweep, m.rules);
      for (const std::string& w : data.warnings) log("warning: " + w);
      if (!o->calibrate.empty()) {
        m = planning::modelFromSweep(data, command);
        rt::writeFileAtomically(o->calibrate, planning::modelToJson(m));
        fmt::print("wrote the plan model ({} variants, {} scenes) to {}\n", m.variants.size(), data.scenes.size(),
                   o->calibrate);
      }
      if (!o->report.empty()) {
        const std::string table = planning::formatReport(planning::planReport(ctx, data, m), data, command);
        std::string doc;
        if (std::ifstream in{o->report}) doc.assign(std::istreambuf_iterator<char>(in), {});
        rt::writeFileAtomically(o->report, planning::placeReport(doc, table));
        fmt::print("{}", table);
      }
      return 0;
    }
    if (o->scenes.empty()) throw std::invalid_argument("plan: give at least one --scene");
    if (o->out.empty()) throw std::invalid_argument("plan: give -o FILE.shadow");
    if (o->maxRmse < 0 && o->budgetMs < 0)
      throw std::invalid_argument("plan: give --max-rmse E, --budget-ms T or both");
    const planning::PlanModel model = planning::loadModel(o->model);
    planning::PlanRequest r;
    if (!o->costProfile.empty())
      r.costProfile = std::make_shared<const sweep::CostProfile>(sweep::resolveCostProfile(o->costProfile));
    r.scenes = o->scenes;
    if (o->maxRmse >= 0) r.maxRmse = o->maxRmse;
    if (o->budgetMs >= 0) r.budgetMs = o->budgetMs;
    r.screen = o->screen;
    r.map = o->map;
    if (o->maxMap > 0) r.maxMap = o->maxMap;
    r.samples = o->samples;
    r.runs = o->runs;
    r.warmup = o->warmup;
    r.filterName = filterNameFrom(o->out);
    r.command = command;
    r.log = log;
    rt::VulkanContext ctx(rt::VulkanOptions{o->device, false});
    try {
      const planning::PlanResult p = planning::plan(ctx, r, model);
      rt::writeFileAtomically(o->out, p.text);
      fmt::print("planned  {} -> {}\n", p.chosen.name, o->out);
      if (!p.mapReason.empty()) fmt::print("  {}\n", p.mapReason);
      const bool predicted = !p.measured.measuredMs.empty();
      for (size_t i = 0; i < p.stats.size(); ++i)
        fmt::print("  {:<24} rmse {:.4f}  {:.3f} ms{}\n", p.stats[i].scene, p.measured.rmse[i], p.measured.ms[i],
                   predicted ? fmt::format(" predicted on {} (measured here {:.2f} ms)", p.measured.profileDevice,
                                           p.measured.measuredMs[i])
                             : std::string());
      if (predicted)
        fmt::print("  worst scene's time {:.3f} ms, predicted on {} from its work counts\n", p.measured.worstMs,
                   p.measured.profileDevice);
      else
        fmt::print("  worst scene's time {:.2f} ms, 95% interval [{:.2f}, {:.2f}]\n", p.measured.worstMs,
                   p.measured.worstLowMs, p.measured.worstHighMs);
      fmt::print("tried   ");
      for (const auto& t : p.tried)
        if (predicted)
          fmt::print(" {} ({:.4f}, {:.3f} ms predicted)", t.variant, t.worstRmse, t.worstMs);
        else
          fmt::print(" {} ({:.4f}, {:.2f} ms [{:.2f}, {:.2f}])", t.variant, t.worstRmse, t.worstMs, t.worstLowMs,
                     t.worstHighMs);
      fmt::print("\n");
    } catch (const planning::PlanError& e) {
      std::fflush(stdout);
      fmt::print(stderr, "shadowc: error: {}\n", e.what());
      return 1;
    }
    return 0;
  };
}

}  // namespace shadowc::cli

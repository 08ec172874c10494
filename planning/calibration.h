// Calibration of the plan model (samples/plan/model.json) and the exhaustive comparison behind
// docs/planning.md's table, both from one measured sweep (calibration_sweep.h): the sweep
// library runs every candidate on every scene (or an existing results.json is read), the model
// is fitted per variant from those rows, and the table's exhaustive column, everything-on column
// and the plan's confirmations are the same rows.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "planning/planner.h"

namespace shadowc::sweep {
struct Results;
}

namespace shadowc::planning {

struct SweepData;

struct CalibrationRequest {
  std::vector<std::string> scenes;  // empty = every built-in scene
  uint32_t screen = 256, map = 1024;
  int samples = 16, warmup = 2;
  rt::RunCount runs = 5;  // a count, or auto (runtime/executor/run_timing.h)
  std::string command;    // recorded as generated_by
  std::function<void(const std::string&)> log;
};

// The rows of the calibration sweep: run into `sweepDir` by the sweep library (finished rows
// are cached there, so a rerun measures only what changed or is missing), or, with `fromSweep`,
// read from an existing `fromSweep/results.json` (e.g. `shadowc sweep
// samples/plan/calibration_sweep.json -o DIR`, sharded and merged) without running anything.
sweep::Results calibrationRows(const CalibrationRequest& request, const std::filesystem::path& sweepDir,
                               const std::string& device);
sweep::Results sweepRows(const std::filesystem::path& fromSweep);

// One row of the docs table: per scene, the plan at a bound a little above the best reachable,
// everything on, and the fastest variant within the bound among all measured (exhaustive).
struct ReportRow {
  std::string scene;
  double bound = 0, best = 0;
  std::string bestVariant;
  Measurement plan, everything, fastest;
  std::string planText;   // the filter description the planner wrote for `plan`
  size_t confirmed = 0;   // candidates the planner measured (of the catalog)
  std::string planError;  // when planning failed
};
// The plans are made on the sweep's rows: a confirmation looks its measurement up there, so the
// plan's time is the same measurement as the exhaustive column's entry for that variant.
std::vector<ReportRow> planReport(rt::VulkanContext& ctx, const SweepData& data, const PlanModel& model);
std::string formatReport(const std::vector<ReportRow>& rows, const SweepData& data, const std::string& command);
// `text` placed between the report markers of an existing document (docs/planning.md), or
// alone when `document` has none.
std::string placeReport(const std::string& document, const std::string& text);

}  // namespace shadowc::planning

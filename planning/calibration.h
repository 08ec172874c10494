// Calibration of the plan model (samples/plan/model.json) and the exhaustive comparison behind
// docs/planning.md's table. Both measure every candidate of the catalog on every scene through
// the run harness (measureCandidate); the model is then fitted per variant (fitVariant).
// When `shadowc sweep` (sweep/) lands, the calibration can read its results.json instead: the
// runs below are exactly the rows such a sweep records (scene, variant, per-pass ms, RMSE).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "planning/planner.h"

namespace shadowc::planning {

struct CalibrationRequest {
  std::vector<std::string> scenes;  // empty = every built-in scene
  uint32_t screen = 128, map = 512;
  int samples = 8, warmup = 2, runs = 3;
  std::string command;  // recorded as generated_by
  std::function<void(const std::string&)> log;
};

PlanModel calibrateModel(rt::VulkanContext& ctx, const CalibrationRequest& request);

// One row of the docs table: per scene, the plan at a bound a little above the best reachable,
// everything on, and the fastest variant within the bound among all measured (exhaustive).
struct ReportRow {
  std::string scene;
  double bound = 0, best = 0;
  std::string bestVariant;
  Measurement plan, everything, fastest;
  std::string planError;  // when planning failed
};
std::vector<ReportRow> planReport(rt::VulkanContext& ctx, const CalibrationRequest& request, const PlanModel& model);
std::string formatReport(const std::vector<ReportRow>& rows, const CalibrationRequest& request);

}  // namespace shadowc::planning

// The calibration sweep (docs/planning.md "The model"): every candidate of the catalog as a
// base filter of one `shadowc sweep` description (samples/plan/calibration_sweep.json), run by
// the sweep library (sweep/), and the plan model fitted from the rows of its results.json.
// The model is calibrated by measured sweeps, not by a measuring path of its own; the table in
// docs/planning.md reads the same rows.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "planning/calibration.h"
#include "sweep/sweep_row.h"
#include "sweep/sweep_spec.h"

namespace shadowc::planning {

// The sweep variant a candidate is measured as. Depth families (hard, pcf, pcss) come twice,
// with the slope-scaled bias (the candidate's name) and with the constant one
// ("<name>_constant_bias"), because the planner picks the bias per scene (useSlopeBias).
std::string sweepVariantName(const Candidate& c, bool slopeBias);

// The description: every candidate x every scene of the request at its screen, map, samples,
// runs and warm-up. Deterministic: the same request gives the same bytes.
// The built-in scenes a calibration covers by default: the spot-light ones (the candidates are spot
// filters; runOnScene refuses a filter whose light differs from the scene's).
std::vector<std::string> defaultCalibrationScenes();
std::string calibrationSweepJson(const CalibrationRequest& request);
sweep::SweepSpec calibrationSweep(const CalibrationRequest& request);

// A sweep's rows joined to the candidates: per scene (case label), the scene prepared without
// a reference and analyzed, and each candidate's measurement with the bias the planner would
// pick on that scene. A row counts for a candidate only when its normalized spec is exactly the
// candidate's today (so a sweep run before the catalog changed is not silently reused).
struct SweepScene {
  std::string label;
  PlanScenes scenes;                          // one scene, prepared with traceReference = false
  std::map<std::string, Measurement> byName;  // candidate name -> its row, as a Measurement
  std::map<std::string, CalibrationRun> runs;
};
struct SweepData {
  std::vector<SweepScene> scenes;
  uint32_t screen = 0, map = 0;
  int samples = 0, runs = 0, warmup = 0;
  std::vector<std::string> warnings;  // rows or candidates that did not match
};
SweepData joinSweep(rt::VulkanContext& ctx, const sweep::Results& results, const std::filesystem::path& dir,
                    const PlanRules& rules);

// The model fitted from the joined rows (fitVariant per candidate).
PlanModel modelFromSweep(const SweepData& data, const std::string& command);

}  // namespace shadowc::planning

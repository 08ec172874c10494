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
// ("<name>_constant_bias"), because the planner picks the bias per scene (useSlopeBias); a
// cascaded one once (its bias is a normal offset either way).
std::string sweepVariantName(const Candidate& c, bool slopeBias);

// One description per light type (a filter reads its map through its light's projection and
// runOnScene refuses a mismatch): every candidate the checker accepts for that light, written with
// it (`light area(size: scene)`, `sun(angle: scene)`, `point(radius: scene)`), x every scene of
// the request with that light (default: the built-ins with it), at the request's screen, map,
// samples, runs and warm-up. Deterministic: the same request gives the same bytes. The spot
// sweep runs into the sweep directory itself, the others into its sun/ and point/
// subdirectories (calibrationSubdir); the rows of all of them are joined (joinSweep).
std::vector<std::string> defaultCalibrationScenes(LightType light = LightType::Spot);
std::vector<std::string> calibrationScenes(const CalibrationRequest& request, LightType light);
std::string calibrationSubdir(LightType light);  // "", "sun", "point"
std::string calibrationSweepJson(const CalibrationRequest& request, LightType light = LightType::Spot);
sweep::SweepSpec calibrationSweep(const CalibrationRequest& request, LightType light = LightType::Spot);
inline constexpr LightType kCalibrationLights[] = {LightType::Spot, LightType::Sun, LightType::Point};

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

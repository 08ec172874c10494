// The planner behind `shadowc plan` (docs/planning.md): scene statistics rule features out,
// the model (plan_model.h) orders the remaining candidates (candidates.h) by predicted cost,
// and every pick is confirmed by running it through the run harness against the ground truth;
// a pick that misses the bound makes it try the next candidate. Several scenes plan one filter:
// a feature is ruled out only when every scene rules it out, and a candidate must meet the bound
// on every scene.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "planning/candidates.h"
#include "planning/plan_model.h"
#include "planning/scene_analysis.h"
#include "runtime/executor/run_timing.h"
#include "runtime/harness/scene_run.h"
#include "sweep/cost_profile.h"

namespace shadowc::rt {
class VulkanContext;
}

namespace shadowc::planning {

// A request the planner cannot meet (unreachable bound, a budget nothing meets): one message.
struct PlanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// The error bound is out of reach of every candidate (the one error a larger map may cure).
struct UnreachableBound : PlanError {
  using PlanError::PlanError;
};

struct PlanRequest {
  std::vector<std::string> scenes;  // built-in names or .json paths
  std::optional<double> maxRmse;    // at least one of maxRmse, budgetMs
  std::optional<double> budgetMs;
  uint32_t screen = 256, map = 1024;
  // The largest map the plan may choose when no candidate meets --max-rmse at `map` (`--max-map`,
  // docs/planning.md "Map size"): it then tries 2 map, 4 map, ... up to this and writes the first
  // that works as the filter's `resolution`.
  std::optional<uint32_t> maxMap;
  int resolution = 0;   // written as `resolution` (set by the map search), 0 = none
  std::string mapNote;  // why that map: a header comment of the written filter
  int samples = 16;     // reference light samples per axis
  int warmup = 2;
  rt::RunCount runs = 5;  // a count, or auto (runtime/executor/run_timing.h)
  // `--cost-profile`: confirmations are timed by the frame this device profile predicts from
  // their exact work counts (docs/cost.md), not by this machine's clock, so the plan is the named
  // device's and the same under any load; the measured medians are kept beside.
  std::shared_ptr<const sweep::CostProfile> costProfile;
  std::string filterName = "planned";
  std::string command;                          // echoed in the written file's header
  std::function<void(const std::string&)> log;  // progress lines (stderr)
};

// One candidate measured on every scene of a request.
struct Measurement {
  std::string variant;
  std::vector<double> rmse, ms;  // per scene
  double worstRmse = 0, worstMs = 0;
  // Where the worst scene's median time can lie: if each scene's median is inside its 95%
  // interval [lo_i, hi_i], the largest median is inside [max lo_i, max hi_i]. Equal to worstMs
  // for a measurement without intervals.
  double worstLowMs = 0, worstHighMs = 0;
  // With a cost profile, `ms` and the worst times are its predictions (points: low = high) and
  // these the measured medians; empty without one.
  std::vector<double> measuredMs;
  std::string profileDevice;
};

// The plan's pick among confirmed candidates, as a rule on the set, so that the order they were
// measured in does not matter (docs/planning.md "Ties"). Only those that meet the bounds count.
// With an error bound: drop every one certainly slower than another that meets it (its worst
// scene's interval wholly above the other's), then take the most accurate of the rest, then the
// lower median, then the first name. With a budget only: the most accurate, then the lower
// median, then the name. nullopt when none meets the bounds. Index into `tried`.
std::optional<size_t> chooseMeasured(const std::vector<Measurement>& tried, std::optional<double> maxRmse,
                                     std::optional<double> budgetMs);
// Two measurements ordered by chooseMeasured's rule on just these two (both meeting the bound):
// whether `candidate` is picked over `chosen`.
bool replacesChosen(const Measurement& candidate, const Measurement& chosen, bool budgetOnly);

// The scenes of a request, prepared once (rasterized + reference) and analyzed.
struct PlanScenes {
  std::vector<std::shared_ptr<const rt::PreparedScene>> prepared;
  std::vector<SceneStats> stats;
};
PlanScenes preparePlanScenes(rt::VulkanContext& ctx, const std::vector<std::string>& scenes, uint32_t screen,
                             uint32_t map, int samples, double contactEpsilon);

// Compiles a candidate (described for these scenes) and runs it on each of them. Results are
// cached per measurementKey in `cache` when given (the report fills it from sweep rows).
std::string measurementKey(const std::string& variant, const PlanScenes& scenes, bool slopeBias);
Measurement measureCandidate(rt::VulkanContext& ctx, const Candidate& c, const PlanScenes& scenes,
                             const PlanModel& model, int warmup, const rt::RunCount& runs,
                             std::map<std::string, Measurement>* cache = nullptr,
                             const sweep::CostProfile* profile = nullptr);

// Why each feature may or may not be used: the statistic and whether it rules the feature out.
struct FeatureVerdict {
  bool ruledOut = false;
  std::string statistic;  // "99.6 % of penumbrae < 1.5 texels"
};
std::map<Feature, FeatureVerdict> featureVerdicts(const std::vector<SceneStats>& stats, const PlanRules& rules,
                                                  const std::vector<std::string>& sceneNames);
bool useSlopeBias(const std::vector<SceneStats>& stats, const PlanRules& rules);

struct PlanResult {
  Candidate chosen;
  Measurement measured;            // of the chosen candidate
  std::vector<Measurement> tried;  // in the order they were confirmed
  std::vector<SceneStats> stats;
  std::string text;       // the filter description written to -o
  std::string mapReason;  // why a larger map, when one was chosen (the request's mapNote)
  double predictedMs = 0, predictedRmse = 0;
};

PlanResult plan(rt::VulkanContext& ctx, const PlanRequest& request, const PlanModel& model);
// The same on scenes already prepared (the report reuses measurements through `cache`).
PlanResult planOnScenes(rt::VulkanContext& ctx, const PlanRequest& request, const PlanModel& model,
                        const PlanScenes& scenes, std::map<std::string, Measurement>* cache = nullptr);

}  // namespace shadowc::planning

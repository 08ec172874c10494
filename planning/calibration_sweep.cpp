#include "planning/calibration_sweep.h"

#include <fmt/core.h>

#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include "driver/driver.h"
#include "runtime/scene/scene.h"
#include "spec/load_filter.h"
#include "sweep/pareto.h"

namespace shadowc::planning {
namespace {

bool isDepthFamily(const Candidate& c) { return c.has(Feature::SlopeBias); }

DescribeOptions sweepDescribeOptions(const Candidate& c, bool slopeBias, LightType light) {
  DescribeOptions d;
  d.filterName = sweepVariantName(c, slopeBias);
  d.slopeBias = slopeBias;
  d.contactEpsilon = 0.01;  // preparePlanScenes' (the analysis' contact epsilon)
  d.light = light;
  return d;
}

LightType lightOf(const rt::Scene& s) {
  return s.light.type == rt::LightType::Sun     ? LightType::Sun
         : s.light.type == rt::LightType::Point ? LightType::Point
                                                : LightType::Spot;
}

// The checker's normalized spec of a candidate as the sweep measures it (what a row's "spec"
// holds), without the filter name.
nlohmann::json normalizedSpec(const Candidate& c, bool slopeBias, LightType light) {
  driver::Options o;
  o.stopAfter = driver::Stage::Check;
  const std::string text = describeCandidate(c, sweepDescribeOptions(c, slopeBias, light));
  const driver::Result r = driver::compileSource(text, c.name, o);
  if (!r.spec) throw std::logic_error("planner candidate '" + c.name + "' is not a valid filter:\n" + r.log);
  nlohmann::json j = nlohmann::json::parse(specToJson(*r.spec).dump());
  j.erase("name");
  return j;
}

// A row's scene as the harness loads it: its label when that is a built-in or a path, else the
// derived scene the sweep wrote (sweep/sweep_scene.h: DIR/scenes/<label>.json).
std::string sceneSource(const std::string& label, const std::filesystem::path& dir) {
  for (const std::string& b : rt::builtinSceneNames())
    if (b == label) return label;
  std::string slug = label;
  for (char& ch : slug)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-' && ch != '_') ch = '_';
  const std::filesystem::path derived = dir / "scenes" / (slug + ".json");
  std::error_code ec;
  return std::filesystem::is_regular_file(derived, ec) ? derived.string() : label;
}

}  // namespace

std::string sweepVariantName(const Candidate& c, bool slopeBias) {
  // A cascaded candidate has one bias (a normal offset, candidateSpec), so one variant.
  return isDepthFamily(c) && !slopeBias && c.cascades == 0 ? c.name + "_constant_bias" : c.name;
}

// A filter reads its map through its light's projection (runOnScene refuses a mismatch), so the
// calibration is one sweep per light type: the candidates the checker accepts for that light,
// written with it, over the scenes of that light.
std::vector<std::string> defaultCalibrationScenes(LightType light) {
  std::vector<std::string> names;
  for (const std::string& n : rt::builtinSceneNames())
    if (lightOf(rt::loadScene(n)) == light) names.push_back(n);
  return names;
}

std::vector<std::string> calibrationScenes(const CalibrationRequest& r, LightType light) {
  if (r.scenes.empty()) return defaultCalibrationScenes(light);
  std::vector<std::string> names;
  for (const std::string& n : r.scenes)
    if (lightOf(rt::loadScene(n)) == light) names.push_back(n);
  return names;
}

std::string calibrationSubdir(LightType light) {
  return light == LightType::Sun ? "sun" : light == LightType::Point ? "point" : "";
}

std::string calibrationSweepJson(const CalibrationRequest& r, LightType light) {
  nlohmann::ordered_json j;
  j["name"] = light == LightType::Spot ? "plan_calibration" : "plan_calibration_" + calibrationSubdir(light);
  auto& filters = j["filters"] = nlohmann::ordered_json::array();
  for (const Candidate& c : candidateCatalog())
    for (bool slope : {true, false}) {
      if (!slope && (!isDepthFamily(c) || c.cascades > 0)) continue;
      const DescribeOptions d = sweepDescribeOptions(c, slope, light);
      if (!candidateAccepted(c, d)) continue;  // e.g. cascades off a sun, a SAT on a cube atlas
      filters.push_back({{"name", sweepVariantName(c, slope)}, {"text", describeCandidate(c, d)}});
    }
  j["scenes"] = calibrationScenes(r, light);
  j["screen"] = r.screen;
  j["map"] = r.map;
  j["reference_samples"] = r.samples;
  if (r.runs.automatic)
    j["runs"] = "auto";
  else
    j["runs"] = r.runs.runs;
  j["warmup"] = r.warmup;
  return j.dump(1) + "\n";
}

sweep::SweepSpec calibrationSweep(const CalibrationRequest& r, LightType light) {
  return sweep::parseSweepSpec(calibrationSweepJson(r, light), "plan_calibration.json",
                               std::filesystem::current_path());
}

SweepData joinSweep(rt::VulkanContext& ctx, const sweep::Results& results, const std::filesystem::path& dir,
                    const PlanRules& rules) {
  SweepData data;
  if (results.rows.empty()) throw std::runtime_error(dir.string() + ": error: the sweep has no result rows");
  const sweep::Row& first = results.rows.front();
  data.screen = first.screen;
  data.map = first.map;
  data.samples = first.referenceSamples;
  data.runs = first.runs;
  data.warmup = first.warmup;
  // Rows by case label, then by variant (base filter) name.
  std::map<std::string, std::map<std::string, const sweep::Row*>> byCase;
  std::vector<std::string> order;
  for (const sweep::Row& row : results.rows) {
    if (row.screen != data.screen || row.map != data.map || row.referenceSamples != data.samples) {
      data.warnings.push_back(fmt::format("row {} on {} ignored: another screen, map or reference than the first row",
                                          row.variant, row.caseLabel));
      continue;
    }
    if (!byCase.count(row.caseLabel)) order.push_back(row.caseLabel);
    byCase[row.caseLabel][row.base] = &row;
  }
  std::map<std::tuple<std::string, bool, LightType>, nlohmann::json> specs;  // normalized once per variant
  for (const std::string& label : order) {
    const auto& rows = byCase.at(label);
    SweepScene sc;
    const sweep::Row& any = *rows.begin()->second;
    sc.label = any.scene;  // the scene's label; every row has the same sizes
    rt::Scene scene = rt::loadScene(sceneSource(any.scene, dir));
    const LightType light = lightOf(scene);
    rt::SceneSettings settings;
    settings.scene = any.scene;
    settings.screen = data.screen;
    settings.map = data.map;
    settings.referenceSamples = data.samples;
    settings.traceReference = false;  // the rows hold the measurements; the analysis needs no reference
    sc.scenes.prepared.push_back(rt::prepareScene(ctx, std::move(scene), settings));
    sc.scenes.stats.push_back(analyzeScene(*sc.scenes.prepared.back()));
    const bool slope = useSlopeBias(sc.scenes.stats, rules);
    for (const Candidate& c : candidateCatalog()) {
      const std::string name = sweepVariantName(c, slope);
      if (!candidateAccepted(c, sweepDescribeOptions(c, slope, light))) continue;  // not swept for this light
      const auto it = rows.find(name);
      if (it == rows.end()) {
        data.warnings.push_back(fmt::format("{}: no row for {}", sc.label, name));
        continue;
      }
      const sweep::Row& row = *it->second;
      auto sit = specs.find({c.name, slope, light});
      if (sit == specs.end())
        sit = specs.emplace(std::make_tuple(c.name, slope, light), normalizedSpec(c, slope, light)).first;
      // Compared as unordered JSON: rows read back from results.json have their keys sorted.
      nlohmann::json measured = nlohmann::json::parse(row.spec.dump());
      measured.erase("name");
      if (measured != sit->second) {
        const nlohmann::json d = nlohmann::json::diff(sit->second, measured);
        data.warnings.push_back(
            fmt::format("{}: row {} measured another filter than today's candidate ({}; rerun "
                        "the sweep)",
                        sc.label, name, d.empty() ? "" : d[0].dump()));
        continue;
      }
      Measurement m;
      m.variant = c.name;
      m.rmse = {row.metrics.rmse};
      m.ms = {row.totalMs};
      m.worstRmse = row.metrics.rmse;
      m.worstMs = row.totalMs;
      m.worstLowMs = sweep::timeLowMs(row);
      m.worstHighMs = sweep::timeHighMs(row);
      sc.byName[c.name] = m;
      CalibrationRun run;
      run.scene = sc.label;
      run.screen = row.screen;
      run.map = row.map;
      run.rmse = row.metrics.rmse;
      run.totalMs = row.totalMs;
      for (const sweep::PassTime& p : row.passes) (p.kind == "shade" ? run.shadeMs : run.mapMs) += p.medianMs;
      run.terms = errorTerms(sc.scenes.stats[0]);
      sc.runs[c.name] = run;
    }
    data.scenes.push_back(std::move(sc));
  }
  return data;
}

PlanModel modelFromSweep(const SweepData& data, const std::string& command) {
  PlanModel model;
  model.generatedBy = command;
  model.screen = data.screen;
  model.map = data.map;
  model.samples = data.samples;
  std::map<std::string, std::vector<CalibrationRun>> runs;
  for (const SweepScene& sc : data.scenes)
    for (const auto& [name, run] : sc.runs) runs[name].push_back(run);
  for (auto& [name, r] : runs) model.variants[name] = fitVariant(std::move(r));
  return model;
}

}  // namespace shadowc::planning

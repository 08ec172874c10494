#include "planning/calibration_sweep.h"

#include <fmt/core.h>

#include <nlohmann/json.hpp>
#include <set>

#include "driver/driver.h"
#include "runtime/scene/scene.h"
#include "spec/load_filter.h"

namespace shadowc::planning {
namespace {

bool isDepthFamily(const Candidate& c) { return c.has(Feature::SlopeBias); }

DescribeOptions sweepDescribeOptions(const Candidate& c, bool slopeBias) {
  DescribeOptions d;
  d.filterName = sweepVariantName(c, slopeBias);
  d.slopeBias = slopeBias;
  d.contactEpsilon = 0.01;  // preparePlanScenes' (the analysis' contact epsilon)
  return d;
}

// The checker's normalized spec of a candidate as the sweep measures it (what a row's "spec"
// holds), without the filter name.
nlohmann::json normalizedSpec(const Candidate& c, bool slopeBias) {
  driver::Options o;
  o.stopAfter = driver::Stage::Check;
  const std::string text = describeCandidate(c, sweepDescribeOptions(c, slopeBias));
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
  return isDepthFamily(c) && !slopeBias ? c.name + "_constant_bias" : c.name;
}

// The catalog's candidates are spot-light filters (a filter reads its map through its light's
// projection, runOnScene refuses a mismatch): the default calibration set is the spot scenes.
std::vector<std::string> defaultCalibrationScenes() {
  std::vector<std::string> names;
  for (const std::string& n : rt::builtinSceneNames())
    if (rt::loadScene(n).light.type == rt::LightType::Spot) names.push_back(n);
  return names;
}

std::string calibrationSweepJson(const CalibrationRequest& r) {
  nlohmann::ordered_json j;
  j["name"] = "plan_calibration";
  auto& filters = j["filters"] = nlohmann::ordered_json::array();
  for (const Candidate& c : candidateCatalog())
    for (bool slope : {true, false}) {
      if (!slope && !isDepthFamily(c)) continue;
      filters.push_back(
          {{"name", sweepVariantName(c, slope)}, {"text", describeCandidate(c, sweepDescribeOptions(c, slope))}});
    }
  j["scenes"] = r.scenes.empty() ? defaultCalibrationScenes() : r.scenes;
  j["screen"] = r.screen;
  j["map"] = r.map;
  j["reference_samples"] = r.samples;
  j["runs"] = r.runs;
  j["warmup"] = r.warmup;
  return j.dump(1) + "\n";
}

sweep::SweepSpec calibrationSweep(const CalibrationRequest& r) {
  return sweep::parseSweepSpec(calibrationSweepJson(r), "plan_calibration.json", std::filesystem::current_path());
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
  std::map<std::pair<std::string, bool>, nlohmann::json> specs;  // normalized once per variant
  for (const std::string& label : order) {
    const auto& rows = byCase.at(label);
    SweepScene sc;
    const sweep::Row& any = *rows.begin()->second;
    sc.label = any.scene;  // the scene's label; every row has the same sizes
    rt::Scene scene = rt::loadScene(sceneSource(any.scene, dir));
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
      const auto it = rows.find(name);
      if (it == rows.end()) {
        data.warnings.push_back(fmt::format("{}: no row for {}", sc.label, name));
        continue;
      }
      const sweep::Row& row = *it->second;
      auto sit = specs.find({c.name, slope});
      if (sit == specs.end()) sit = specs.emplace(std::make_pair(c.name, slope), normalizedSpec(c, slope)).first;
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

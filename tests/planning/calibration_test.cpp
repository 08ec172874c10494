// The plan model calibrated from a measured sweep (planning/calibration_sweep.h,
// docs/planning.md "The model"), the confirmation that tries the next candidates, and the
// stored calibration sweep description.
#include "planning/calibration.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "planning/calibration_sweep.h"
#include "planning/fresh_validate.h"
#include "runtime/vulkan/vulkan_context.h"
#include "support/test_support.h"
#include "sweep/results_io.h"
#include "sweep/sweep_spec.h"

namespace shadowc {
namespace {

rt::VulkanContext& context() {
  static rt::VulkanContext ctx;
  return ctx;
}

// The candidates the checker accepts for a light (the calibration sweeps only those), and how
// many sweep variants they make (depth families twice, with both biases).
std::vector<planning::Candidate> acceptedFor(LightType light) {
  planning::DescribeOptions d;
  d.light = light;
  std::vector<planning::Candidate> out;
  for (const planning::Candidate& c : planning::candidateCatalog())
    if (planning::candidateAccepted(c, d)) out.push_back(c);
  return out;
}
size_t sweptVariants(LightType light) {
  size_t n = 0;
  for (const planning::Candidate& c : acceptedFor(light))
    n += c.has(planning::Feature::SlopeBias) && c.cascades == 0 ? 2 : 1;
  return n;
}

planning::CalibrationRequest tinyRequest() {
  planning::CalibrationRequest r;
  r.scenes = {"two_planes"};
  r.screen = 64;
  r.map = 256;
  r.samples = 4;
  r.runs = 1;
  r.warmup = 0;
  return r;
}

// samples/plan/calibration_sweep.json is what `shadowc plan --write-sweep` writes for its own
// settings: it names today's candidates exactly (regenerate with the command in docs/planning.md).
TEST(CalibrationSweep, StoredDescriptionIsTodaysCatalog) {
  const std::string stored = test::readFile(test::sourceDir() / "samples/plan/calibration_sweep.json");
  const nlohmann::json j = nlohmann::json::parse(stored);
  planning::CalibrationRequest r;
  r.scenes = j["scenes"].get<std::vector<std::string>>();
  r.screen = j["screen"];
  r.map = j["map"];
  r.samples = j["reference_samples"];
  r.runs = j["runs"].get<int>();
  r.warmup = j["warmup"];
  EXPECT_EQ(planning::calibrationSweepJson(r), stored)
      << "regenerate: shadowc plan --write-sweep samples/plan/calibration_sweep.json (docs/planning.md)";
  // Sibling: other settings give other bytes (the comparison can fail).
  r.runs.runs += 1;
  EXPECT_NE(planning::calibrationSweepJson(r), stored);
  // Every candidate is there; depth families with both biases.
  EXPECT_EQ(j["filters"].size(), sweptVariants(LightType::Spot));
  // Sibling: the cascaded candidates are the checker's to refuse on a spot light (E0453).
  EXPECT_LT(acceptedFor(LightType::Spot).size(), planning::candidateCatalog().size());
  EXPECT_EQ(r.scenes, planning::defaultCalibrationScenes());  // every built-in spot scene
  // Sibling: the default leaves out exactly the sun scenes (light types may not mix in one plan).
  EXPECT_LT(planning::defaultCalibrationScenes().size(), rt::builtinSceneNames().size());
}

// Run by the sweep library, read back from results.json, joined to the candidates, fitted: the
// model's runs are the sweep's rows, and a row that measured another filter is not used.
TEST(CalibrationSweep, ModelIsFittedFromTheSweepRows) {
  const auto dir = test::freshTempDir("plan_calibration_sweep");
  const planning::CalibrationRequest request = tinyRequest();
  const sweep::Results ran = planning::calibrationRows(request, dir, "");
  ASSERT_EQ(ran.rows.size(), sweptVariants(LightType::Spot));  // depth families twice
  const sweep::Results rows = planning::sweepRows(dir);        // --from-sweep reads the same rows
  ASSERT_EQ(rows.rows.size(), ran.rows.size());
  const planning::PlanRules rules;
  const planning::SweepData data = planning::joinSweep(context(), rows, dir, rules);
  EXPECT_TRUE(data.warnings.empty()) << data.warnings.front();
  ASSERT_EQ(data.scenes.size(), 1u);
  const planning::PlanModel model = planning::modelFromSweep(data, "test");
  EXPECT_EQ(model.variants.size(), acceptedFor(LightType::Spot).size());
  EXPECT_EQ(model.screen, 64u);
  EXPECT_EQ(model.map, 256u);
  const bool slope = planning::useSlopeBias(data.scenes[0].scenes.stats, rules);
  for (const planning::Candidate& c : acceptedFor(LightType::Spot)) {
    const std::string name = planning::sweepVariantName(c, slope);
    const sweep::Row* row = nullptr;
    for (const sweep::Row& r : rows.rows)
      if (r.base == name) row = &r;
    ASSERT_NE(row, nullptr) << name;
    ASSERT_EQ(model.variants.at(c.name).runs.size(), 1u);
    EXPECT_DOUBLE_EQ(model.variants.at(c.name).runs[0].rmse, row->metrics.rmse) << c.name;
    EXPECT_DOUBLE_EQ(model.variants.at(c.name).runs[0].totalMs, row->totalMs) << c.name;
  }
  // Sibling: a row whose spec is not today's candidate is refused, named in a warning.
  sweep::Results tampered = rows;
  for (sweep::Row& r : tampered.rows)
    if (r.base == planning::everythingOn().name) r.spec["early_out_min_max"] = false;
  const planning::SweepData bad = planning::joinSweep(context(), tampered, dir, rules);
  ASSERT_EQ(bad.warnings.size(), 1u);
  EXPECT_NE(bad.warnings[0].find(planning::everythingOn().name), std::string::npos) << bad.warnings[0];
  EXPECT_EQ(planning::modelFromSweep(bad, "test").variants.count(planning::everythingOn().name), 0u);

  // The report on the same rows: the plan meets its bound and its measurement is a sweep row.
  const auto report = planning::planReport(context(), data, model);
  ASSERT_EQ(report.size(), 1u);
  EXPECT_TRUE(report[0].planError.empty()) << report[0].planError;
  // Independently: the description the planner wrote, compiled from a file and validated on a
  // freshly traced reference (fresh_validate.h), meets the bound.
  EXPECT_LE(test::validateWrittenPlan(context(), report[0].planText, "two_planes", request.screen, request.map,
                                      request.samples)
                .rmse,
            report[0].bound);
  EXPECT_GE(report[0].confirmed, 1u);
  EXPECT_DOUBLE_EQ(report[0].plan.worstMs, data.scenes[0].byName.at(report[0].plan.variant).worstMs);
  EXPECT_LE(report[0].fastest.worstMs, report[0].plan.worstMs);
  const std::string doc =
      "intro\n<!-- plan report: begin (generated; do not edit by hand) -->\nold\n"
      "<!-- plan report: end -->\noutro\n";
  const std::string placed = planning::placeReport(doc, "TABLE\n");
  EXPECT_EQ(placed,
            "intro\n<!-- plan report: begin (generated; do not edit by hand) -->\nTABLE\n"
            "<!-- plan report: end -->\noutro\n");
  EXPECT_EQ(planning::placeReport("no markers", "TABLE\n"), "TABLE\n");
}

// One calibration sweep per light type (spot into DIR, sun into DIR/sun, point into DIR/point),
// each of the candidates the checker accepts for that light, joined as one set: the sun scene's
// candidates include the cascaded ones, the point scene's no VSSM (E0450), and the report plans
// each scene within its bound with a filter of its own light. Siblings: the spot sweep alone holds
// no sun or point row, and the point scene's everything-on column is refused, not measured.
// Its cost is the count, not the size: every candidate each light accepts, compiled and run once at
// the smallest sizes (64² screen, 256² map, 4² samples, 1 run), which is the property checked.
TEST(CalibrationSweep, EveryLightTypeIsSweptAndJoined) {
  const auto dir = test::freshTempDir("plan_calibration_lights");
  planning::CalibrationRequest request = tinyRequest();
  request.scenes = {"two_planes", "sun_two_planes", "point_room"};
  request.map = 384;  // a point light's faces are cells of 128^2
  const sweep::Results ran = planning::calibrationRows(request, dir, "");
  EXPECT_TRUE(ran.skipped.empty()) << ran.skipped.front().message;
  EXPECT_EQ(ran.rows.size(),
            sweptVariants(LightType::Spot) + sweptVariants(LightType::Sun) + sweptVariants(LightType::Point));
  EXPECT_TRUE(std::filesystem::exists(dir / "sun" / "results.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "point" / "results.json"));
  EXPECT_EQ(planning::sweepRows(dir).rows.size(), ran.rows.size());  // --from-sweep reads all three
  EXPECT_EQ(sweep::readResultsJson(dir / "results.json").rows.size(), sweptVariants(LightType::Spot));

  const planning::PlanRules rules;
  const planning::SweepData data = planning::joinSweep(context(), ran, dir, rules);
  EXPECT_TRUE(data.warnings.empty()) << data.warnings.front();
  ASSERT_EQ(data.scenes.size(), 3u);
  std::map<std::string, const planning::SweepScene*> byScene;
  for (const planning::SweepScene& sc : data.scenes) byScene[sc.label] = &sc;
  ASSERT_EQ(byScene.count("sun_two_planes") + byScene.count("point_room"), 2u);
  EXPECT_EQ(byScene["sun_two_planes"]->byName.size(), acceptedFor(LightType::Sun).size());
  EXPECT_EQ(byScene["sun_two_planes"]->byName.count("pcss_poisson16_cascades4"), 1u);
  EXPECT_EQ(byScene["point_room"]->byName.size(), acceptedFor(LightType::Point).size());
  EXPECT_EQ(byScene["point_room"]->byName.count(planning::everythingOn().name), 0u);
  EXPECT_EQ(byScene["two_planes"]->byName.count("pcss_poisson16_cascades4"), 0u);

  const planning::PlanModel model = planning::modelFromSweep(data, "test");
  const auto report = planning::planReport(context(), data, model);
  ASSERT_EQ(report.size(), 3u);
  for (const planning::ReportRow& r : report) {
    EXPECT_TRUE(r.planError.empty()) << r.scene << ": " << r.planError;
    EXPECT_LE(
        test::validateWrittenPlan(context(), r.planText, r.scene, request.screen, request.map, request.samples).rmse,
        r.bound)
        << r.scene;
    EXPECT_EQ(r.everything.variant.empty(), r.scene == "point_room") << r.scene;
  }
  const std::string table = planning::formatReport(report, data, "test");
  EXPECT_NE(table.find("| point_room |"), std::string::npos) << table;
  EXPECT_NE(table.find("refused (E0450)"), std::string::npos) << table;
  EXPECT_NE(table.find("(of the 2 where everything on compiles)"), std::string::npos) << table;
}

// The confirmation tries the next candidates while the model says they may be faster than the
// best measured: here the first candidate (cheapest predicted) measures slow, the next one fast.
TEST(PlanConfirmation, TriesTheNextCandidateWhenTheFirstMeasuresSlow) {
  rt::SceneSettings s;
  s.scene = "two_planes";
  s.screen = 64;
  s.map = 256;
  s.traceReference = false;  // every measurement comes from the cache below; none may run
  planning::PlanScenes scenes;
  scenes.prepared.push_back(rt::prepareScene(context(), s));
  scenes.stats.push_back(planning::analyzeScene(*scenes.prepared.back()));
  planning::PlanModel model = planning::loadModel();
  const bool slope = planning::useSlopeBias(scenes.stats, model.rules);
  // Every candidate in bound; measured time = 10 x the prediction, except the second
  // cheapest-predicted allowed one, which measures at its prediction.
  planning::PlanRequest r;
  r.scenes = {"two_planes"};
  r.maxRmse = 1.0;
  r.screen = s.screen;
  r.map = s.map;
  const auto verdicts = planning::featureVerdicts(scenes.stats, model.rules, r.scenes);
  std::vector<std::pair<double, std::string>> allowed;
  for (const planning::Candidate& c : acceptedFor(LightType::Spot)) {  // what the planner considers
    if (!model.variants.count(c.name)) continue;
    bool ok = true;
    for (planning::Feature f : planning::kFeatures)
      if (f != planning::Feature::SlopeBias && c.has(f) && verdicts.at(f).ruledOut) ok = false;
    if (ok) allowed.push_back({model.predictMs(c.name, r.map, r.screen), c.name});
  }
  std::sort(allowed.begin(), allowed.end());
  ASSERT_GE(allowed.size(), 2u);
  const std::string fast = allowed[1].second;
  auto cacheWith = [&](double slowFactor) {
    std::map<std::string, planning::Measurement> cache;
    for (const planning::Candidate& c : acceptedFor(LightType::Spot)) {
      if (!model.variants.count(c.name)) continue;
      planning::Measurement m;
      m.variant = c.name;
      const double ms = model.predictMs(c.name, r.map, r.screen) * (c.name == fast ? 1.0 : slowFactor);
      m.rmse = {0.01};
      m.ms = {ms};
      m.worstRmse = 0.01;
      m.worstMs = ms;
      cache[planning::measurementKey(c.name, scenes, slope)] = m;
    }
    return cache;
  };
  auto cache = cacheWith(10.0);
  const planning::PlanResult p = planning::planOnScenes(context(), r, model, scenes, &cache);
  EXPECT_EQ(p.chosen.name, fast);
  EXPECT_GE(p.tried.size(), 2u);
  // Sibling: when the first measures as predicted, the next is not expected to be faster and the
  // first is the plan (the check above can fail).
  auto honest = cacheWith(1.0);
  const planning::PlanResult q = planning::planOnScenes(context(), r, model, scenes, &honest);
  EXPECT_EQ(q.chosen.name, allowed[0].second);
}

// `--write-sweep` writes a description `shadowc sweep` loads; `--from-sweep` without results is
// one message and exit 1.
TEST(CalibrationSweepCli, WritesTheSweepAndRefusesAMissingOne) {
  const auto dir = test::freshTempDir("plan_write_sweep");
  const auto file = dir / "calibration.json";
  const test::CliResult w = test::runShadowc("plan --write-sweep '" + file.string() +
                                             "' --scene two_planes --screen 64 --map 256 --samples 4 --runs 1");
  ASSERT_EQ(w.code, 0) << w.err;
  const sweep::SweepSpec spec = sweep::loadSweepSpec(file);
  EXPECT_EQ(spec.filters.size(), sweptVariants(LightType::Spot));
  ASSERT_EQ(spec.scenes.size(), 1u);
  EXPECT_EQ(spec.scenes[0].scene, "two_planes");
  EXPECT_EQ(spec.screens, std::vector<uint32_t>{64});
  EXPECT_EQ(spec.runs.runs, 1);
  const test::CliResult r = test::runShadowc("plan --calibrate '" + (dir / "m.json").string() + "' --from-sweep '" +
                                             (dir / "none").string() + "'");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("results.json"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "m.json"));
}

}  // namespace
}  // namespace shadowc

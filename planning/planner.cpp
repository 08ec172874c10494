#include "planning/planner.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "driver/driver.h"
#include "runtime/vulkan/vulkan_context.h"

namespace shadowc::planning {
namespace {

std::string sceneList(const PlanScenes& s) {
  std::string out;
  for (const SceneStats& st : s.stats) out += (out.empty() ? "" : ",") + st.scene;
  return out;
}

// The worst scene of a statistic (the one that needs the feature most) and its value.
template <class F>
std::pair<double, std::string> worst(const std::vector<SceneStats>& stats, F value, bool highest) {
  double best = highest ? -1e300 : 1e300;
  std::string name;
  for (const SceneStats& s : stats) {
    const double v = value(s);
    if (highest ? v > best : v < best) {
      best = v;
      name = s.scene;
    }
  }
  return {best, name};
}

std::string where(const std::vector<SceneStats>& stats, const std::string& scene) {
  std::string w = stats.size() > 1 ? fmt::format(" (worst scene: {})", scene) : "";
  // A point light's statistics are taken per cube face and merged (scene_analysis.h).
  if (!stats.empty() && stats[0].lightShape == "sphere") w += ", over the 6 cube faces";
  return w;
}

}  // namespace

PlanScenes preparePlanScenes(rt::VulkanContext& ctx, const std::vector<std::string>& scenes, uint32_t screen,
                             uint32_t map, int samples, double contactEpsilon) {
  PlanScenes out;
  std::vector<rt::Scene> loaded;
  for (const std::string& s : scenes) loaded.push_back(rt::loadScene(s));  // every scene error before any work
  for (size_t i = 0; i < scenes.size(); ++i) {
    rt::SceneSettings settings;
    settings.scene = scenes[i];
    settings.screen = screen;
    settings.map = map;
    settings.referenceSamples = samples;
    out.prepared.push_back(rt::prepareScene(ctx, std::move(loaded[i]), settings));
    AnalysisOptions options;
    options.contactEpsilon = contactEpsilon;
    out.stats.push_back(analyzeScene(*out.prepared.back(), options));
  }
  return out;
}

bool useSlopeBias(const std::vector<SceneStats>& stats, const PlanRules& rules) {
  return worst(
             stats, [](const SceneStats& s) { return s.slopeDegrees.p99; }, true)
             .first > rules.slopeDegrees;
}

// The candidates' light follows the scenes' (a filter reads its map through its light's
// projection: frame.glsl, frame_ortho.glsl or frame_cube.glsl); scenes of several kinds cannot
// share one filter.
LightType planLight(const PlanScenes& scenes) {
  auto kind = [](rt::LightType t) {
    return t == rt::LightType::Sun ? LightType::Sun : t == rt::LightType::Point ? LightType::Point : LightType::Spot;
  };
  auto word = [](LightType t) { return t == LightType::Sun ? "sun" : t == LightType::Point ? "point" : "spot"; };
  if (scenes.prepared.empty()) return LightType::Spot;
  const LightType first = kind(scenes.prepared[0]->scene.light.type);
  for (const auto& p : scenes.prepared)
    if (kind(p->scene.light.type) != first)
      throw PlanError(fmt::format(
          "plan scenes mix lights ('{}' has a {} light, '{}' a {} light): one filter reads its map through one "
          "projection; plan them separately",
          scenes.prepared[0]->scene.name, word(first), p->scene.name, word(kind(p->scene.light.type))));
  return first;
}

// The scenes of `base` prepared for the candidate's light views (the reference shared), one per scene.
std::vector<std::shared_ptr<const rt::PreparedScene>> scenesFor(rt::VulkanContext& ctx, const PlanScenes& base,
                                                                const CompiledPasses& passes) {
  std::vector<std::shared_ptr<const rt::PreparedScene>> out;
  for (const auto& p : base.prepared) out.push_back(rt::prepareSceneForFilter(ctx, p, passes.manifest.spec));
  return out;
}

std::string measurementKey(const std::string& variant, const PlanScenes& scenes, bool slopeBias) {
  return variant + "|" + sceneList(scenes) + "|" + (slopeBias ? "slope" : "constant");
}

std::optional<size_t> chooseMeasured(const std::vector<Measurement>& tried, std::optional<double> maxRmse,
                                     std::optional<double> budgetMs) {
  std::vector<size_t> meeting;
  for (size_t i = 0; i < tried.size(); ++i)
    if ((!maxRmse || tried[i].worstRmse <= *maxRmse) && (!budgetMs || tried[i].worstMs <= *budgetMs))
      meeting.push_back(i);
  std::vector<size_t> kept;
  for (size_t i : meeting) {
    // Certainly slower than another that meets the bound: out (not with a budget only, where the
    // bound is on time and accuracy is what is bought).
    const bool slower = maxRmse && std::any_of(meeting.begin(), meeting.end(), [&](size_t k) {
                          return k != i && tried[k].worstHighMs < tried[i].worstLowMs;
                        });
    if (!slower) kept.push_back(i);
  }
  if (kept.empty()) return std::nullopt;
  return *std::min_element(kept.begin(), kept.end(), [&](size_t a, size_t b) {
    const Measurement &x = tried[a], &y = tried[b];
    if (x.worstRmse != y.worstRmse) return x.worstRmse < y.worstRmse;
    if (x.worstMs != y.worstMs) return x.worstMs < y.worstMs;
    return x.variant < y.variant;
  });
}

bool replacesChosen(const Measurement& candidate, const Measurement& chosen, bool budgetOnly) {
  const std::optional<double> anyBound = budgetOnly ? std::nullopt : std::optional<double>(1e300);
  return chooseMeasured({chosen, candidate}, anyBound, std::nullopt) == size_t(1);
}

Measurement measureCandidate(rt::VulkanContext& ctx, const Candidate& c, const PlanScenes& scenes,
                             const PlanModel& model, int warmup, const rt::RunCount& runs,
                             std::map<std::string, Measurement>* cache, const sweep::CostProfile* profile) {
  DescribeOptions d;
  d.slopeBias = useSlopeBias(scenes.stats, model.rules);
  d.contactEpsilon = scenes.stats.empty() ? 0.01 : scenes.stats[0].contactEpsilon;
  d.light = planLight(scenes);
  const std::string key =
      measurementKey(c.name, scenes, d.slopeBias) + (profile ? "|profile " + profile->device : std::string());
  if (cache) {
    auto it = cache->find(key);
    if (it != cache->end()) return it->second;
  }
  const std::string text = describeCandidate(c, d);
  const FilterSpec spec = candidateSpec(c, d);
  const driver::Result r = driver::compileSpec(spec);
  if (!r.artifact) throw std::logic_error("planner candidate '" + c.name + "' did not compile:\n" + r.log + text);
  const CompiledPasses passes = r.artifact->passes();
  std::optional<CompiledPasses> counted;  // the instrumented build, for the profile's counts
  if (profile) {
    driver::Options counting;
    counting.counters = true;
    const driver::Result rc = driver::compileSpec(spec, counting);
    if (!rc.artifact) throw std::logic_error("planner candidate '" + c.name + "' did not compile counted:\n" + rc.log);
    counted = rc.artifact->passes();
  }
  Measurement m;
  m.variant = c.name;
  if (profile) m.profileDevice = profile->device;
  for (const auto& prepared : scenesFor(ctx, scenes, passes)) {
    rt::RunOptions options;
    options.warmup = warmup;
    options.runs = runs;
    const rt::SceneRunResult run = rt::runOnScene(ctx, passes, *prepared, options);
    m.rmse.push_back(run.metrics.rmse);
    const rt::TimingResult& t = *run.outputs.timing;
    double ms = t.totalMs, low = t.stats.n > 0 ? t.stats.ciLowMs : t.totalMs,
           high = t.stats.n > 0 ? t.stats.ciHighMs : t.totalMs;
    if (profile) {
      sweep::CostSample s;
      s.variant = c.name;
      s.screen = prepared->settings.screen;
      s.map = prepared->settings.map;
      for (const auto& p : t.passes) s.passes.push_back({p.name, p.kind, p.medianMs});
      s.totalMs = t.totalMs;
      s.work = rt::runOnScene(ctx, *counted, *prepared, {}).outputs.work;
      s.momentChannels = sweep::momentChannelsOfSpec(passes.manifest.spec);
      const std::optional<double> predicted = profile->frameMs(s);
      if (!predicted)
        throw PlanError(
            fmt::format("the cost profile for {} cannot price {}: it has a pass the profile was not "
                        "fitted on (docs/cost.md)",
                        profile->device, c.name));
      m.measuredMs.push_back(t.totalMs);
      ms = low = high = *predicted;
    }
    m.ms.push_back(ms);
    m.worstRmse = std::max(m.worstRmse, run.metrics.rmse);
    m.worstMs = std::max(m.worstMs, ms);
    m.worstLowMs = std::max(m.worstLowMs, low);
    m.worstHighMs = std::max(m.worstHighMs, high);
  }
  if (cache) (*cache)[key] = m;
  return m;
}

std::map<Feature, FeatureVerdict> featureVerdicts(const std::vector<SceneStats>& stats, const PlanRules& r,
                                                  const std::vector<std::string>&) {
  std::map<Feature, FeatureVerdict> v;
  // Blocker search and the penumbra-sized kernel: only where penumbrae are wider than a fixed kernel.
  const auto narrow = worst(
      stats, [&](const SceneStats& s) { return s.fractionPenumbraBelow(r.penumbraTexels); }, false);
  const bool soft = narrow.first < r.penumbraQuantile;
  const std::string narrowText = fmt::format("{:.1f} % of penumbrae < {:g} texels{}", 100.0 * narrow.first,
                                             r.penumbraTexels, where(stats, narrow.second));
  v[Feature::BlockerSearch] = {!soft, narrowText};
  v[Feature::PenumbraKernel] = {!soft, narrowText};
  const auto wide = worst(
      stats, [](const SceneStats& s) { return s.penumbraTexels.p99; }, true);
  v[Feature::Sat] = {!soft || wide.first < r.satTexels,
                     fmt::format("p99 penumbra {:.1f} texels (SAT ruled out below {:g}){}", wide.first, r.satTexels,
                                 where(stats, wide.second))};
  v[Feature::Quadtree] = {!soft || wide.first < r.quadtreeTexels,
                          fmt::format("p99 penumbra {:.1f} texels (quadtree ruled out below {:g}){}", wide.first,
                                      r.quadtreeTexels, where(stats, wide.second))};
  const auto multi = worst(
      stats, [](const SceneStats& s) { return s.multiDepthFraction(); }, true);
  const std::string multiText =
      fmt::format("{:.1f} % of penumbra kernel regions hold occluders at >= 2 distinct depths{}", 100.0 * multi.first,
                  where(stats, multi.second));
  v[Feature::Fallback] = {!soft || multi.first <= r.multiDepthFraction, multiText};
  v[Feature::Layers] = {multi.first <= r.multiDepthFraction, multiText};
  const auto contact = worst(
      stats, [](const SceneStats& s) { return s.contactFraction(); }, true);
  v[Feature::Contact] = {!soft || contact.first <= r.contactFraction,
                         fmt::format("{:.2f} % of receivers within {:g} of a blocker{}", 100.0 * contact.first,
                                     stats.empty() ? 0.01 : stats[0].contactEpsilon, where(stats, contact.second))};
  const auto uniform = worst(
      stats, [](const SceneStats& s) { return s.uniformFraction(); }, false);
  v[Feature::EarlyOut] = {!soft || uniform.first < r.uniformFraction,
                          fmt::format("{:.1f} % of receivers fully lit or in umbra{}", 100.0 * uniform.first,
                                      where(stats, uniform.second))};
  const auto slope = worst(
      stats, [](const SceneStats& s) { return s.slopeDegrees.p99; }, true);
  // Cascades: a sun's one map spreads its texels evenly over depths the camera sees at very
  // different scales; cut into slices where the receivers' camera depths span a wide ratio.
  const auto depthRatio = worst(
      stats, [](const SceneStats& s) { return s.cameraDepthRatio(); }, true);
  bool allSuns = !stats.empty();
  for (const SceneStats& s : stats) allSuns = allSuns && s.lightShape == "sun";
  v[Feature::Cascades] = {!allSuns || depthRatio.first < r.cascadeDepthRatio,
                          allSuns
                              ? fmt::format("receivers' camera depth p99 / p01 = {:.1f} (cascades offered from {:g}){}",
                                            depthRatio.first, r.cascadeDepthRatio, where(stats, depthRatio.second))
                              : std::string("cascades split a sun's orthographic map; this light has no cascades")};
  v[Feature::SlopeBias] = {slope.first <= r.slopeDegrees,
                           fmt::format("p99 receiver slope {:.1f} degrees (slope-scaled above {:g}){}", slope.first,
                                       r.slopeDegrees, where(stats, slope.second))};
  return v;
}

// When a scene's penumbrae are too narrow for its map, what a larger map would do: the error of an
// unreachable bound then names the cure, resolution, that no filter can stand in for
// (SceneStats::mapForPenumbraTexels; docs/planning.md "Unreachable bounds").
std::string resolutionHint(const std::vector<SceneStats>& stats) {
  const SceneStats* worst = nullptr;
  for (const SceneStats& s : stats) {
    const uint32_t wanted = s.mapForPenumbraTexels();
    if (wanted > s.mapSize && (!worst || wanted > worst->mapForPenumbraTexels())) worst = &s;
  }
  if (!worst) return "";
  return fmt::format(
      "; the 10th-percentile penumbra on {} is {:.2f} texels at {}^2, narrower than any filter can shape: a "
      "{}^2 map makes it {:g} texels (plan with --map {})",
      worst->scene, worst->penumbraTexels.p10, worst->mapSize, worst->mapForPenumbraTexels(),
      SceneStats::kPenumbraTexelsWanted, worst->mapForPenumbraTexels());
}

PlanResult plan(rt::VulkanContext& ctx, const PlanRequest& request, const PlanModel& model) {
  if (request.scenes.empty()) throw PlanError("give at least one --scene");
  if (request.maxMap && (*request.maxMap < request.map || *request.maxMap > 16384))
    throw PlanError(
        fmt::format("--max-map {} must be at least --map {} and at most 16384", *request.maxMap, request.map));
  if (request.log) request.log("preparing the scenes (rasterize, Embree reference, analysis)");
  const PlanScenes scenes = preparePlanScenes(ctx, request.scenes, request.screen, request.map, request.samples, 0.01);
  try {
    return planOnScenes(ctx, request, model, scenes);
  } catch (const UnreachableBound& e) {
    // Map size as a planned resource (docs/planning.md "Map size"): where the penumbrae are
    // narrower than the map resolves, no filter can shape them, and a larger map can.
    if (!request.maxMap || *request.maxMap <= request.map) throw;
    const SceneStats* narrow = nullptr;
    for (const SceneStats& s : scenes.stats)
      if (s.mapForPenumbraTexels() > s.mapSize && (!narrow || s.penumbraTexels.p10 < narrow->penumbraTexels.p10))
        narrow = &s;
    if (!narrow)
      throw UnreachableBound(std::string(e.what()) +
                             "; every scene's penumbrae are 2 texels or wider at this map, so a larger one "
                             "(--max-map) would not help");
    std::string last = e.what();
    for (uint64_t m = uint64_t(request.map) * 2; m <= *request.maxMap; m *= 2) {
      PlanRequest r = request;
      r.map = uint32_t(m);
      r.maxMap.reset();
      r.resolution = int(m);
      r.mapNote = fmt::format(
          "Map {}^2 (`resolution`): no variant met the bound at {}^2, where the 10th-percentile penumbra on {} is "
          "{:.2f} texels; at {}^2 it is {:.2f}.",
          m, request.map, narrow->scene, narrow->penumbraTexels.p10, m,
          narrow->penumbraTexels.p10 * double(m) / request.map);
      if (request.log)
        request.log(fmt::format("no variant meets the bound at {}^2: planning on a {}^2 map", request.map, m));
      const PlanScenes larger = preparePlanScenes(ctx, request.scenes, request.screen, r.map, request.samples, 0.01);
      try {
        return planOnScenes(ctx, r, model, larger);
      } catch (const UnreachableBound& again) {
        last = again.what();
      }
    }
    throw UnreachableBound(fmt::format("{} (and on every map up to --max-map {})", last, *request.maxMap));
  }
}

PlanResult planOnScenes(rt::VulkanContext& ctx, const PlanRequest& request, const PlanModel& model,
                        const PlanScenes& scenes, std::map<std::string, Measurement>* cache) {
  if (!request.maxRmse && !request.budgetMs) throw PlanError("give --max-rmse E, --budget-ms T or both");
  const std::map<Feature, FeatureVerdict> verdicts = featureVerdicts(scenes.stats, model.rules, request.scenes);
  struct Option {
    const Candidate* c;
    bool allowed;
    double ms, rmse;  // predicted, worst over scenes
  };
  DescribeOptions light;
  light.light = planLight(scenes);
  std::vector<Option> options;
  std::map<Feature, std::string> refusedFor;  // a feature whose every candidate the checker refuses
  for (Feature f : kFeatures) {
    std::string why;
    bool anyAccepted = false, any = false;
    for (const Candidate& c : candidateCatalog())
      if (c.has(f)) {
        any = true;
        std::string w;
        if (candidateAccepted(c, light, &w))
          anyAccepted = true;
        else if (why.empty())
          why = w.substr(0, w.find(':'));  // the code
      }
    if (any && !anyAccepted) refusedFor[f] = why;
  }
  for (const Candidate& c : candidateCatalog()) {
    // A cascaded candidate the calibration has not measured is predicted as its one-map sibling
    // (the same taps per pixel; the confirmation measures it anyway).
    std::string modelName = c.name;
    if (!model.variants.count(modelName) && c.cascades > 0)
      modelName = c.name.substr(0, c.name.rfind(fmt::format("_cascades{}", c.cascades)));
    if (!model.variants.count(modelName)) continue;
    if (!candidateAccepted(c, light)) continue;  // the checker decides what serves this light
    Option o{&c, true, 0, 0};
    for (Feature f : kFeatures)
      if (f != Feature::SlopeBias && c.has(f) && verdicts.at(f).ruledOut) o.allowed = false;
    o.ms = model.predictMs(modelName, request.map, request.screen);
    for (const SceneStats& s : scenes.stats) o.rmse = std::max(o.rmse, model.predictRmse(modelName, s));
    options.push_back(o);
  }
  // Confirmation order: candidates the statistics allow and the model predicts within the
  // bound (cheapest first; most accurate first with only a budget), then the other allowed
  // ones, then those a statistic ruled out (a prediction can be wrong; a measurement cannot).
  const double margin = model.rules.confirmMargin;
  auto stage = [&](const Option& o) {
    const bool predictedOk = (!request.maxRmse || o.rmse <= *request.maxRmse * margin) &&
                             (!request.budgetMs || o.ms <= *request.budgetMs * margin);
    return o.allowed ? (predictedOk ? 0 : 1) : 2;
  };
  std::stable_sort(options.begin(), options.end(), [&](const Option& a, const Option& b) {
    if (stage(a) != stage(b)) return stage(a) < stage(b);
    return request.maxRmse ? a.ms < b.ms : a.rmse < b.rmse;
  });
  PlanResult result;
  result.stats = scenes.stats;
  const Option* chosen = nullptr;
  std::vector<const Option*> triedOptions;  // result.tried[i] measured triedOptions[i]
  const bool budgetOnly = !request.maxRmse;
  for (const Option& o : options) {
    // With a bound: after a hit, every other allowed candidate (predicted within the bound or
    // not: the error model can be wrong both ways) is confirmed when the model says it may be
    // faster than the best measured (rules.confirmTimeSlack); the fastest within the bound wins.
    if (chosen && !budgetOnly) {
      if (stage(o) > 1) break;
      // With a cost profile the measured times are another device's: the slack is on the model's
      // own predictions, so which candidates are confirmed does not move with this machine's load.
      const double best = request.costProfile ? chosen->ms : result.measured.worstMs;
      if (o.ms > best * model.rules.confirmTimeSlack) continue;
    }
    if (chosen && budgetOnly && stage(o) > 0) break;  // with only a budget, compare the predicted-ok ones
    if (request.log)
      request.log(fmt::format("confirming {} (predicted {:.4f} rmse, {:.2f} ms)", o.c->name, o.rmse, o.ms));
    const Measurement m =
        measureCandidate(ctx, *o.c, scenes, model, request.warmup, request.runs, cache, request.costProfile.get());
    result.tried.push_back(m);
    triedOptions.push_back(&o);
    if (const auto pick = chooseMeasured(result.tried, request.maxRmse, request.budgetMs)) {
      chosen = triedOptions[*pick];
      result.measured = result.tried[*pick];
    }
  }
  if (!chosen) {
    const auto byRmse =
        std::min_element(result.tried.begin(), result.tried.end(),
                         [](const Measurement& a, const Measurement& b) { return a.worstRmse < b.worstRmse; });
    const auto byMs =
        std::min_element(result.tried.begin(), result.tried.end(),
                         [](const Measurement& a, const Measurement& b) { return a.worstMs < b.worstMs; });
    if (request.maxRmse && byRmse->worstRmse > *request.maxRmse)
      throw UnreachableBound(
          fmt::format("--max-rmse {:g} is unreachable on {}: the best reachable bound is {:.4f} (variant {}, "
                      "{:.2f} ms){}",
                      *request.maxRmse, sceneList(scenes), byRmse->worstRmse, byRmse->variant, byRmse->worstMs,
                      resolutionHint(scenes.stats)));
    throw PlanError(
        fmt::format("no variant meets --budget-ms {:g}{} on {}: the fastest is {} at {:.2f} ms (rmse {:.4f})",
                    *request.budgetMs, request.maxRmse ? fmt::format(" within --max-rmse {:g}", *request.maxRmse) : "",
                    sceneList(scenes), byMs->variant, byMs->worstMs, byMs->worstRmse));
  }
  result.chosen = *chosen->c;
  result.predictedMs = chosen->ms;
  result.predictedRmse = chosen->rmse;

  // The written file: one comment per feature with the statistic that decided it.
  DescribeOptions d;
  d.filterName = request.filterName;
  d.slopeBias = useSlopeBias(scenes.stats, model.rules);
  d.contactEpsilon = scenes.stats.empty() ? 0.01 : scenes.stats[0].contactEpsilon;
  d.light = light.light;
  const bool depthFamily = result.chosen.has(Feature::SlopeBias);
  for (Feature f : kFeatures) {
    const FeatureVerdict& v = verdicts.at(f);
    if (f == Feature::Cascades && d.light != LightType::Sun) continue;  // only a sun has cascades to keep or drop
    std::string line;
    if (f == Feature::SlopeBias) {
      line = !depthFamily
                 ? fmt::format("{} dropped: moment filters take no depth bias; {}", featureName(f), v.statistic)
             : result.chosen.cascades > 0
                 ? fmt::format("{} dropped: cascades take a normal offset in their own texels; {}", featureName(f),
                               v.statistic)
             : d.slopeBias && d.light == LightType::Point
                 ? fmt::format("{} kept, in the receiver-plane form (per tap, in the receiver's cube face): {}",
                               featureName(f), v.statistic)
             : d.slopeBias ? fmt::format("{} kept: {}", featureName(f), v.statistic)
                           : fmt::format("{} dropped: {}", featureName(f), v.statistic);
    } else if (result.chosen.has(f)) {
      line = v.ruledOut ? fmt::format("{} kept: {}, but every variant without it missed the bound", featureName(f),
                                      v.statistic)
                        : fmt::format("{} kept: {}", featureName(f), v.statistic);
    } else if (refusedFor.count(f)) {
      line = fmt::format("{} dropped: {}; the checker refuses every variant with it for this light ({})",
                         featureName(f), v.statistic, refusedFor.at(f));
    } else {
      line = v.ruledOut ? fmt::format("{} dropped: {}", featureName(f), v.statistic)
                        : fmt::format("{} dropped: {}; the cheapest variant within the bound does without it",
                                      featureName(f), v.statistic);
    }
    d.featureComments[f] = line;
  }
  std::string bound;
  if (request.maxRmse) bound += fmt::format("rmse <= {:g}", *request.maxRmse);
  if (request.budgetMs) bound += fmt::format("{}time <= {:g} ms", bound.empty() ? "" : ", ", *request.budgetMs);
  d.header = {
      fmt::format("Planned by `{}` (docs/planning.md).", request.command.empty() ? "shadowc plan" : request.command),
      fmt::format("Scenes: {}; bound {}; screen {}^2, map {}^2, reference {}x{} light samples.", sceneList(scenes),
                  bound, request.screen, request.map, request.samples, request.samples),
      fmt::format("Variant {} (model: {:.4f} rmse, {:.2f} ms); measured rmse per scene:", result.chosen.name,
                  result.predictedRmse, result.predictedMs)};
  std::string perScene;
  for (size_t i = 0; i < scenes.stats.size(); ++i)
    perScene += fmt::format("{}{} {:.4f}", i ? ", " : "  ", scenes.stats[i].scene, result.measured.rmse[i]);
  d.header.push_back(perScene);
  result.mapReason = request.mapNote;
  if (!request.mapNote.empty()) d.header.push_back(request.mapNote);
  d.resolution = request.resolution;
  result.text = describeCandidate(result.chosen, d);
  return result;
}

}  // namespace shadowc::planning

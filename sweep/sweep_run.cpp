#include "sweep/sweep_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <tuple>

#include "driver/driver.h"
#include "runtime/executor/busy_machine.h"
#include "runtime/harness/scene_run.h"
#include "runtime/images/png_image.h"
#include "runtime/vulkan/vulkan_context.h"
#include "spec/load_filter.h"
#include "spec/print_filter.h"
#include "sweep/cache_key.h"
#include "sweep/progress.h"
#include "sweep/results_io.h"
#include "sweep/sweep_scene.h"

namespace shadowc::sweep {
namespace {

// The variant's first error in glslc form (no caret lines: the report shows one line each).
std::string firstError(const std::vector<Diagnostic>& diags, std::string* code) {
  for (const Diagnostic& d : diags) {
    if (d.severity != Severity::Error) continue;
    *code = d.code;
    return fmt::format("{}:{}:{}: error: {} [{}]", d.location.file, d.location.line, d.location.column, d.message,
                       d.code);
  }
  *code = "SW003";
  return "the driver rejected the variant without a diagnostic";
}

std::string firstLine(const std::string& s) {
  const size_t nl = s.find('\n');
  return nl == std::string::npos ? s : s.substr(0, nl);
}

struct Checked {
  std::optional<FilterSpec> spec;
  nlohmann::ordered_json specJson;
  std::optional<Skipped> skipped;
};

struct Job {
  size_t variant = 0, caseIndex = 0;
  std::string key;
};

struct Compiled {
  std::optional<CompiledPasses> passes;
  std::optional<CompiledPasses> counted;  // the instrumented build, when the sweep counts
  bool countedTried = false;              // compiled (or failed) once: not again for the next case
  std::string contentHash;
  std::optional<Skipped> skipped;
};

}  // namespace

SweepOutcome runSweep(const SweepSpec& spec, const SweepOptions& o, std::FILE* log) {
  const Expansion e = expand(spec);
  for (const std::string& w : e.warnings) fmt::print(log, "sweep: warning: {}\n", w);
  SweepOutcome outcome;
  Results& res = outcome.results;
  res.sweep = spec.name;
  res.shard = o.shard.text();

  // 1. Which jobs are this shard's, and which variants and cases they need.
  std::vector<bool> variantNeeded(e.variants.size(), false), caseNeeded(e.cases.size(), false);
  for (size_t c = 0; c < e.cases.size(); ++c)
    for (size_t v = 0; v < e.variants.size(); ++v)
      if (o.shard.contains(c * e.variants.size() + v)) variantNeeded[v] = caseNeeded[c] = true;

  // 2. The checker decides validity (driver, stop after Check): cheap, and it gives the
  //    normalized spec the cache key is made of.
  std::vector<Checked> checked(e.variants.size());
  for (const Variant& v : e.variants) {
    if (!variantNeeded[v.index]) continue;
    Checked& ch = checked[v.index];
    driver::Options opt;
    opt.stopAfter = driver::Stage::Check;
    const driver::Result r = driver::compileSource(v.text, v.label, opt);
    if (!r.ok || !r.spec) {
      std::string code;
      const std::string message = firstError(r.diagnostics, &code);
      ch.skipped = Skipped{v.index, v.label, code, message};
    } else {
      ch.spec = *r.spec;
      ch.specJson = specToJson(*r.spec);
    }
    if (ch.skipped) res.skipped.push_back(*ch.skipped);
  }

  // 3. Compile every valid variant, in parallel (the driver keeps no shared mutable state): the
  //    emitted code's content hash is part of the cache key, so a row measured with another
  //    shadowc's shaders (a changed template, folding or recipe) is never reused.
  std::vector<size_t> toCompile;
  for (const Variant& v : e.variants)
    if (variantNeeded[v.index] && checked[v.index].spec) toCompile.push_back(v.index);
  std::map<size_t, Compiled> compiled;
  for (size_t v : toCompile) compiled[v];
  {
    std::atomic<size_t> next{0};
    auto work = [&] {
      for (size_t i; (i = next++) < toCompile.size();) {
        const Variant& v = e.variants[toCompile[i]];
        Compiled& out = compiled.at(v.index);
        driver::Options opt;
        opt.generic = v.shader == ShaderKind::Generic;  // `shadowc compile --generic`
        const driver::Result r = driver::compileSource(v.text, v.label, opt);
        if (r.ok && r.artifact) {
          out.passes = r.artifact->passes();
          out.contentHash = r.artifact->manifest.contentHash;
        } else {
          std::string code;
          std::string message = firstError(r.diagnostics, &code);
          if (r.diagnostics.empty()) message = "compile failed: " + firstLine(r.log);
          out.skipped = Skipped{v.index, v.label, code, message};
        }
      }
    };
    const size_t threads = std::clamp<size_t>(o.jobs > 0 ? size_t(o.jobs) : std::thread::hardware_concurrency(), 1,
                                              std::max<size_t>(1, toCompile.size()));
    if (!toCompile.empty()) fmt::print(log, "sweep: compiling {} variants on {} threads\n", toCompile.size(), threads);
    std::vector<std::thread> pool;
    for (size_t t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
  }
  for (const auto& [v, c] : compiled)
    if (c.skipped) res.skipped.push_back(*c.skipped);
  // 4. Scenes (derived ones written to DIR/scenes/), keys, cache look-ups.
  std::vector<ResolvedScene> scenes(e.cases.size());
  std::map<std::string, ResolvedScene> byLabel;  // one scene serves every screen x map case
  for (const Case& c : e.cases) {
    if (!caseNeeded[c.index]) continue;
    auto it = byLabel.find(c.scene.label);
    if (it == byLabel.end()) it = byLabel.emplace(c.scene.label, resolveScene(c.scene, o.outDir)).first;
    scenes[c.index] = it->second;
  }
  std::vector<Job> pending;
  std::vector<Row> rows;
  std::vector<std::string> busyRows;  // "variant on case" of each row timed on a busy machine
  for (const Case& c : e.cases)
    for (const Variant& v : e.variants) {
      if (!o.shard.contains(c.index * e.variants.size() + v.index) || !checked[v.index].spec ||
          !compiled.at(v.index).passes)
        continue;
      try {  // a light type that is not the scene's: refused before the case's reference is traced
        rt::checkLightType(compiled.at(v.index).passes->manifest, scenes[c.index].lightType, scenes[c.index].name);
      } catch (const std::invalid_argument& ex) {
        res.skipped.push_back({v.index, v.label, "SW002", fmt::format("{}: {}", c.label, ex.what())});
        continue;
      }
      if (int(c.map) > checked[v.index].spec->mapSize) {  // as validate: its precision checks assume at most that
        res.skipped.push_back({v.index, v.label, "SW004",
                               fmt::format("{}: map {} exceeds the filter's map_size {}", c.label, c.map,
                                           checked[v.index].spec->mapSize)});
        continue;
      }
      const std::string key = cacheKey({checked[v.index].specJson, shaderKindName(v.shader),
                                        compiled.at(v.index).contentHash, scenes[c.index].hash, c.screen, c.map,
                                        spec.referenceSamples, spec.runs, spec.warmup, o.device, spec.counters});
      if (std::optional<Row> cached = readCachedRow(o.outDir, key)) {
        cached->variantIndex = v.index;  // the same measurement may sit at another place in a new sweep
        cached->caseIndex = c.index;
        cached->variant = v.label;
        cached->base = v.base;
        cached->params = v.params;
        cached->filterText = v.text;
        cached->normalizedText = printFilter(*checked[v.index].spec);
        cached->caseLabel = c.label;
        cached->scene = c.scene.label;
        rows.push_back(std::move(*cached));
        ++res.stats.cached;
      } else {
        pending.push_back({v.index, c.index, key});
      }
    }
  fmt::print(log, "sweep: {}: {} variants x {} cases{}; {} invalid, {} rows cached, {} to run\n", spec.name,
             e.variants.size(), e.cases.size(), o.shard.count > 1 ? " (shard " + o.shard.text() + ")" : "",
             res.skipped.size(), rows.size(), pending.size());

  // 5. Run, one case at a time: the scene (raster + reference) is prepared once per case.
  if (!pending.empty()) {
    rt::VulkanContext ctx(rt::VulkanOptions{o.device, o.validation});
    Progress progress(log, pending.size(), o.tty);
    std::shared_ptr<const rt::PreparedScene> prepared;
    // The case's scene per light-view configuration its variants ask for (a cascaded sun's or a
    // light-sampled spot's atlas, rt::prepareSceneForFilter; the reference is traced once per case).
    std::vector<std::shared_ptr<const rt::PreparedScene>> withViews;
    size_t preparedCase = SIZE_MAX;
    for (const Job& job : pending) {
      const Variant& v = e.variants[job.variant];
      const Case& c = e.cases[job.caseIndex];
      Compiled& comp = compiled.at(job.variant);
      // The instrumented build only for a variant that has a row to run (a cached row keeps its
      // counts), once for all its cases.
      if (spec.counters && !comp.countedTried) {
        comp.countedTried = true;
        driver::Options counting;
        counting.generic = v.shader == ShaderKind::Generic;
        counting.counters = true;
        const driver::Result r = driver::compileSource(v.text, v.label, counting);
        if (r.ok && r.artifact) comp.counted = r.artifact->passes();
      }
      const std::string refImage = fmt::format("images/case{}-reference.png", c.index);
      if (preparedCase != c.index) {
        progress.note(fmt::format("preparing {} (raster, Embree reference {}x{} samples)", c.label,
                                  spec.referenceSamples, spec.referenceSamples));
        rt::SceneSettings settings;
        settings.scene = scenes[c.index].nameOrPath;
        settings.screen = c.screen;
        settings.map = c.map;
        settings.referenceSamples = spec.referenceSamples;
        settings.useCache = o.useReferenceCache;
        auto last = std::chrono::steady_clock::now();
        prepared = rt::prepareScene(ctx, settings, [&](double fraction, double seconds, double raysPerSecond) {
          if (std::chrono::steady_clock::now() - last < std::chrono::seconds(2)) return;
          last = std::chrono::steady_clock::now();
          progress.note(fmt::format("reference {:.0f}% ({:.1f} s, {:.1f} M rays/s)", 100 * fraction, seconds,
                                    raysPerSecond * 1e-6));
        });
        if (!prepared->referenceCacheWarning.empty()) progress.note("warning: " + prepared->referenceCacheWarning);
        rt::writeVisibilityPng(o.outDir / refImage, prepared->reference, c.screen, c.screen);
        preparedCase = c.index;
        withViews = {prepared};
      }
      Row row;
      try {
        rt::SceneSettings views = prepared->settings;
        rt::setFilterViews(views, comp.passes->manifest.spec);
        auto scene = std::find_if(withViews.begin(), withViews.end(),
                                  [&](const auto& p) { return rt::sameFilterViews(p->settings, views); });
        if (scene == withViews.end()) {
          withViews.push_back(rt::prepareSceneForFilter(ctx, prepared, comp.passes->manifest.spec));
          scene = withViews.end() - 1;
        }
        rt::RunOptions ro;
        ro.warmup = spec.warmup;
        ro.runs = spec.runs;
        const rt::SceneRunResult run = rt::runOnScene(ctx, *comp.passes, **scene, ro);
        row.passes.clear();
        for (const auto& p : run.outputs.timing->passes) row.passes.push_back({p.name, p.kind, p.medianMs});
        row.totalMs = run.outputs.timing->totalMs;
        row.total = run.outputs.timing->stats;
        row.runs = run.outputs.timing->runs;
        row.busyWarning = rt::busyWarning(row.total, run.outputs.timing->otherCpuShare);
        if (!row.busyWarning.empty()) busyRows.push_back(fmt::format("{} on {}", v.label, c.label));
        row.clock = rt::toString(run.outputs.timing->clock);
        row.rejectedRuns = int(run.outputs.timing->rejected.size());
        row.metrics = run.metrics;
        // One untimed run of the instrumented build: the counts of one frame (an instrumented
        // build's times include the counting, so the times above are the plain build's).
        if (comp.counted) row.work = rt::runOnScene(ctx, *comp.counted, **scene, {}).outputs.work;
        row.resultImage = fmt::format("images/{}-result.png", job.key);
        row.errorImage = fmt::format("images/{}-error.png", job.key);
        rt::writeVisibilityPng(o.outDir / row.resultImage, run.outputs.visibility, c.screen, c.screen);
        rt::writeErrorPng(o.outDir / row.errorImage, run.outputs.visibility, prepared->reference, c.screen, c.screen);
      } catch (const std::exception& ex) {
        res.skipped.push_back({v.index, v.label, "SW002", fmt::format("{}: {}", c.label, ex.what())});
        progress.step(fmt::format("{} on {}: failed", v.label, c.label));
        continue;
      }
      row.key = job.key;
      row.variantIndex = v.index;
      row.caseIndex = c.index;
      row.variant = v.label;
      row.base = v.base;
      row.params = v.params;
      row.shader = shaderKindName(v.shader);
      row.caseLabel = c.label;
      row.scene = c.scene.label;
      row.sceneHash = scenes[c.index].hash;
      row.screen = c.screen;
      row.map = c.map;
      row.referenceSamples = spec.referenceSamples;
      row.warmup = spec.warmup;
      row.spec = checked[v.index].specJson;
      row.filterText = v.text;
      row.normalizedText = printFilter(*checked[v.index].spec);
      row.contentHash = comp.contentHash;
      row.device = ctx.deviceName();
      row.referenceImage = refImage;
      writeCachedRow(o.outDir, row);  // atomically, as soon as it is done: resume trusts it
      ++res.stats.ran;
      progress.step(fmt::format("{} on {}: {:.3f} ms ({}, {} rejected), rmse {:.5f}", v.label, c.label, row.totalMs,
                                row.clock, row.rejectedRuns, row.metrics.rmse));
      rows.push_back(std::move(row));
      if (o.stopAfter > 0 && res.stats.ran >= o.stopAfter) {
        progress.finish();
        fmt::print(log, "sweep: stopping abruptly after {} rows (SHADOWC_SWEEP_STOP_AFTER)\n", res.stats.ran);
        std::fflush(log);
        std::_Exit(3);
      }
    }
    progress.finish();
    outcome.validationMessages = ctx.validationMessageCount();
    if (!busyRows.empty())
      fmt::print(log,
                 "sweep: warning: the machine was busy while timing {} of {} rows (first: {}); their intervals are "
                 "wider and overlapping ones are tied on the frontier (docs/sweep.md \"Ties\")\n",
                 busyRows.size(), res.stats.ran, busyRows.front());
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    return std::tie(a.caseIndex, a.variantIndex) < std::tie(b.caseIndex, b.variantIndex);
  });
  std::stable_sort(res.skipped.begin(), res.skipped.end(),
                   [](const Skipped& a, const Skipped& b) { return a.variantIndex < b.variantIndex; });
  res.rows = std::move(rows);
  return outcome;
}

}  // namespace shadowc::sweep

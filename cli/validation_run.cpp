#include "cli/validation_run.h"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "driver/driver.h"
#include "manifest/compiled_passes.h"
#include "planning/scene_analysis.h"
#include "runtime/executor/busy_machine.h"
#include "runtime/executor/pass_forms.h"
#include "runtime/harness/scene_run.h"
#include "runtime/images/atomic_file.h"
#include "runtime/images/png_image.h"
#include "runtime/vulkan/vulkan_context.h"

namespace shadowc::cli {
namespace {

using Clock = std::chrono::steady_clock;

// The passes to run: a manifest written by `shadowc compile` (what an engine built earlier; known
// by its content, not its name), or a filter description compiled here by the driver. Empty when
// it did not compile (the driver's log is on stderr).
// `counters`: the instrumented build of the description (plan/work_counters.h).
bool fromManifest(const ValidationOptions& o) {
  return o.filterSource.empty() && CompiledPasses::isManifest(o.filterPath);
}
std::optional<CompiledPasses> passesToRun(const ValidationOptions& o, bool counters = false) {
  if (fromManifest(o)) return CompiledPasses::fromDirectory(o.filterPath);
  driver::Options options;
  options.counters = counters;
  const driver::Result r = o.filterSource.empty() ? driver::compileFile(o.filterPath, options)
                                                  : driver::compileSource(o.filterSource, o.filterPath, options);
  if (!r.log.empty()) fmt::print(stderr, "{}", r.log);
  if (!r.artifact) return std::nullopt;
  return r.artifact->passes();
}

// The spec facts the harness checks, from the manifest's normalized "spec" (the same JSON for a
// filter compiled here): the light size a filter folded in, the map size its precision checks assumed.
struct SpecFacts {
  bool lightFolded = false;
  double lightSize = 0;
  bool sun = false;  // light{type: "sun"}: an orthographic map (absent type: a spot light)
  int mapSize = 1 << 30;
  int resolution = 0;  // the planned map side (`resolution`, docs/dsl.md), 0 = none
};
SpecFacts specFacts(const Manifest& manifest) {
  SpecFacts f;
  const nlohmann::json& spec = manifest.spec;
  if (spec.contains("light") && spec["light"].contains("size_from_scene") &&
      spec["light"]["size_from_scene"].is_boolean()) {
    f.lightFolded = !spec["light"]["size_from_scene"].get<bool>();
    f.lightSize = spec["light"].value("size", 0.0);
  }
  if (spec.contains("light") && spec["light"].value("type", std::string("spot")) == "sun") {
    f.sun = true;
    f.lightFolded = !spec["light"].value("angle_from_scene", true);
    f.lightSize = spec["light"].value("angle", 0.0);
  }
  if (spec.contains("map_size") && spec["map_size"].is_number_integer()) f.mapSize = spec["map_size"].get<int>();
  if (spec.contains("resolution") && spec["resolution"].is_number_integer())
    f.resolution = spec["resolution"].get<int>();
  return f;
}

void progress(const char* what) { fmt::print(stderr, "shadowc: {}\n", what); }

// Where a penumbra-sized kernel's `max` cuts the scene (a cap must not truncate
// silently): the scene analysis's penumbra widths (planning/scene_analysis.h, the PCSS form over
// its own blocker search, with the scene's light) against the filter's max. The shaders clamp the
// blocker search region and the kernel to max (templates/lookup/kernel.glsl).
struct CapReport {
  double maxTexels = 0;
  uint64_t penumbraPixels = 0, penumbraOverCap = 0;
  double searchP99 = 0;
};
std::optional<CapReport> capReport(const Manifest& manifest, const rt::PreparedScene& prepared) {
  const nlohmann::json& k = manifest.spec.contains("kernel") ? manifest.spec["kernel"] : nlohmann::json();
  if (!k.is_object() || k.value("size", "") != "penumbra") return std::nullopt;
  // The analysis assumes one frustum (`plan` refuses point lights for the same reason).
  if (prepared.scene.light.type == rt::LightType::Point) return std::nullopt;
  const planning::SceneStats stats = planning::analyzeScene(prepared);
  CapReport c;
  c.maxTexels = k.value("max_texels", 0.0);
  c.penumbraPixels = stats.penumbraTexels.count;
  for (double w : stats.penumbraTexels.samples) c.penumbraOverCap += w > c.maxTexels ? 1 : 0;
  c.searchP99 = stats.searchTexelsP99;
  return c;
}

// The counts beside the times: per receiver, every field the build counts that is not zero.
void printWork(const rt::WorkCounts& work) {
  fmt::print("work     {} pass, per receiver over {} receivers (instrumented build, one run)\n", work.pass,
             work.receivers());
  bool any = false;
  for (size_t k = 0; k < work.fields.size(); ++k) {
    if (work.fields[k] == "receivers" || work.totals[k] == 0) continue;
    fmt::print("  {:<16} {:12.3f}   total {}\n", work.fields[k], work.perReceiver(work.fields[k]), work.totals[k]);
    any = true;
  }
  if (!any) fmt::print("  (no work counted)\n");
}

}  // namespace

int runValidation(const ValidationOptions& given) {
  ValidationOptions o = given;
  if (o.size == 0 || o.map == 0 || o.samples < 1 || !o.runs.any() || o.warmup < 0)
    throw std::invalid_argument("--screen, --map, --samples and --runs must be positive, --warmup >= 0");
  // A misspelt form override is refused for every filter, before anything is compiled or traced.
  const std::string passForm = rt::checkedPassForm(o.passForm);

  // 1. The passes to run.
  const std::optional<CompiledPasses> compiled = passesToRun(o);
  if (!compiled) return 1;
  const SpecFacts facts = specFacts(compiled->manifest);
  // A planned filter renders the map it was planned for unless --map says otherwise.
  if (!o.mapGiven && facts.resolution > 0) {
    o.map = uint32_t(facts.resolution);
    fmt::print(stderr, "shadowc: rendering the filter's planned {}^2 map (its `resolution`; --map overrides)\n", o.map);
  }
  if (int(o.map) > facts.mapSize)
    throw std::invalid_argument(fmt::format(
        "--map {} exceeds the filter's map_size {} (its precision checks assume at most that)", o.map, facts.mapSize));
  const Manifest& manifest = compiled->manifest;
  // The instrumented build: the manifest given when it is one, else the description compiled
  // again with the counters (a plain manifest cannot be instrumented: its source is not here).
  const bool instrumented = rt::workCounterBuffer(manifest) != nullptr;
  std::optional<CompiledPasses> counted;
  if (o.counters && !instrumented) {
    if (fromManifest(o))
      throw std::invalid_argument("--counters: '" + o.filterPath +
                                  "' is a plain build; give the .shadow file, or a directory from "
                                  "`shadowc compile --counters`");
    counted = passesToRun(o, true);
    if (!counted) return 1;
  }
  if (instrumented)
    fmt::print(stderr,
               "shadowc: warning: '{}' is an instrumented build (compile --counters): its times include "
               "the counting\n",
               o.filterPath);

  // 2. Scene (its errors come before device errors), device, rasterized inputs and reference.
  rt::Scene loaded = rt::loadScene(o.scene);
  rt::checkLightType(manifest, loaded.light.type, loaded.name);  // before the device, raster and trace
  if (facts.sun && facts.lightFolded && std::abs(facts.lightSize - double(loaded.light.angleDegrees)) > 1e-6)
    fmt::print(stderr,
               "shadowc: warning: the filter's sun angle {} differs from scene '{}' sun angle {}; "
               "the reference uses the scene's sun\n",
               facts.lightSize, loaded.name, loaded.light.angleDegrees);
  // A filter that folds its own light size into the shader ignores the scene's light: the
  // reference traces the scene's light, so the error then measures the mismatch too.
  if (!facts.sun && facts.lightFolded &&
      std::abs(facts.lightSize - double(loaded.light.width)) > 1e-6 * loaded.light.width)
    fmt::print(stderr,
               "shadowc: warning: the filter's light size {} differs from scene '{}' light width {}; "
               "the reference uses the scene's light\n",
               facts.lightSize, loaded.name, loaded.light.width);
  rt::VulkanContext ctx(rt::VulkanOptions{o.device, o.validation});
  rt::SceneSettings settings;
  settings.scene = o.scene;
  settings.screen = o.size;
  settings.map = o.map;
  settings.referenceSamples = o.samples;
  settings.useCache = o.useCache;
  rt::setFilterViews(settings, manifest.spec);  // a cascaded sun's or light-sampled spot's atlas
  progress(fmt::format("tracing the Embree reference ({}x{} pixels, {}x{} light samples)", o.size, o.size, o.samples,
                       o.samples)
               .c_str());
  auto last = Clock::now();
  const std::shared_ptr<const rt::PreparedScene> prepared =
      rt::prepareScene(ctx, std::move(loaded), settings, [&](double fraction, double seconds, double raysPerSecond) {
        if (Clock::now() - last < std::chrono::seconds(2)) return;
        last = Clock::now();
        fmt::print(stderr, "shadowc: reference {:.0f}% ({:.1f} s, {:.1f} M rays/s)\n", 100.0 * fraction, seconds,
                   raysPerSecond * 1e-6);
      });
  if (!prepared->referenceCacheWarning.empty())
    fmt::print(stderr, "shadowc: warning: {}\n", prepared->referenceCacheWarning);
  const rt::Scene& scene = prepared->scene;

  // 3. Passes through the run harness: timed runs, metrics against the reference.
  progress(fmt::format("running {} passes ({} warm-up + {} timed runs) on {}", manifest.passes.size(), o.warmup,
                       rt::toString(o.runs), ctx.deviceName())
               .c_str());
  rt::RunOptions run;
  run.warmup = o.warmup;
  run.runs = o.runs;
  run.passForm = passForm;
  const rt::SceneRunResult measured = rt::runOnScene(ctx, *compiled, *prepared, run);
  const rt::TimingResult& timing = *measured.outputs.timing;
  // One untimed run of the instrumented build: the counts of one frame.
  std::optional<rt::WorkCounts> work = measured.outputs.work;
  if (counted) work = rt::runOnScene(ctx, *counted, *prepared, {}).outputs.work;
  const std::vector<float>& result = measured.outputs.visibility;
  const std::vector<float>& reference = prepared->reference;
  const rt::Metrics& metrics = measured.metrics;

  // 5. Report.
  fmt::print("filter   {} ({} passes)\n", manifest.filter, manifest.passes.size());
  fmt::print("scene    {}  screen {}x{}  map {}^2  reference {}x{} samples{}\n", scene.name, o.size, o.size, o.map,
             o.samples, o.samples, prepared->referenceFromCache ? " (cached)" : "");
  fmt::print("device   {}\n", ctx.describe());
  fmt::print("timing   median of {} runs after {} warm-up, {}\n", timing.runs, timing.warmup, rt::clockSummary(timing));
  for (const auto& p : timing.passes) fmt::print("  {:<16} {:<10} {:9.3f} ms\n", p.name, p.kind, p.medianMs);
  fmt::print("  {:<16} {:<10} {:9.3f} ms\n", "total", "", timing.totalMs);
  fmt::print("  {}{}\n", rt::statsSummary(timing.stats),
             timing.stoppedAtCap ? fmt::format(", stopped at the {:g} s cap", o.runs.capMs / 1000) : "");
  if (const std::string busy = rt::busyWarning(timing.stats, timing.otherCpuShare); !busy.empty())
    fmt::print(stderr, "shadowc: warning: {}\n", busy);
  if (!measured.outputs.forms.empty()) fmt::print("  {}\n", rt::describeChoices(measured.outputs.forms));
  if (work) printWork(*work);
  fmt::print("error    over {} geometry pixels\n", metrics.compared);
  fmt::print("  rmse {:.5f}  mae {:.5f}  max {:.5f}  p99 {:.5f}\n", metrics.rmse, metrics.mae, metrics.maxAbsError,
             metrics.p99AbsError);
  fmt::print("  light bleeding {:.4f}  over-darkening {:.4f}  non-finite {}  out of range {}\n", metrics.lightBleeding,
             metrics.overDarkening, metrics.nonFinite, metrics.outOfRange);
  const std::optional<CapReport> caps = capReport(manifest, *prepared);
  if (caps)
    fmt::print(
        "caps     kernel max {:g} texels: the penumbra is wider on {} of {} penumbra pixels (scene "
        "analysis); blocker search region p99 {:.1f} texels{}\n",
        caps->maxTexels, caps->penumbraOverCap, caps->penumbraPixels, caps->searchP99,
        caps->searchP99 > caps->maxTexels ? ", cut to the max" : "");
  const size_t messages = ctx.validationMessageCount();
  if (ctx.validationEnabled()) fmt::print("validation {} messages\n", messages);

  if (!o.jsonOut.empty()) {
    nlohmann::ordered_json j;
    j["filter"] = manifest.filter;
    j["scene"] = scene.name;
    j["device"] = ctx.deviceName();
    j["screen"] = {o.size, o.size};
    j["map_size"] = o.map;
    j["reference_samples"] = o.samples;
    nlohmann::ordered_json t;
    t["warmup"] = timing.warmup;
    t["runs"] = timing.runs;
    t["clock"] = rt::toString(timing.clock);
    t["rejected_runs"] = timing.rejected.size();
    auto& passes = t["passes"] = nlohmann::ordered_json::array();
    for (const auto& p : timing.passes)
      passes.push_back({{"name", p.name}, {"kind", p.kind}, {"median_ms", p.medianMs}, {"min_ms", p.minMs}});
    t["total_ms"] = timing.totalMs;
    t["total"] = rt::toJson(timing.stats);
    if (timing.otherCpuShare) t["other_cpu_share"] = *timing.otherCpuShare;
    t["busy_warning"] = rt::busyWarning(timing.stats, timing.otherCpuShare);
    t["host_total_ms"] = rt::median(timing.runHostMs);
    if (!measured.outputs.forms.empty()) {
      auto& forms = t["pass_forms"] = nlohmann::ordered_json::array();
      for (const auto& f : measured.outputs.forms)
        forms.push_back({{"pass", f.pass}, {"form", f.form}, {"why", f.why}});
    }
    j["timing"] = std::move(t);
    if (work) j["work"] = rt::workJson(*work);
    j["metrics"] = rt::toJson(metrics);
    if (caps)
      j["caps"] = {{"kernel_max_texels", caps->maxTexels},
                   {"penumbra_pixels", caps->penumbraPixels},
                   {"penumbra_over_max", caps->penumbraOverCap},
                   {"search_texels_p99", caps->searchP99}};
    j["validation_messages"] = messages;
    rt::writeFileAtomically(o.jsonOut, j.dump(2) + "\n");
  }
  if (!o.imagesDir.empty()) {
    const std::filesystem::path d(o.imagesDir);
    rt::writeVisibilityPng(d / "result.png", result, o.size, o.size);
    rt::writeVisibilityPng(d / "reference.png", reference, o.size, o.size);
    rt::writeErrorPng(d / "error.png", result, reference, o.size, o.size);
    rt::writeComparisonPng(d / "comparison.png", result, reference, o.size, o.size);
    // The filter's visibility unrounded (float32, row 0 = top), to compare an engine's against.
    rt::writeFileAtomically(d / "visibility.f32", std::string_view(reinterpret_cast<const char*>(result.data()),
                                                                   result.size() * sizeof(float)));
    fmt::print("images   {}/{{result,reference,error,comparison}}.png, visibility.f32\n", d.string());
  }
  if (messages > 0) {
    std::fflush(stdout);
    fmt::print(stderr, "shadowc: error: the validation layer reported {} message(s)\n", messages);
    return 1;
  }
  if (metrics.compared == 0) {  // "rmse 0" over no pixel would compare nothing
    std::fflush(stdout);
    fmt::print(
        stderr,
        "shadowc: error: nothing compared: the result or the reference is non-finite on all {} geometry pixels\n",
        metrics.pixels);
    return 1;
  }
  return 0;
}

}  // namespace shadowc::cli

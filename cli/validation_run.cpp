#include "cli/validation_run.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "emit/filter_emitter.h"
#include "emit/output_writer.h"
#include "manifest/manifest.h"
#include "runtime/executor/pass_executor.h"
#include "runtime/images/atomic_file.h"
#include "runtime/images/png_image.h"
#include "runtime/metrics/metrics.h"
#include "runtime/raster/rasterizer.h"
#include "runtime/reference/embree_reference.h"
#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"
#include "runtime/vulkan/vulkan_context.h"
#include "spec/load_filter.h"

namespace shadowc::cli {
namespace {

using Clock = std::chrono::steady_clock;

// A temporary directory for the compiled filter, removed on scope exit.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    path = std::filesystem::temp_directory_path() / fmt::format("shadowc-validate-{}-{}", getpid(),
                                                                Clock::now().time_since_epoch().count());
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

// What validate runs: the manifest, the folder holding its .spv files, and the spec facts the
// harness checks (light size against the scene's, the map size the precision checks assumed).
struct CompiledPasses {
  bool ok = false;
  Manifest manifest;
  std::filesystem::path dir;
  std::shared_ptr<TempDir> temp;  // set when compiled here
  bool lightFolded = false;
  double lightSize = 0;
  int mapSize = 1 << 30;
};

bool isManifestPath(const std::string& path) {
  const std::filesystem::path p(path);
  return p.filename() == "manifest.json" || (std::filesystem::is_directory(p) && std::filesystem::exists(p / "manifest.json"));
}

// A manifest written by `shadowc compile`: loadManifest rejects other format versions and
// malformed files with one message; the spec facts come from its normalized "spec".
CompiledPasses loadCompiled(const std::string& path) {
  std::filesystem::path file(path);
  if (std::filesystem::is_directory(file)) file /= "manifest.json";
  CompiledPasses c;
  c.manifest = loadManifest(file.string());
  c.dir = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
  const nlohmann::json& spec = c.manifest.spec;
  if (spec.contains("light") && spec["light"].contains("size_from_scene") && spec["light"]["size_from_scene"].is_boolean()) {
    c.lightFolded = !spec["light"]["size_from_scene"].get<bool>();
    c.lightSize = spec["light"].value("size", 0.0);
  }
  if (spec.contains("map_size") && spec["map_size"].is_number_integer()) c.mapSize = spec["map_size"].get<int>();
  c.ok = true;
  return c;
}

CompiledPasses compileHere(const ValidationOptions& o) {
  CompiledPasses c;
  const LoadResult loaded = o.filterSource.empty() ? loadFilterFile(o.filterPath)
                                                   : loadFilterSource(o.filterSource, o.filterPath);
  if (!loaded.diagnostics.empty()) fmt::print(stderr, "{}", formatDiagnostics(loaded));
  if (!loaded.spec) return c;
  const FilterSpec& spec = *loaded.spec;
  const FilterEmitResult emitted = emitFilter(spec);
  if (!emitted.ok) {
    fmt::print(stderr, "{}", emitted.log);
    return c;
  }
  c.temp = std::make_shared<TempDir>();
  if (const std::string err = writeFilesAtomically(c.temp->path, emitted.files); !err.empty()) throw std::runtime_error(err);
  c.manifest = emitted.manifest;
  c.dir = c.temp->path;
  c.lightFolded = !spec.light.sizeFromScene;
  c.lightSize = spec.light.size;
  c.mapSize = spec.mapSize;
  c.ok = true;
  return c;
}

void progress(const char* what) { fmt::print(stderr, "shadowc: {}\n", what); }

}  // namespace

int runValidation(const ValidationOptions& o) {
  if (o.size == 0 || o.map == 0 || o.samples < 1 || o.runs < 1 || o.warmup < 0)
    throw std::invalid_argument("--size, --map, --samples and --runs must be positive, --warmup >= 0");

  // 1. The passes to run: a compiled manifest (what an engine built earlier), or a filter
  //    description compiled here in process into a temp dir.
  const CompiledPasses compiled = isManifestPath(o.filterPath) && o.filterSource.empty()
                                      ? loadCompiled(o.filterPath)
                                      : compileHere(o);
  if (!compiled.ok) return 1;
  if (int(o.map) > compiled.mapSize)
    throw std::invalid_argument(fmt::format("--map {} exceeds the filter's map_size {} (its precision checks assume at most that)",
                                            o.map, compiled.mapSize));
  const Manifest& manifest = compiled.manifest;

  // 2. Scene, frame, device, rasterized inputs.
  const rt::Scene scene = rt::loadScene(o.scene);
  const rt::FrameSetup setup = rt::setupFrame(scene, o.map, o.size, o.size);
  // A filter that folds its own light size into the shader ignores the scene's light: the
  // reference traces the scene's light, so the error then measures the mismatch too.
  if (compiled.lightFolded && std::abs(compiled.lightSize - double(scene.light.width)) > 1e-6 * scene.light.width)
    fmt::print(stderr, "shadowc: warning: the filter's light size {} differs from scene '{}' light width {}; "
                       "the reference uses the scene's light\n", compiled.lightSize, scene.name, scene.light.width);
  rt::VulkanContext ctx(rt::VulkanOptions{o.device, o.validation});
  const rt::RasterOutputs raster = rt::rasterize(ctx, scene, setup);

  // 3. Passes: inputs by role, timed runs (the last run leaves the visibility image).
  rt::PassExecutor ex(ctx, manifest, compiled.dir, o.map, o.size, o.size);
  ex.setFrame(setup.frame);
  auto uploadRole = [&](ImageRole role, const rt::HostImage& image) {
    const std::string name = ex.imageWithRole(role);
    if (!name.empty()) ex.upload(name, image);
  };
  uploadRole(ImageRole::InputDepth, raster.lightDepth);
  uploadRole(ImageRole::InputPosition, raster.gbufferPosition);
  uploadRole(ImageRole::InputNormal, raster.gbufferNormal);
  const std::string output = ex.imageWithRole(ImageRole::OutputVisibility);
  if (output.empty()) throw std::runtime_error("the manifest has no output_visibility image");
  progress(fmt::format("running {} passes ({} warm-up + {} timed runs) on {}", manifest.passes.size(), o.warmup,
                       o.runs, ctx.deviceName()).c_str());
  const rt::TimingResult timing = ex.time(o.warmup, o.runs);
  const std::vector<float> result = ex.download(output).channel(0);

  // 4. Ground truth and error.
  const std::vector<float> positions = raster.gbufferPosition.floats();
  const std::vector<float> normals = raster.gbufferNormal.floats();
  progress(fmt::format("tracing the Embree reference ({}x{} pixels, {}x{} light samples)", o.size, o.size, o.samples,
                       o.samples).c_str());
  auto last = Clock::now();
  const rt::ReferenceResult reference = rt::traceReference(
      scene, positions, normals, o.size, o.size, o.samples, {},
      [&](const rt::ReferenceProgress& p) {
        if (Clock::now() - last < std::chrono::seconds(2)) return;
        last = Clock::now();
        fmt::print(stderr, "shadowc: reference {:.0f}% ({:.1f} s, {:.1f} M rays/s)\n",
                   100.0 * double(p.pixelsDone) / double(std::max<uint64_t>(1, p.pixelsTotal)), p.seconds,
                   p.raysPerSecond * 1e-6);
      },
      o.useCache);
  if (!reference.cacheWarning.empty()) fmt::print(stderr, "shadowc: warning: {}\n", reference.cacheWarning);
  const rt::Metrics metrics = rt::computeMetrics(result, reference.visibility, rt::geometryMask(positions));

  // 5. Report.
  fmt::print("filter   {} ({} passes)\n", manifest.filter, manifest.passes.size());
  fmt::print("scene    {}  screen {}x{}  map {}^2  reference {}x{} samples{}\n", scene.name, o.size, o.size, o.map,
             o.samples, o.samples, reference.fromCache ? " (cached)" : "");
  fmt::print("device   {}\n", ctx.describe());
  fmt::print("timing   median of {} runs after {} warm-up, GPU timestamps\n", timing.runs, timing.warmup);
  for (const auto& p : timing.passes) fmt::print("  {:<16} {:<10} {:9.3f} ms\n", p.name, p.kind, p.medianMs);
  fmt::print("  {:<16} {:<10} {:9.3f} ms\n", "total", "", timing.totalMs);
  fmt::print("error    over {} geometry pixels\n", metrics.compared);
  fmt::print("  rmse {:.5f}  mae {:.5f}  max {:.5f}  p99 {:.5f}\n", metrics.rmse, metrics.mae, metrics.maxAbsError,
             metrics.p99AbsError);
  fmt::print("  light bleeding {:.4f}  over-darkening {:.4f}  non-finite {}  out of range {}\n", metrics.lightBleeding,
             metrics.overDarkening, metrics.nonFinite, metrics.outOfRange);
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
    auto& passes = t["passes"] = nlohmann::ordered_json::array();
    for (const auto& p : timing.passes)
      passes.push_back({{"name", p.name}, {"kind", p.kind}, {"median_ms", p.medianMs}, {"min_ms", p.minMs}});
    t["total_ms"] = timing.totalMs;
    j["timing"] = std::move(t);
    j["metrics"] = rt::toJson(metrics);
    j["validation_messages"] = messages;
    rt::writeFileAtomically(o.jsonOut, j.dump(2) + "\n");
  }
  if (!o.imagesDir.empty()) {
    const std::filesystem::path d(o.imagesDir);
    rt::writeVisibilityPng(d / "result.png", result, o.size, o.size);
    rt::writeVisibilityPng(d / "reference.png", reference.visibility, o.size, o.size);
    rt::writeErrorPng(d / "error.png", result, reference.visibility, o.size, o.size);
    rt::writeComparisonPng(d / "comparison.png", result, reference.visibility, o.size, o.size);
    fmt::print("images   {}/{{result,reference,error,comparison}}.png\n", d.string());
  }
  if (messages > 0) {
    std::fflush(stdout);
    fmt::print(stderr, "shadowc: error: the validation layer reported {} message(s)\n", messages);
    return 1;
  }
  return 0;
}

}  // namespace shadowc::cli

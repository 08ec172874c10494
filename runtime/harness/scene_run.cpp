#include "runtime/harness/scene_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "runtime/reference/embree_reference.h"

namespace shadowc::rt {
namespace {

// The light side of a preparation: the frame (with the settings' cascades) and the rasterized
// light depth and G-buffer.
void fitAndRasterize(VulkanContext& ctx, PreparedScene& p) {
  p.setup = fitFrame(p.scene, p.settings);
  p.raster = rasterize(ctx, p.scene, p.setup, p.settings.hardwareDepth);
}

}  // namespace

FrameSetup fitFrame(const Scene& scene, const SceneSettings& s) {
  FrameSetup f = setupFrame(scene, s.map, s.screen, s.screen, s.cubeTanHalf);
  setupCascades(scene, s.cascades, f);
  setupLightSamples(scene, s.lightSamples, f);
  return f;
}

std::shared_ptr<const PreparedScene> prepareScene(VulkanContext& ctx, const SceneSettings& settings,
                                                  const ReferenceProgressFn& progress) {
  return prepareScene(ctx, loadScene(settings.scene), settings, progress);
}

std::shared_ptr<const PreparedScene> prepareScene(VulkanContext& ctx, Scene scene, const SceneSettings& settings,
                                                  const ReferenceProgressFn& progress) {
  if (settings.screen == 0 || settings.map == 0 || settings.referenceSamples < 1)
    throw std::invalid_argument("screen and map sizes and reference samples must be positive");
  auto p = std::make_shared<PreparedScene>();
  p->settings = settings;
  p->scene = std::move(scene);
  fitAndRasterize(ctx, *p);
  const std::vector<float> positions = p->raster.gbufferPosition.floats();
  p->mask = geometryMask(positions);
  if (!settings.traceReference) return p;
  // Metrics over no pixel would read "rmse 0": refuse before the trace, the expensive part.
  if (std::none_of(p->mask.begin(), p->mask.end(), [](uint8_t m) { return m != 0; }))
    throw SceneError(fmt::format(
        "scene '{}': the camera sees no geometry ({}x{} pixels, none on a surface), so nothing would be compared "
        "against the reference: aim camera.eye/target at the objects (docs/scenes.md)",
        p->scene.name, settings.screen, settings.screen));
  ProgressFn onProgress;
  if (progress)
    onProgress = [&progress](const ReferenceProgress& r) {
      progress(double(r.pixelsDone) / double(std::max<uint64_t>(1, r.pixelsTotal)), r.seconds, r.raysPerSecond);
    };
  // The on-disk cache is keyed by content (scene hash, G-buffer bytes, samples): embree_reference.h.
  ReferenceResult reference =
      traceReference(p->scene, positions, p->raster.gbufferNormal.floats(), settings.screen, settings.screen,
                     settings.referenceSamples, settings.referenceCache, onProgress, settings.useCache);
  p->reference = std::move(reference.visibility);
  p->referenceFromCache = reference.fromCache;
  p->referenceCacheWarning = reference.cacheWarning;
  return p;
}

void setFilterViews(SceneSettings& s, const nlohmann::json& spec) {
  s.cascades = cascadeConfigFromSpec(spec);
  s.lightSamples = lightSampleConfigFromSpec(spec);
  s.hardwareDepth = hardwareDepthFromSpec(spec);
}

bool sameFilterViews(const SceneSettings& a, const SceneSettings& b) {
  return a.cascades == b.cascades && a.lightSamples == b.lightSamples && a.hardwareDepth == b.hardwareDepth;
}

std::shared_ptr<const PreparedScene> prepareSceneForFilter(VulkanContext& ctx,
                                                           std::shared_ptr<const PreparedScene> base,
                                                           const nlohmann::json& spec) {
  SceneSettings settings = base->settings;
  setFilterViews(settings, spec);
  if (sameFilterViews(settings, base->settings)) return base;
  auto p = std::make_shared<PreparedScene>(*base);
  p->settings = settings;
  fitAndRasterize(ctx, *p);  // refuses cascades on a spot or point light, light samples on a sun (SceneError)
  // Same camera, same G-buffer: the base's reference and mask hold for this frame too.
  if (p->raster.gbufferPosition.floats() != base->raster.gbufferPosition.floats())
    throw std::logic_error("the light views changed the camera's G-buffer of scene '" + base->scene.name + "'");
  return p;
}

void checkLightType(const Manifest& manifest, LightType sceneLight, const std::string& sceneName) {
  // The runtime knows no technique, but the projection is the frame's: a filter reads the map
  // through its light's (frame.glsl or frame_ortho.glsl), so a sun filter needs a sun scene.
  // A point filter reads a cube atlas (frame_cube.glsl), so it needs a point scene.
  const nlohmann::json& spec = manifest.spec;
  const std::string filterType = spec.contains("light") && spec["light"].is_object()
                                     ? spec["light"].value("type", std::string("spot"))
                                     : std::string("spot");
  const std::string sceneType = sceneLight == LightType::Sun     ? "sun"
                                : sceneLight == LightType::Point ? "point"
                                                                 : "spot";
  auto what = [](const std::string& t) { return t == "sun" ? "sun" : t == "point" ? "point light" : "spot light"; };
  if (filterType != sceneType)
    throw std::invalid_argument(fmt::format(
        "filter '{}' is for a {} but scene '{}' has a {}: compile the filter with 'light {}' (docs/dsl.md \"light\")",
        manifest.filter, what(filterType), sceneName, what(sceneType),
        sceneType == "sun"     ? "sun"
        : sceneType == "point" ? "point(radius: scene)"
                               : "area(size: scene)"));
}

RunInputs sceneInputs(const CompiledPasses& passes, const PreparedScene& scene) {
  checkLightType(passes.manifest, scene.scene.light.type, scene.scene.name);
  const nlohmann::json& spec = passes.manifest.spec;
  SceneSettings wanted = scene.settings;
  setFilterViews(wanted, spec);
  if (!sameFilterViews(wanted, scene.settings))
    throw std::invalid_argument(fmt::format(
        "filter '{}' has {} cascades, {} light views and {} depth input but scene '{}' was prepared with {}, {} and "
        "{}: prepare it with the manifest's views (setFilterViews(settings, manifest.spec))",
        passes.manifest.filter, wanted.cascades.count, wanted.lightSamples.count, toString(wanted.hardwareDepth.format),
        scene.scene.name, scene.settings.cascades.count, scene.settings.lightSamples.count,
        toString(scene.settings.hardwareDepth.format)));
  RunInputs inputs;
  inputs.frame = scene.setup.frame;
  inputs.mapSize = scene.setup.mapSize;
  inputs.width = scene.setup.width;
  inputs.height = scene.setup.height;
  inputs.lightDepth = scene.raster.lightDepth;
  inputs.hardwareDepth = scene.raster.hardwareDepth;
  inputs.position = scene.raster.gbufferPosition;
  inputs.normal = scene.raster.gbufferNormal;
  return inputs;
}

SceneRunResult runOnScene(VulkanContext& ctx, const CompiledPasses& passes, const PreparedScene& scene,
                          const RunOptions& options) {
  if (scene.reference.size() != scene.mask.size())
    throw std::invalid_argument("scene '" + scene.scene.name +
                                "' was prepared without its reference (traceReference = false)");
  const RunInputs inputs = sceneInputs(passes, scene);
  SceneRunResult r;
  r.outputs = runPasses(ctx, passes, inputs, options);
  r.metrics = computeMetrics(r.outputs.visibility, scene.reference, scene.mask);
  return r;
}

}  // namespace shadowc::rt

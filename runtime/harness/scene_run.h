// A compiled filter on a scene, measured against the ground truth: rasterize the scene's light
// depth and G-buffer, run the passes through the run harness (run_harness.h), trace the Embree
// reference (cached by content hash), compute the metrics. What `validate`, `demo`, `sweep`,
// `plan` and the GPU accuracy tests share.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "runtime/harness/run_harness.h"
#include "runtime/metrics/metrics.h"
#include "runtime/raster/rasterizer.h"
#include "runtime/scene/cascade_setup.h"
#include "runtime/scene/frame_setup.h"
#include "runtime/scene/light_sample_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {

struct SceneSettings {
  std::string scene = "two_planes";      // a built-in name or a .json path (loadScene)
  uint32_t screen = 256;                 // square screen side
  uint32_t map = 1024;                   // shadow-map side
  int referenceSamples = 16;             // light samples per axis for the Embree reference
  std::filesystem::path referenceCache;  // empty = the default cache ($SHADOWC_CACHE_DIR or ~/.cache/shadowc)
  bool useCache = true;
  // false: rasterize only, no Embree trace (`shadowc analyze` reads the light depth map and the
  // G-buffer alone); PreparedScene::reference stays empty and runOnScene refuses the scene.
  bool traceReference = true;
  // A point light's face half-fov tangent (cube_setup.h): 1.5 gives the guard band the lookup's
  // kernels need at face seams; 1 (no band) only for the seam test's failing sibling.
  float cubeTanHalf = kCubeTanHalf;
  // A cascaded sun filter's cascades (cascadeConfigFromSpec of its manifest): the light depth is
  // then an atlas of cascades fitted to the camera; the reference does not depend on them.
  CascadeConfig cascades;
  // A light-sampled spot filter's views (lightSampleConfigFromSpec of its manifest): the light
  // depth is then an atlas of hard views from points on the light; the reference does not depend
  // on them either.
  LightSampleConfig lightSamples;
  // A hardware-depth filter's depth attachment (hardwareDepthFromSpec of its manifest): the light
  // pass then also keeps its depth attachment in that format and direction, the filter's input.
  HardwareDepth hardwareDepth;
};

// The frame `s` fits on `scene`: light frustum, camera, and the settings' cascades and light
// samples (what prepareScene rasterizes; CPU only). Throws SceneError as those setups do.
FrameSetup fitFrame(const Scene& scene, const SceneSettings& s);

// The light views a filter's manifest asks for (its cascades, its light samples, the depth
// attachment it reads), set into `s`.
// Throws std::invalid_argument on a malformed spec.
void setFilterViews(SceneSettings& s, const nlohmann::json& spec);
// True when scenes prepared with `a` and `b` have the same light views.
bool sameFilterViews(const SceneSettings& a, const SceneSettings& b);

// The scene side, computed once and reusable for many filters (a sweep runs every variant on it).
struct PreparedScene {
  SceneSettings settings;
  Scene scene;
  FrameSetup setup;
  RasterOutputs raster;
  std::vector<float> reference;  // Embree visibility, width x height
  std::vector<uint8_t> mask;     // geometry pixels
  bool referenceFromCache = false;
  std::string referenceCacheWarning;
};

// Progress of the reference trace (fraction done, seconds so far), for a progress line.
using ReferenceProgressFn = std::function<void(double fraction, double seconds, double raysPerSecond)>;

// Loads settings.scene (loadScene: one located message for a bad name or file), then as below.
// Throws SceneError, before tracing, when the camera sees no geometry (nothing to compare).
std::shared_ptr<const PreparedScene> prepareScene(VulkanContext& ctx, const SceneSettings& settings,
                                                  const ReferenceProgressFn& progress = {});
// A scene already loaded (a caller that looks at it before the device exists: `validate`
// reports scene errors before device errors); settings.scene is only its label.
std::shared_ptr<const PreparedScene> prepareScene(VulkanContext& ctx, Scene scene, const SceneSettings& settings,
                                                  const ReferenceProgressFn& progress = {});
// `base` prepared for a filter with other light views (setFilterViews of its manifest's spec:
// cascades, light samples): the frame fitted and the light depth rasterized again, the reference
// and geometry mask shared (the camera and G-buffer do not depend on the light views, so neither
// does the reference). `base` itself when the views are already its own. What `sweep` and `plan`
// run cascaded and light-sampled filters on.
std::shared_ptr<const PreparedScene> prepareSceneForFilter(VulkanContext& ctx,
                                                           std::shared_ptr<const PreparedScene> base,
                                                           const nlohmann::json& spec);

struct SceneRunResult {
  RunOutputs outputs;  // visibility, timing (when runs > 0)
  Metrics metrics;     // outputs.visibility against the reference over the geometry mask
};

// Throws std::invalid_argument when the filter's light type (spot, sun, point) is not the
// scene's: a check on the manifest and the scene's light alone, so a caller can make it before
// rasterizing and tracing (`validate`, `sweep`; sceneInputs makes it again).
void checkLightType(const Manifest& manifest, LightType sceneLight, const std::string& sceneName);

// The harness inputs of a prepared scene for a filter: its frame, light depth and G-buffer.
// Throws std::invalid_argument when the filter's light type or light views (cascades, light samples) are not the
// scene's.
RunInputs sceneInputs(const CompiledPasses& passes, const PreparedScene& scene);

SceneRunResult runOnScene(VulkanContext& ctx, const CompiledPasses& passes, const PreparedScene& scene,
                          const RunOptions& options = {});

}  // namespace shadowc::rt

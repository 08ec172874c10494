// Ground truth, ray traced with Embree: by default the shadowing term a renderer multiplies its
// lighting by (docs/scenes.md "Ground truth"; the ratio estimator of Heitz, Hill & McGuire 2018):
// unoccluded light over all light, each light sample weighted by cos(theta_receiver) *
// cos(theta_light) / r^2, over the part of the light in front of the receiver's tangent plane.
// Light behind that plane is the N.L term's business, not the shadow's. The unweighted fraction
// of the whole light (what this file computed before) stays available as LightFraction.
// Stratified N x N samples on the light rectangle, or on the disk through the concentric
// mapping (Shirley & Chiu 1997); a point light (width 0) is one ray; a sun, stratified directions
// on its cone of directions, weighted by cos(theta_receiver). Results are cached on disk
// by content (measure, scene hash, exact G-buffer bytes, samples).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "runtime/scene/scene.h"

namespace shadowc::rt {

// What one reference pixel holds.
enum class ReferenceMeasure : uint8_t {
  // Sum of w over unoccluded samples / sum of w over all samples, w = cos_r cos_l / r^2, only the
  // samples in front of the receiver's tangent plane. A point with no light in front of its plane
  // gets 0: it receives no light, and a shadow map sees it behind its own lit side.
  ShadowingTerm,
  // Unoccluded samples / all samples of the whole light, unweighted (rays from light samples
  // behind the tangent plane hit the receiver itself and count as shadow).
  LightFraction,
};
const char* referenceMeasureName(ReferenceMeasure m);  // "shadowing_term", "light_fraction"

struct ReferenceProgress {
  uint64_t pixelsDone = 0, pixelsTotal = 0;
  uint64_t rays = 0;   // traced so far
  double seconds = 0;  // wall time so far
  double raysPerSecond = 0;
};
using ProgressFn = std::function<void(const ReferenceProgress&)>;

struct ReferenceResult {
  uint32_t width = 0, height = 0;
  int samplesPerAxis = 0;
  ReferenceMeasure measure = ReferenceMeasure::ShadowingTerm;
  std::vector<float> visibility;  // width * height, row 0 first, in [0, 1]; background = 1
  bool fromCache = false;
  std::filesystem::path cacheFile;  // empty when caching was off or failed
  std::string cacheWarning;         // why the cache could not be written (never fatal)
  uint64_t rays = 0;                // traced (0 when read from the cache)
  double seconds = 0;
  double raysPerSecond = 0;
};

// $SHADOWC_CACHE_DIR, else $XDG_CACHE_HOME/shadowc, else ~/.cache/shadowc.
std::filesystem::path defaultReferenceCacheDir();

// positionsRGBA / normalsRGBA: width * height * 4 floats (the G-buffer convention: w = 0 for
// background). cacheDir: empty = defaultReferenceCacheDir(). useCache = false neither reads
// nor writes the cache. Throws std::invalid_argument on mismatched sizes or samplesPerAxis < 1.
ReferenceResult traceReference(const Scene& scene, const std::vector<float>& positionsRGBA,
                               const std::vector<float>& normalsRGBA, uint32_t width, uint32_t height,
                               int samplesPerAxis, const std::filesystem::path& cacheDir, ProgressFn progress = {},
                               bool useCache = true, ReferenceMeasure measure = ReferenceMeasure::ShadowingTerm);

// The visibility of one point, exactly as traceReference computes a pixel (pixelIndex seeds
// the jitter). For tests and tools; builds its own BVH each call, so not for loops.
float referenceVisibilityAt(const Scene& scene, const glm::vec3& position, const glm::vec3& normal, int samplesPerAxis,
                            uint64_t pixelIndex = 0, ReferenceMeasure measure = ReferenceMeasure::ShadowingTerm);

// Point on the light for stratum (i, j) of n x n with jitter (ju, jv) in [0, 1): rectangle
// sides along lightBasis x/y; disk by the concentric mapping. Exposed for tests.
glm::vec3 lightSamplePoint(const AreaLight& light, int i, int j, int n, float ju, float jv);
// A sun's direction (unit, towards the sun) for stratum (i, j) of n x n: the concentric disk
// mapped onto the cap of half-angle angle / 2 around -light.direction, equal solid angle per
// stratum. Exposed for tests.
glm::vec3 sunSampleDirection(const AreaLight& light, int i, int j, int n, float ju, float jv);
// A point light's direction (unit, from `from` towards the sphere) for stratum (i, j) of n x n:
// the same equal-solid-angle cap mapping on the cone that the sphere subtends from `from`
// (half-angle asin(radius / distance)). Exposed for tests.
glm::vec3 pointSampleDirection(const AreaLight& light, const glm::vec3& from, int i, int j, int n, float ju, float jv);

}  // namespace shadowc::rt

// Ground truth: per-pixel fraction of the area light visible from each G-buffer point,
// ray traced with Embree (unweighted: no cosine, no distance falloff — the quantity every
// shadow filter estimates). Stratified N x N samples on the light rectangle, or on the disk
// through the concentric mapping (Shirley & Chiu 1997); a point light (width 0) is one ray.
// Results are cached on disk by content (scene hash, exact G-buffer bytes, samples).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "runtime/scene/scene.h"

namespace shadowc::rt {

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
                               bool useCache = true);

// The visibility of one point, exactly as traceReference computes a pixel (pixelIndex seeds
// the jitter). For tests and tools; builds its own BVH each call, so not for loops.
float referenceVisibilityAt(const Scene& scene, const glm::vec3& position, const glm::vec3& normal, int samplesPerAxis,
                            uint64_t pixelIndex = 0);

// Point on the light for stratum (i, j) of n x n with jitter (ju, jv) in [0, 1): rectangle
// sides along lightBasis x/y; disk by the concentric mapping. Exposed for tests.
glm::vec3 lightSamplePoint(const AreaLight& light, int i, int j, int n, float ju, float jv);

}  // namespace shadowc::rt

#include "runtime/reference/embree_reference.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <stdexcept>

#define XXH_INLINE_ALL
#include <xxhash.h>

#include "runtime/images/atomic_file.h"
#include "runtime/reference/embree_scene.h"
#include "runtime/scene/frame_setup.h"

namespace shadowc::rt {
namespace {

constexpr char kCacheMagic[8] = {'S', 'H', 'C', 'R', 'E', 'F', '0', '1'};
constexpr uint64_t kJitterSeed = 0x5ad0c5eedULL;

// splitmix64: a fixed, platform-independent jitter per (pixel, sample): the result does not
// depend on thread scheduling.
uint64_t mix(uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}
float unitFloat(uint64_t bits) { return static_cast<float>(bits >> 40) * (1.0f / 16777216.0f); }  // [0, 1)

// Ray origin offset along the normal, relative to the point's own magnitude (fp32 G-buffer and
// Embree round-off grow with |p|) and to its distance from the light, so it works from the
// depth_range scene's 1e-3 to its 1e4.
float normalOffset(const glm::vec3& p, const glm::vec3& lightPos) {
  const float mag = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return 1e-4f * std::max({mag, 0.01f * glm::length(p - lightPos), 1e-20f});
}

struct PixelValue {
  float visibility = 1;
  int rays = 0;
};

class PixelTracer {
 public:
  PixelTracer(const EmbreeScene& embree, int samplesPerAxis, ReferenceMeasure measure)
      : embree_(embree),
        light_(embree.scene().light),
        n_(light_.width > 0 || light_.type != LightType::Spot ? samplesPerAxis : 1),
        measure_(measure) {}

  PixelValue visibility(const glm::vec3& p, const glm::vec3& normal, uint64_t pixelIndex) const {
    if (light_.type == LightType::Sun) return sunVisibility(p, normal, pixelIndex);
    if (light_.type == LightType::Point) return pointVisibility(p, normal, pixelIndex);
    const glm::vec3 org = p + normalOffset(p, light_.position) * normal;
    const bool weighted = measure_ == ReferenceMeasure::ShadowingTerm;
    // Double sums: 1024^2 samples of weights spanning many orders of magnitude (depth_range).
    double unoccluded = 0, total = 0;
    int rays = 0;
    for (int j = 0; j < n_; ++j) {
      for (int i = 0; i < n_; ++i) {
        const uint64_t h = mix(mix(pixelIndex ^ kJitterSeed) + static_cast<uint64_t>(j * n_ + i));
        const glm::vec3 target = lightSamplePoint(light_, i, j, n_, unitFloat(h), unitFloat(mix(h)));
        double w = 1;
        if (weighted) {
          // cos_r cos_l / r^2 = (n . d)(l . -d) / |d|^4 with d = sample - point; samples behind
          // the tangent plane (n . d <= 0) are not part of the shadowing term's light.
          const glm::dvec3 d = glm::dvec3(target) - glm::dvec3(p);
          const double cosR = glm::dot(glm::dvec3(normal), d);
          if (cosR <= 0) continue;
          const double cosL = std::max(0.0, -glm::dot(glm::dvec3(light_.direction), d));
          const double d2 = glm::dot(d, d);
          w = cosR * cosL / (d2 * d2);
          if (!(w > 0)) continue;
        }
        total += w;
        ++rays;
        // Traced from the light sample to the (offset) point, not the other way: the light's
        // coordinates are the small ones, so an occluder 1e-3 in front of a light seen from a
        // receiver 1e4 away (depth_range) is still resolved in fp32; the segment ends at the
        // offset point, so the receiver itself is never hit.
        if (!embree_.occluded(target, org - target, 1.0f)) unoccluded += w;
      }
    }
    // No light in front of the tangent plane: the point receives none (see ReferenceMeasure).
    if (total <= 0) return {0.0f, rays};
    return {static_cast<float>(std::clamp(unoccluded / total, 0.0, 1.0)), rays};
  }

 private:
  // A sun: stratified directions on its cone (sunSampleDirection), each weighted by
  // cos(theta_receiver) alone (cos_l / r^2 is the same for every point of a distant light);
  // directions below the tangent plane are not part of the shadowing term's light.
  PixelValue sunVisibility(const glm::vec3& p, const glm::vec3& normal, uint64_t pixelIndex) const {
    const glm::vec3 org = p + normalOffset(p, p) * normal;
    const bool weighted = measure_ == ReferenceMeasure::ShadowingTerm;
    double unoccluded = 0, total = 0;
    int rays = 0;
    for (int j = 0; j < n_; ++j) {
      for (int i = 0; i < n_; ++i) {
        const uint64_t h = mix(mix(pixelIndex ^ kJitterSeed) + static_cast<uint64_t>(j * n_ + i));
        const glm::vec3 dir = sunSampleDirection(light_, i, j, n_, unitFloat(h), unitFloat(mix(h)));
        const double cosR = glm::dot(glm::dvec3(normal), glm::dvec3(dir));
        if (weighted && cosR <= 0) continue;
        const double w = weighted ? cosR : 1.0;
        total += w;
        ++rays;
        if (cosR > 0 && !embree_.occluded(org, dir * rayLength_, 1.0f)) unoccluded += w;
      }
    }
    if (total <= 0) return {0.0f, rays};
    return {static_cast<float>(std::clamp(unoccluded / total, 0.0, 1.0)), rays};
  }

  // A point light: stratified directions on the cone the sphere subtends (pointSampleDirection),
  // equal solid angle each, weighted by cos(theta_receiver): over the sphere cos_l dA / r^2 = dw,
  // so this is the ratio estimator of docs/scenes.md; directions below the tangent plane are not
  // part of the shadowing term's light. Each ray ends on the sphere's near surface.
  PixelValue pointVisibility(const glm::vec3& p, const glm::vec3& normal, uint64_t pixelIndex) const {
    const glm::vec3 org = p + normalOffset(p, light_.position) * normal;
    const bool weighted = measure_ == ReferenceMeasure::ShadowingTerm;
    const glm::dvec3 toCentre = glm::dvec3(light_.position) - glm::dvec3(org);
    const double dist2 = glm::dot(toCentre, toCentre), r2 = double(light_.radius) * light_.radius;
    double unoccluded = 0, total = 0;
    int rays = 0;
    for (int j = 0; j < n_; ++j) {
      for (int i = 0; i < n_; ++i) {
        const uint64_t h = mix(mix(pixelIndex ^ kJitterSeed) + static_cast<uint64_t>(j * n_ + i));
        const glm::vec3 dir = pointSampleDirection(light_, org, i, j, n_, unitFloat(h), unitFloat(mix(h)));
        const double cosR = glm::dot(glm::dvec3(normal), glm::dvec3(dir));
        if (weighted && cosR <= 0) continue;
        const double w = weighted ? cosR : 1.0;
        total += w;
        ++rays;
        const double b = glm::dot(toCentre, glm::dvec3(dir));
        const double t = b - std::sqrt(std::max(0.0, b * b - (dist2 - r2)));
        if (cosR > 0 && !embree_.occluded(org, dir * static_cast<float>(std::max(t, 0.0)), 1.0f)) unoccluded += w;
      }
    }
    if (total <= 0) return {0.0f, rays};
    return {static_cast<float>(std::clamp(unoccluded / total, 0.0, 1.0)), rays};
  }
  const EmbreeScene& embree_;
  const AreaLight& light_;
  float rayLength_ = 2.0f * std::max(sceneBounds(embree_.scene()).diagonal(), 1.0f);
  int n_;
  ReferenceMeasure measure_;
};

std::string cacheKey(const Scene& scene, const std::vector<float>& pos, const std::vector<float>& nrm, uint32_t w,
                     uint32_t h, int samples, ReferenceMeasure measure) {
  XXH3_state_t* s = XXH3_createState();
  XXH3_128bits_reset(s);
  const std::string sceneHash = scene.contentHash();
  // v2: the shadowing term (weighted, tangent plane) replaced the plain light fraction; the
  // measure's name is part of the key, so the two never share an entry.
  const char tag[] = "shadowc-reference-v2";
  XXH3_128bits_update(s, tag, sizeof tag);
  const std::string measureName = referenceMeasureName(measure);
  XXH3_128bits_update(s, measureName.data(), measureName.size());
  XXH3_128bits_update(s, sceneHash.data(), sceneHash.size());
  const uint32_t header[3] = {w, h, static_cast<uint32_t>(samples)};
  XXH3_128bits_update(s, header, sizeof header);
  XXH3_128bits_update(s, pos.data(), pos.size() * sizeof(float));
  XXH3_128bits_update(s, nrm.data(), nrm.size() * sizeof(float));
  const XXH128_hash_t d = XXH3_128bits_digest(s);
  XXH3_freeState(s);
  return fmt::format("{:016x}{:016x}", d.high64, d.low64);
}

// File: magic[8], u32 width, height, samples, key[32 chars], float data[w*h], u64 XXH3 of data.
std::string encodeCache(const ReferenceResult& r, const std::string& key) {
  std::string out(kCacheMagic, sizeof kCacheMagic);
  const uint32_t header[3] = {r.width, r.height, static_cast<uint32_t>(r.samplesPerAxis)};
  out.append(reinterpret_cast<const char*>(header), sizeof header);
  out.append(key);
  const size_t bytes = r.visibility.size() * sizeof(float);
  out.append(reinterpret_cast<const char*>(r.visibility.data()), bytes);
  const uint64_t check = XXH3_64bits(r.visibility.data(), bytes);
  out.append(reinterpret_cast<const char*>(&check), sizeof check);
  return out;
}

bool decodeCache(const std::filesystem::path& file, const std::string& key, ReferenceResult& r) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t pixels = size_t(r.width) * r.height;
  const size_t expected = sizeof kCacheMagic + 12 + key.size() + pixels * sizeof(float) + 8;
  if (data.size() != expected || std::memcmp(data.data(), kCacheMagic, sizeof kCacheMagic) != 0) return false;
  uint32_t header[3];
  std::memcpy(header, data.data() + sizeof kCacheMagic, sizeof header);
  if (header[0] != r.width || header[1] != r.height || header[2] != static_cast<uint32_t>(r.samplesPerAxis)) {
    return false;
  }
  size_t at = sizeof kCacheMagic + 12;
  if (data.compare(at, key.size(), key) != 0) return false;
  at += key.size();
  std::vector<float> vis(pixels);
  std::memcpy(vis.data(), data.data() + at, pixels * sizeof(float));
  uint64_t check;
  std::memcpy(&check, data.data() + at + pixels * sizeof(float), sizeof check);
  if (check != XXH3_64bits(vis.data(), pixels * sizeof(float))) return false;
  r.visibility = std::move(vis);
  return true;
}

}  // namespace

const char* referenceMeasureName(ReferenceMeasure m) {
  return m == ReferenceMeasure::ShadowingTerm ? "shadowing_term" : "light_fraction";
}

namespace {
// Concentric square -> disk mapping (Shirley & Chiu 1997): keeps the strata compact and equal in
// area. (u, v) in [0, 1)^2 -> signed radius r in [-1, 1] and angle phi.
void concentricDisk(float u, float v, float& r, float& phi) {
  const float a = 2.0f * u - 1.0f, c = 2.0f * v - 1.0f;
  r = 0, phi = 0;
  constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.0f;
  if (a == 0 && c == 0) {
    r = 0;
  } else if (std::abs(a) > std::abs(c)) {
    r = a;
    phi = kQuarterPi * (c / a);
  } else {
    r = c;
    phi = 2.0f * kQuarterPi - kQuarterPi * (a / c);
  }
}
}  // namespace

glm::vec3 sunSampleDirection(const AreaLight& light, int i, int j, int n, float ju, float jv) {
  const float u = (static_cast<float>(i) + ju) / static_cast<float>(n);
  const float v = (static_cast<float>(j) + jv) / static_cast<float>(n);
  float r = 0, phi = 0;
  concentricDisk(u, v, r, phi);
  // Equal areas of the unit disk -> equal solid angles of the cap: 1 - cos(theta) = r^2 (1 - cos(theta_max)).
  const double cosMax = std::cos(0.5 * glm::radians(double(light.angleDegrees)));
  const double cosT = 1.0 - double(r) * double(r) * (1.0 - cosMax);
  const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT)) * (r < 0 ? -1.0 : 1.0);
  const LightBasis b = lightBasis(light);
  const glm::dvec3 d = -glm::dvec3(b.z) * cosT +
                       (glm::dvec3(b.x) * std::cos(double(phi)) + glm::dvec3(b.y) * std::sin(double(phi))) * sinT;
  return glm::vec3(glm::normalize(d));
}

glm::vec3 pointSampleDirection(const AreaLight& light, const glm::vec3& from, int i, int j, int n, float ju, float jv) {
  const float u = (static_cast<float>(i) + ju) / static_cast<float>(n);
  const float v = (static_cast<float>(j) + jv) / static_cast<float>(n);
  float r = 0, phi = 0;
  concentricDisk(u, v, r, phi);
  const glm::dvec3 toCentre = glm::dvec3(light.position) - glm::dvec3(from);
  const double dist = glm::length(toCentre);
  const glm::dvec3 axis = toCentre / dist;
  const double sinMax = std::min(1.0, double(light.radius) / dist);
  const double cosMax = std::sqrt(std::max(0.0, 1.0 - sinMax * sinMax));
  const double cosT = 1.0 - double(r) * double(r) * (1.0 - cosMax);
  const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT)) * (r < 0 ? -1.0 : 1.0);
  const glm::dvec3 helper = std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 bx = glm::normalize(glm::cross(helper, axis));
  const glm::dvec3 by = glm::cross(axis, bx);
  const glm::dvec3 d = axis * cosT + (bx * std::cos(double(phi)) + by * std::sin(double(phi))) * sinT;
  return glm::vec3(glm::normalize(d));
}

glm::vec3 lightSamplePoint(const AreaLight& light, int i, int j, int n, float ju, float jv) {
  const float u = (static_cast<float>(i) + ju) / static_cast<float>(n);  // [0, 1)
  const float v = (static_cast<float>(j) + jv) / static_cast<float>(n);
  const LightBasis b = lightBasis(light);
  float x, y;
  if (light.shape == LightShape::Rect) {
    x = (u - 0.5f) * light.width;
    y = (v - 0.5f) * light.width;
  } else {
    float r = 0, phi = 0;
    concentricDisk(u, v, r, phi);
    r *= 0.5f * light.width;
    x = r * std::cos(phi);
    y = r * std::sin(phi);
  }
  return light.position + x * b.x + y * b.y;
}

std::filesystem::path defaultReferenceCacheDir() {
  if (const char* d = std::getenv("SHADOWC_CACHE_DIR"); d != nullptr && *d != '\0') return d;
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d != nullptr && *d != '\0') {
    return std::filesystem::path(d) / "shadowc";
  }
  if (const char* d = std::getenv("HOME"); d != nullptr && *d != '\0') {
    return std::filesystem::path(d) / ".cache" / "shadowc";
  }
  return std::filesystem::temp_directory_path() / "shadowc-cache";
}

ReferenceResult traceReference(const Scene& scene, const std::vector<float>& positionsRGBA,
                               const std::vector<float>& normalsRGBA, uint32_t width, uint32_t height,
                               int samplesPerAxis, const std::filesystem::path& cacheDir, ProgressFn progress,
                               bool useCache, ReferenceMeasure measure) {
  const size_t pixels = size_t(width) * height;
  if (positionsRGBA.size() != pixels * 4 || normalsRGBA.size() != pixels * 4) {
    throw std::invalid_argument(fmt::format("traceReference: G-buffer holds {} / {} floats, expected {} ({}x{} RGBA)",
                                            positionsRGBA.size(), normalsRGBA.size(), pixels * 4, width, height));
  }
  if (samplesPerAxis < 1 || samplesPerAxis > 1024) {
    throw std::invalid_argument(
        fmt::format("traceReference: samplesPerAxis must be in [1, 1024], got {}", samplesPerAxis));
  }
  ReferenceResult r;
  r.width = width;
  r.height = height;
  r.samplesPerAxis = samplesPerAxis;
  r.measure = measure;
  const auto start = std::chrono::steady_clock::now();
  std::string key;
  if (useCache) {
    key = cacheKey(scene, positionsRGBA, normalsRGBA, width, height, samplesPerAxis, measure);
    r.cacheFile = (cacheDir.empty() ? defaultReferenceCacheDir() : cacheDir) / ("reference-" + key + ".bin");
    if (decodeCache(r.cacheFile, key, r)) {
      r.fromCache = true;
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (progress) progress({pixels, pixels, 0, r.seconds, 0});
      return r;
    }
  }

  const EmbreeScene embree(scene);
  const PixelTracer tracer(embree, samplesPerAxis, measure);
  r.visibility.assign(pixels, 1.0f);
  // Bands of rows, each traced on all cores; progress is reported between bands from this thread.
  const uint32_t band = std::max<uint32_t>(1, height / 16);
  uint64_t rays = 0;
  for (uint32_t y0 = 0; y0 < height; y0 += band) {
    const uint32_t y1 = std::min(height, y0 + band);
    std::atomic<uint64_t> bandRays{0};
    tbb::parallel_for(y0, y1, [&](uint32_t y) {
      uint64_t rowRays = 0;
      for (uint32_t x = 0; x < width; ++x) {
        const size_t i = size_t(y) * width + x;
        const float* p = &positionsRGBA[i * 4];
        if (p[3] == 0.0f) continue;  // background: fully lit by convention
        const float* n = &normalsRGBA[i * 4];
        const PixelValue v = tracer.visibility({p[0], p[1], p[2]}, {n[0], n[1], n[2]}, i);
        r.visibility[i] = v.visibility;
        rowRays += static_cast<uint64_t>(v.rays);
      }
      bandRays += rowRays;
    });
    rays += bandRays.load();
    r.rays = rays;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.raysPerSecond = r.seconds > 0 ? static_cast<double>(r.rays) / r.seconds : 0;
    if (progress) progress({size_t(y1) * width, pixels, r.rays, r.seconds, r.raysPerSecond});
  }
  if (useCache) {
    try {
      writeFileAtomically(r.cacheFile, encodeCache(r, key));
    } catch (const std::exception& e) {
      r.cacheWarning = e.what();
      r.cacheFile.clear();
    }
  }
  return r;
}

float referenceVisibilityAt(const Scene& scene, const glm::vec3& position, const glm::vec3& normal, int samplesPerAxis,
                            uint64_t pixelIndex, ReferenceMeasure measure) {
  const EmbreeScene embree(scene);
  return PixelTracer(embree, samplesPerAxis, measure).visibility(position, normal, pixelIndex).visibility;
}

}  // namespace shadowc::rt

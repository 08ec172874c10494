#include "planning/scene_analysis.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "runtime/scene/cube_setup.h"

namespace shadowc::planning {
namespace {

Distribution makeDistribution(std::vector<double> values, std::vector<double> edges) {
  Distribution d;
  d.edges = std::move(edges);
  d.counts.assign(d.edges.size() + 1, 0);
  std::sort(values.begin(), values.end());
  d.count = values.size();
  if (!values.empty()) {
    double sum = 0;
    for (double v : values) sum += v;
    d.mean = sum / double(values.size());
    auto q = [&](double p) { return values[std::min(values.size() - 1, size_t(p * double(values.size())))]; };
    d.p10 = q(0.1);
    d.p50 = q(0.5);
    d.p90 = q(0.9);
    d.p99 = q(0.99);
    d.max = values.back();
  }
  for (double v : values) {
    const size_t bin = size_t(std::upper_bound(d.edges.begin(), d.edges.end(), v) - d.edges.begin());
    ++d.counts[bin];
  }
  d.samples = std::move(values);
  return d;
}

// Light-view geometry of frame.glsl (a spot): uv = 0.5 + 0.5 xy / (z tanHalfFov), and of
// frame_ortho.glsl (a sun): uv = 0.5 + 0.5 xy / halfExtent; both d = (z - n) / (f - n).
// `width` is the light's width in world units for a spot, the penumbra slope 2 tan(angle / 2)
// for a sun (lightParams.w in both). A point light's cube face (frame_cube.glsl) is a spot frame
// in the face's axes whose map is the face's atlas cell.
struct LightFrame {
  glm::mat4 view;
  double scale, n, f, width;  // scale: tanHalfFov (spot) or halfExtent (sun)
  uint32_t map;
  bool ortho = false;
  glm::dvec2 uv(const glm::dvec3& p) const {
    const double s = ortho ? scale : p.z * scale;
    return {0.5 + 0.5 * p.x / s, 0.5 + 0.5 * p.y / s};
  }
  // The ray through texel (tx, ty): origin and direction, direction.z = 1.
  std::pair<glm::dvec3, glm::dvec3> rayThroughTexel(double tx, double ty) const {
    const double x = 2 * (tx + 0.5) / map - 1, y = 2 * (ty + 0.5) / map - 1;
    if (ortho) return {glm::dvec3(x * scale, y * scale, 0.0), glm::dvec3(0, 0, 1)};
    return {glm::dvec3(0.0), glm::dvec3(x * scale, y * scale, 1.0)};
  }
  double normalized(double z) const { return (z - n) / (f - n); }
  // Unit vector from the receiver at p towards the light.
  glm::dvec3 toLight(const glm::dvec3& p) const { return ortho ? glm::dvec3(0, 0, -1) : -glm::normalize(p); }
  // Blocker-search width in texels (shadowc_searchWidthUV): the light seen from the receiver,
  // cut at the near plane.
  double searchTexels(double zr) const {
    if (ortho) return width * std::max(zr - n, 0.0) / (2 * scale) * map;
    return width / (2 * n * scale) * (zr - n) / zr * map;
  }
  // PCSS penumbra width in texels (shadowc_penumbraWidthUV) behind a blocker at view depth zb:
  // perspective (zr - zb) / zb * width, orthographic (zr - zb) * 2 tan(angle / 2).
  double penumbraTexels(double zr, double zb) const {
    if (ortho) return width * std::max(zr - zb, 0.0) / (2 * scale) * map;
    return width / (2 * n * scale) * n * (zr - zb) / (zb * zr) * map;
  }
};

// Normalized depth of the receiver's tangent plane seen through texel (tx, ty); `fallback`
// where the ray misses the plane (grazing or behind the light).
double planeDepth(const LightFrame& lf, const glm::dvec3& p, const glm::dvec3& nrm, double tx, double ty,
                  double fallback) {
  const auto [origin, dir] = lf.rayThroughTexel(tx, ty);
  const double denom = glm::dot(nrm, dir);
  if (std::abs(denom) < 1e-9) return fallback;
  const double t = glm::dot(nrm, p - origin) / denom;  // z of the hit minus the origin's, since dir.z = 1
  if (!(t > 0) || !std::isfinite(t)) return fallback;
  return lf.normalized(origin.z + t);
}

// Distinct depth clusters among sorted blocker depths: a new cluster where the gap exceeds
// `gap` (occluders at one depth, or one tilted/curved occluder, stay one cluster).
int countClusters(std::vector<double>& depths, double gap) {
  if (depths.empty()) return 0;
  std::sort(depths.begin(), depths.end());
  int clusters = 1;
  for (size_t i = 1; i < depths.size(); ++i)
    if (depths[i] - depths[i - 1] > gap) ++clusters;
  return clusters;
}

}  // namespace

double Distribution::fractionBelow(double value) const {
  if (samples.empty()) return 1.0;
  return double(std::lower_bound(samples.begin(), samples.end(), value) - samples.begin()) / double(samples.size());
}

uint32_t SceneStats::mapForPenumbraTexels(double texels) const {
  const double p10 = penumbraTexels.p10;
  if (penumbraTexels.count == 0 || p10 >= texels || mapSize == 0) return mapSize;
  if (!(p10 > 0)) return 0;  // a zero-width p10 (contact): no map size widens it
  uint64_t map = mapSize;
  while (double(map) / mapSize * p10 < texels && map < (uint64_t(1) << 30)) map *= 2;
  return uint32_t(map);
}

double SceneStats::fractionPenumbraBelow(double texels) const { return penumbraTexels.fractionBelow(texels); }
double SceneStats::contactFraction() const { return receivers ? double(contact) / double(receivers) : 0.0; }
double SceneStats::multiDepthFraction() const {
  uint64_t total = 0, multi = 0;
  for (size_t k = 0; k < clusterCounts.size(); ++k) {
    total += clusterCounts[k];
    if (k >= 1) multi += clusterCounts[k];
  }
  return total ? double(multi) / double(total) : 0.0;
}
double SceneStats::uniformFraction() const { return receivers ? double(lit + umbra) / double(receivers) : 1.0; }

SceneStats analyzeScene(const rt::PreparedScene& scene, const AnalysisOptions& options) {
  const ShadowcFrame& fr = scene.setup.frame;
  const bool cube = scene.setup.cube;
  const uint32_t atlas = scene.setup.mapSize;
  // A cube's six faces share near, far, tan(half fov) and the light; each is a cell of the atlas.
  LightFrame lf{scene.setup.lightView,   fr.lightParams[0], fr.lightParams[1],
                fr.lightParams[2],       fr.lightParams[3], cube ? rt::cubeCellSize(atlas) : atlas,
                scene.setup.orthographic};
  const uint32_t map = lf.map;
  const std::vector<float> depth = scene.raster.lightDepth.channel(0);
  const std::vector<float> pos = scene.raster.gbufferPosition.floats();
  const std::vector<float> nor = scene.raster.gbufferNormal.floats();
  glm::ivec2 cell(0);  // the receiver's face cell in the atlas (0 for one map)
  auto depthAt = [&](int x, int y) {
    x = cell.x + std::clamp(x, 0, int(map) - 1);
    y = cell.y + std::clamp(y, 0, int(map) - 1);
    return double(depth[size_t(y) * atlas + size_t(x)]);
  };

  SceneStats s;
  s.scene = scene.scene.name;
  s.mapSize = atlas;  // the map asked for (a cube face is its cell of mapSize / 3)
  s.screen = scene.setup.width;
  s.lightWidth = lf.width;
  s.lightShape = lf.ortho                ? "sun"
                 : cube                  ? "sphere"
                 : fr.lightShape[0] == 0 ? "rect"
                 : fr.lightShape[0] == 1 ? "disk"
                                         : "point";
  s.faceReceivers.assign(cube ? 6 : 0, 0);
  s.nearPlane = lf.n;
  s.farPlane = lf.f;
  s.contactEpsilon = options.contactEpsilon;
  s.clusterCounts.assign(4, 0);
  s.depthMin = 1;
  s.depthMax = 0;
  for (float d : depth)  // a cube atlas' empty third row holds 1 ("nothing hit") and is skipped
    if (d < 1.0f) {
      s.depthMin = std::min(s.depthMin, double(d));
      s.depthMax = std::max(s.depthMax, double(d));
    }

  std::vector<double> widths, separations, slopes, depthSlopes, search, cameraDepths;
  struct Tap {
    double r2, d;  // squared offset (texels), blocker depth
  };
  std::vector<Tap> blockers;
  std::vector<double> kernelDepths;
  const glm::dmat3 rot(glm::dmat4(lf.view));
  for (size_t i = 0; i < scene.mask.size(); ++i) {
    if (!scene.mask[i]) continue;
    const glm::dvec3 world(pos[4 * i], pos[4 * i + 1], pos[4 * i + 2]);
    glm::dvec3 p = glm::dvec3(glm::dmat4(lf.view) * glm::dvec4(world, 1.0));
    glm::dvec3 nrm = glm::normalize(rot * glm::dvec3(nor[4 * i], nor[4 * i + 1], nor[4 * i + 2]));
    int face = 0;
    if (cube) {
      // The face of the direction's major axis, as frame_cube.glsl picks it; then that face's axes.
      face = rt::cubeFaceOf(glm::vec3(p));
      const glm::dmat3 rows(rt::cubeFaceRows(face));
      p = rows * p;
      nrm = rows * nrm;
      cell = glm::ivec2(rt::cubeCellOrigin(face, atlas));
    }
    if (!(p.z > 0)) continue;
    const glm::dvec2 uv = lf.uv(p);
    const double u = uv.x, v = uv.y;
    if (u < 0 || u >= 1 || v < 0 || v >= 1) continue;
    const double cosL = glm::dot(nrm, lf.toLight(p));
    if (cosL <= 0) {
      ++s.backFacing;
      continue;
    }
    ++s.receivers;
    if (cube) ++s.faceReceivers[size_t(face)];
    cameraDepths.push_back(-(glm::dmat4(scene.setup.cameraView) * glm::dvec4(world, 1.0)).z);
    slopes.push_back(glm::degrees(std::acos(std::min(1.0, cosL))));
    const double dr = lf.normalized(p.z);
    const double tx = u * map - 0.5, ty = v * map - 0.5;
    const double slope = std::abs(planeDepth(lf, p, nrm, tx + 1, ty, dr) - planeDepth(lf, p, nrm, tx, ty, dr));
    depthSlopes.push_back(slope);

    // Blocker search over the cone to the light cut at the near plane (shadowc_searchWidthUV),
    // at least the 3x3 neighbourhood so a point light still sees touching occluders.
    const double searchTexels = lf.searchTexels(p.z);
    search.push_back(searchTexels);
    const double half = std::clamp(searchTexels * 0.5, 1.0, double(map));
    const int taps = std::min(options.maxTapsPerAxis, 2 * int(std::ceil(half)) + 1);
    const double stride = 2 * half / double(taps - 1);
    // Not a filter bias: the depth map's round-off plus one texel of the receiver's slope (its
    // texel centre is up to a texel from the receiver, and a faceted mesh strays from the smooth
    // normal's tangent plane by about that much).
    const double bias = 1e-5 + 1e-4 * dr + std::min(slope, 0.05);
    blockers.clear();
    int total = 0;
    double sum = 0, nearest = 0;
    for (int jy = 0; jy < taps; ++jy)
      for (int jx = 0; jx < taps; ++jx) {
        const double ox = -half + jx * stride, oy = -half + jy * stride;
        const int sx = int(std::lround(tx + ox)), sy = int(std::lround(ty + oy));
        ++total;
        const double db = depthAt(sx, sy);
        if (db >= 1.0) continue;
        // Compared with the receiver's tangent plane through that texel (so a sloped receiver is
        // not its own blocker), and never behind the receiver itself.
        if (db >= std::min(dr, planeDepth(lf, p, nrm, sx, sy, dr)) - bias) continue;
        blockers.push_back({ox * ox + oy * oy, db});
        sum += db;
        nearest = std::max(nearest, db);
      }
    if (blockers.empty()) {
      ++s.lit;
      continue;
    }
    separations.push_back(dr - nearest);
    if (dr - nearest < options.contactEpsilon) ++s.contact;
    if (int(blockers.size()) == total) {
      ++s.umbra;
      continue;
    }
    ++s.penumbra;
    // PCSS penumbra estimate at the receiver (shadowc_penumbraWidthUV) from the average blocker.
    const double zb = lf.n + (sum / double(blockers.size())) * (lf.f - lf.n);
    const double w = lf.penumbraTexels(p.z, zb);
    widths.push_back(std::max(0.0, w));
    // Depth complexity inside the kernel region (the penumbra width around the receiver).
    const double kr = std::max(0.5 * w, stride);
    kernelDepths.clear();
    for (const Tap& t : blockers)
      if (t.r2 <= kr * kr) kernelDepths.push_back(t.d);
    if (kernelDepths.empty()) kernelDepths.push_back(nearest);
    const double gap = std::max(1e-3, options.clusterGap * (dr - nearest));
    const int clusters = countClusters(kernelDepths, gap);
    ++s.clusterCounts[size_t(std::clamp(clusters, 1, 4) - 1)];
  }
  s.penumbraTexels = makeDistribution(std::move(widths), {0.5, 1.5, 3, 6, 12, 24, 48, 96});
  s.separation = makeDistribution(std::move(separations), {1e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3});
  s.slopeDegrees = makeDistribution(std::move(slopes), {15, 30, 45, 60, 75, 85});
  s.depthSlopePerTexel = makeDistribution(std::move(depthSlopes), {1e-5, 1e-4, 5e-4, 1e-3, 5e-3, 1e-2});
  std::sort(cameraDepths.begin(), cameraDepths.end());
  if (!cameraDepths.empty()) {
    s.cameraDepthP01 = cameraDepths[size_t(0.01 * double(cameraDepths.size()))];
    s.cameraDepthP99 = cameraDepths[std::min(cameraDepths.size() - 1, size_t(0.99 * double(cameraDepths.size())))];
  }
  std::sort(search.begin(), search.end());
  s.searchTexelsP99 = search.empty() ? 0 : search[std::min(search.size() - 1, size_t(0.99 * double(search.size())))];
  if (!s.separation.samples.empty()) {
    s.separationP01 = s.separation.samples[size_t(0.01 * double(s.separation.samples.size()))];
    // Near d = 1 one unit in the last place of an n-bit mantissa is 2^-n.
    s.bitsNeeded = int(std::ceil(std::log2(1.0 / std::max(s.separationP01, 1e-12))));
  }
  return s;
}

}  // namespace shadowc::planning

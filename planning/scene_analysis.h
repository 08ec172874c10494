// Scene analysis: the statistics that decide which shadow features a scene calls for
// (docs/planning.md). Reads only what prepareScene rasterizes — the light depth map, the camera
// G-buffer and the light — never the reference, so `shadowc analyze` runs without Embree.
//
// Every receiver is a geometry pixel of the G-buffer (what a shade pass evaluates), projected
// into the shadow map with templates/frame.glsl's conventions. Per receiver, a blocker search on
// the depth map over the cone to the light (shadowc_searchWidthUV) finds the occluders; the
// PCSS form w = W (z_r - z_b) / z_b at the receiver (shadowc_penumbraWidthUV) gives the
// penumbra width in shadow-map texels.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "runtime/harness/scene_run.h"

namespace shadowc::planning {

// A distribution: quantiles plus a histogram over fixed bin edges (value < edge[i] -> bin i,
// the last bin takes the rest).
struct Distribution {
  uint64_t count = 0;
  double mean = 0, p10 = 0, p50 = 0, p90 = 0, p99 = 0, max = 0;
  std::vector<double> edges;                 // upper bin edges, ascending
  std::vector<uint64_t> counts;              // edges.size() + 1 bins
  double fractionBelow(double value) const;  // exact, from the kept samples
  std::vector<double> samples;               // sorted; not written to JSON
};

struct AnalysisOptions {
  double contactEpsilon = 0.01;  // normalized depth, as the contact path's |z_avg - d| < epsilon
  int maxTapsPerAxis = 25;       // blocker-search taps per axis (the region is sampled, not scanned)
  double clusterGap = 0.1;       // depth clusters split where sorted blocker depths jump by more than
                                 // this fraction of the receiver-blocker separation (and 1e-3)
};

struct SceneStats {
  std::string scene;
  uint32_t mapSize = 0, screen = 0;
  double lightWidth = 0;  // world units (0 = point light); a sun's penumbra slope 2 tan(angle / 2)
  std::string lightShape;
  double nearPlane = 0, farPlane = 0;

  uint64_t receivers = 0;  // front-facing geometry pixels inside the shadow map
  // A point light (lightShape "sphere"): receivers per cube face (+x, -x, +y, -y, +z, -z). Each
  // receiver is analyzed in the face frame_cube.glsl picks for it (its texels are the face's atlas
  // cell, its depths the face's); every statistic below merges the six faces.
  std::vector<uint64_t> faceReceivers;
  uint64_t backFacing = 0;     // N.L <= 0: the N.L term's business, not the shadow's
  uint64_t lit = 0;            // no blocker in the search region
  uint64_t umbra = 0;          // every search tap is a blocker
  uint64_t penumbra = 0;       // blockers and non-blockers in the search region
  double searchTexelsP99 = 0;  // blocker-search region width (texels), 99th percentile

  Distribution penumbraTexels;  // over penumbra receivers: w in shadow-map texels
  // Contact: nearest blocker within contactEpsilon (normalized depth) of the receiver.
  double contactEpsilon = 0;
  uint64_t contact = 0;
  Distribution separation;  // over blocked receivers: d_r - (nearest blocker depth), normalized
  // Depth complexity: distinct occluder depth clusters inside each penumbra receiver's kernel
  // region (the penumbra width around it). clusterCounts[k] = receivers with k+1 clusters (last: 4+).
  std::vector<uint64_t> clusterCounts;
  // Depth range and precision.
  double depthMin = 0, depthMax = 0;  // normalized depth of geometry in the map
  double separationP01 = 0;           // 1st percentile of d_r - d_b over blocked receivers
  int bitsNeeded = 0;                 // mantissa bits to resolve separationP01 near d = 1
  // The camera's view depth range over the receivers (1st and 99th percentile of the distance
  // along the view axis): what cascades exist for (one map's texels are spread evenly over a range
  // the camera sees at very different scales; Zhang et al. 2006).
  double cameraDepthP01 = 0, cameraDepthP99 = 0;
  // Receivers' camera-depth ratio p99 / p01 (1 when there are none).
  double cameraDepthRatio() const { return cameraDepthP01 > 0 ? cameraDepthP99 / cameraDepthP01 : 1.0; }
  // Receiver slopes.
  Distribution slopeDegrees;        // angle between N and the direction to the light centre
  Distribution depthSlopePerTexel;  // |d(receiver depth)/d(texel)| along the map's x axis

  double fractionPenumbraBelow(double texels) const;  // over penumbra receivers (1 when none)
  // The map size at which the 10th-percentile penumbra spans `texels` texels: a penumbra's width
  // in texels is its width in map uv times the map size, so it grows in proportion; the answer
  // is this map size times the least power of two that gets there (a point light's atlas keeps
  // its factor 3). This map size when it already does, or when there is no penumbra; 0 when the
  // p10 is 0 texels (contact), which no map size widens. No filter
  // widens a penumbra narrower than a texel or two into the right shape: resolution does.
  uint32_t mapForPenumbraTexels(double texels = kPenumbraTexelsWanted) const;
  static constexpr double kPenumbraTexelsWanted = 2;
  double contactFraction() const;     // contact / receivers
  double multiDepthFraction() const;  // penumbra receivers with >= 2 clusters
  double uniformFraction() const;     // (lit + umbra) / receivers
};

SceneStats analyzeScene(const rt::PreparedScene& scene, const AnalysisOptions& options = {});

nlohmann::ordered_json toJson(const SceneStats& stats);
// The readable summary with text histograms (what `shadowc analyze` prints).
std::string formatSummary(const SceneStats& stats);

}  // namespace shadowc::planning

// The two forms of SceneStats: JSON (fixed key order) and the readable summary of
// `shadowc analyze` with one text histogram per distribution.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "planning/scene_analysis.h"

namespace shadowc::planning {
namespace {

nlohmann::ordered_json distJson(const Distribution& d) {
  nlohmann::ordered_json j;
  j["count"] = d.count;
  j["mean"] = d.mean;
  j["p10"] = d.p10;
  j["p50"] = d.p50;
  j["p90"] = d.p90;
  j["p99"] = d.p99;
  j["max"] = d.max;
  j["edges"] = d.edges;
  j["counts"] = d.counts;
  return j;
}

double pct(uint64_t a, uint64_t b) { return b ? 100.0 * double(a) / double(b) : 0.0; }

std::string bar(uint64_t n, uint64_t maxN) {
  const int width = maxN ? int(40.0 * double(n) / double(maxN) + 0.5) : 0;
  return std::string(size_t(width), '#');
}

std::string histogram(const std::string& title, const Distribution& d, const char* unit, int precision) {
  std::string out = fmt::format(
      "{} ({} receivers: mean {:.{}f}, p50 {:.{}f}, p90 {:.{}f}, p99 {:.{}f}, max {:.{}f} {})\n", title, d.count,
      d.mean, precision, d.p50, precision, d.p90, precision, d.p99, precision, d.max, precision, unit);
  if (d.count == 0) return out + "  (none)\n";
  const uint64_t maxN = *std::max_element(d.counts.begin(), d.counts.end());
  for (size_t b = 0; b < d.counts.size(); ++b) {
    const std::string lo = b == 0 ? "0" : fmt::format("{:g}", d.edges[b - 1]);
    const std::string label = b < d.edges.size() ? fmt::format("[{}, {:g})", lo, d.edges[b]) : fmt::format(">= {}", lo);
    out += fmt::format("  {:<16} {:6.2f} % {}\n", label, pct(d.counts[b], d.count), bar(d.counts[b], maxN));
  }
  return out;
}

}  // namespace

nlohmann::ordered_json toJson(const SceneStats& s) {
  nlohmann::ordered_json j;
  j["scene"] = s.scene;
  j["map_size"] = s.mapSize;
  j["screen"] = s.screen;
  j["light"] = {{"shape", s.lightShape}, {"width", s.lightWidth}};
  j["near"] = s.nearPlane;
  j["far"] = s.farPlane;
  j["receivers"] = {{"front_facing", s.receivers},
                    {"back_facing", s.backFacing},
                    {"lit", s.lit},
                    {"umbra", s.umbra},
                    {"penumbra", s.penumbra}};
  if (!s.faceReceivers.empty()) j["cube_face_receivers"] = s.faceReceivers;  // +x -x +y -y +z -z
  j["camera_depth"] = {{"p01", s.cameraDepthP01}, {"p99", s.cameraDepthP99}, {"ratio", s.cameraDepthRatio()}};
  j["search_texels_p99"] = s.searchTexelsP99;
  j["penumbra_texels"] = distJson(s.penumbraTexels);
  j["penumbra_below_1_5_texels"] = s.fractionPenumbraBelow(1.5);
  j["map_for_p10_penumbra"] = {{"texels", SceneStats::kPenumbraTexelsWanted}, {"map_size", s.mapForPenumbraTexels()}};
  j["contact"] = {{"epsilon", s.contactEpsilon}, {"receivers", s.contact}, {"fraction", s.contactFraction()}};
  j["separation"] = distJson(s.separation);
  j["depth_clusters"] = {{"counts_1_2_3_4plus", s.clusterCounts}, {"multi_depth_fraction", s.multiDepthFraction()}};
  j["depth_range"] = {{"min", s.depthMin},
                      {"max", s.depthMax},
                      {"far_over_near", s.nearPlane > 0 ? s.farPlane / s.nearPlane : 0.0},
                      {"separation_p01", s.separationP01},
                      {"bits_needed", s.bitsNeeded}};
  j["slope_degrees"] = distJson(s.slopeDegrees);
  j["depth_slope_per_texel"] = distJson(s.depthSlopePerTexel);
  return j;
}

std::string formatSummary(const SceneStats& s) {
  std::string out;
  out += fmt::format("scene    {}  map {}^2  screen {}^2\n", s.scene, s.mapSize, s.screen);
  if (s.lightShape == "sun")  // lightWidth is the penumbra slope 2 tan(angle / 2) (frame_ortho.glsl)
    out +=
        fmt::format("light    sun angle {:.3g} deg (penumbra slope {:g})  near {:g}  far {:g}\n",
                    2 * std::atan(0.5 * s.lightWidth) * 180 / 3.14159265358979, s.lightWidth, s.nearPlane, s.farPlane);
  else if (s.lightShape == "sphere")  // a point light: six cube faces, texels of a face's atlas cell
    out += fmt::format("light    point (sphere) diameter {:g}  near {:g}  far {:g}; cube faces {}^2 texels each\n",
                       s.lightWidth, s.nearPlane, s.farPlane, s.mapSize / 3);
  else
    out += fmt::format("light    {} width {:g}  near {:g}  far {:g}\n", s.lightShape, s.lightWidth, s.nearPlane,
                       s.farPlane);
  if (!s.faceReceivers.empty()) {
    static const char* kFaces[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    out += "receivers per cube face (statistics below merge all six):";
    for (size_t f = 0; f < s.faceReceivers.size(); ++f) out += fmt::format(" {} {}", kFaces[f], s.faceReceivers[f]);
    out += "\n";
  }
  out += fmt::format("camera depth of receivers p01 {:.3g}  p99 {:.3g}  (ratio {:.3g})\n", s.cameraDepthP01,
                     s.cameraDepthP99, s.cameraDepthRatio());
  out += fmt::format("receivers {} front-facing ({} back-facing): lit {:.1f} %, umbra {:.1f} %, penumbra {:.1f} %\n",
                     s.receivers, s.backFacing, pct(s.lit, s.receivers), pct(s.umbra, s.receivers),
                     pct(s.penumbra, s.receivers));
  out += fmt::format("blocker search region p99 {:.1f} texels\n\n", s.searchTexelsP99);
  out += histogram("penumbra width, texels", s.penumbraTexels, "texels", 2);
  out += fmt::format("  {:.1f} % of penumbrae < 1.5 texels\n", 100.0 * s.fractionPenumbraBelow(1.5));
  if (s.penumbraTexels.count > 0) {
    const uint32_t wanted = s.mapForPenumbraTexels();
    out += wanted == 0 ? fmt::format("  p10 penumbra 0 texels at {}^2 (contact): no map size widens it\n\n", s.mapSize)
           : wanted == s.mapSize
               ? fmt::format("  p10 penumbra {:.2f} texels at {}^2: the map resolves it ({:g} or more)\n\n",
                             s.penumbraTexels.p10, s.mapSize, SceneStats::kPenumbraTexelsWanted)
               : fmt::format(
                     "  p10 penumbra {:.2f} texels at {}^2: a {}^2 map makes it {:g} texels (no filter "
                     "widens a penumbra narrower than that: resolution does)\n\n",
                     s.penumbraTexels.p10, s.mapSize, wanted, SceneStats::kPenumbraTexelsWanted);
  } else {
    out += "\n";
  }
  out += fmt::format("contact  {:.2f} % of receivers within {:g} (normalized depth) of their nearest blocker\n",
                     100.0 * s.contactFraction(), s.contactEpsilon);
  out += histogram("blocker-receiver separation, normalized depth", s.separation, "", 4);
  out += "\ndepth complexity (occluder depth clusters in a penumbra receiver's kernel region)\n";
  const uint64_t total = s.clusterCounts[0] + s.clusterCounts[1] + s.clusterCounts[2] + s.clusterCounts[3];
  const uint64_t maxN = *std::max_element(s.clusterCounts.begin(), s.clusterCounts.end());
  for (size_t k = 0; k < 4; ++k)
    out += fmt::format("  {:<16} {:6.2f} % {}\n", k < 3 ? fmt::format("{} cluster{}", k + 1, k ? "s" : "") : "4+",
                       pct(s.clusterCounts[k], total), bar(s.clusterCounts[k], maxN));
  out += fmt::format(
      "\ndepth range  geometry d in [{:.6f}, {:.6f}], far/near {:.3g}; 1st-percentile separation {:.3g} "
      "needs {} mantissa bits (fp16 has 11, int32 16.16 SAT 16, fp32 24)\n\n",
      s.depthMin, s.depthMax, s.nearPlane > 0 ? s.farPlane / s.nearPlane : 0.0, s.separationP01, s.bitsNeeded);
  out += histogram("receiver slope (angle between N and the light), degrees", s.slopeDegrees, "deg", 1);
  out += histogram("receiver depth change per shadow-map texel", s.depthSlopePerTexel, "", 6);
  return out;
}

}  // namespace shadowc::planning

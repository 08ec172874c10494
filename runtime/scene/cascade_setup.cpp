// setupCascades: the camera-depth splits and per-cascade orthographic windows of a cascaded sun.
#include "runtime/scene/cascade_setup.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shadowc::rt {

CascadeConfig cascadeConfigFromSpec(const nlohmann::json& spec) {
  CascadeConfig c;
  if (!spec.is_object() || !spec.contains("cascades")) return c;
  const nlohmann::json& j = spec["cascades"];
  try {
    c.count = j.at("count").get<int>();
    const std::string split = j.at("split").get<std::string>();
    if (split == "uniform")
      c.split = CascadeScheme::Uniform;
    else if (split == "log")
      c.split = CascadeScheme::Log;
    else if (split == "practical")
      c.split = CascadeScheme::Practical;
    else
      throw std::invalid_argument("unknown split '" + split + "'");
    c.lambda = j.at("lambda").get<double>();
    c.blend = j.at("blend").get<double>();
    c.grid = j.at("grid").get<int>();
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(fmt::format("manifest spec.cascades: {}", e.what()));
  }
  if (c.count < 1 || c.count > kMaxCascades || c.grid < 1 || c.grid * c.grid < c.count)
    throw std::invalid_argument(
        fmt::format("manifest spec.cascades: count {} in a {}x{} atlas", c.count, c.grid, c.grid));
  return c;
}

std::vector<double> cascadeSplitDepths(const CascadeConfig& c, double near, double far) {
  std::vector<double> s(size_t(c.count) + 1);
  const double lambda = c.split == CascadeScheme::Uniform ? 0.0 : c.split == CascadeScheme::Log ? 1.0 : c.lambda;
  for (int i = 0; i <= c.count; ++i) {
    const double t = double(i) / c.count;
    s[size_t(i)] = lambda * near * std::pow(far / near, t) + (1.0 - lambda) * (near + (far - near) * t);
  }
  s.front() = near, s.back() = far;  // exact ends whatever pow rounds to
  return s;
}

void setupCascades(const Scene& scene, const CascadeConfig& c, FrameSetup& f) {
  if (c.count == 0) return;
  if (!f.orthographic || scene.light.type != LightType::Sun)
    throw SceneError(fmt::format("scene '{}': cascades need a sun; its light is a spot light", scene.name));
  if (f.mapSize % uint32_t(c.grid) != 0)
    throw SceneError(
        fmt::format("cascades: the map side {} is not a multiple of the {}x{} atlas", f.mapSize, c.grid, c.grid));
  const double camFar = f.cameraFar, camNear = std::max<double>(f.cameraNear, kCascadeNearFraction * camFar);
  const std::vector<double> splits = cascadeSplitDepths(c, camNear, camFar);
  const glm::mat4 camToWorld = glm::inverse(f.cameraView);
  const double tanY = std::tan(0.5 * glm::radians(double(scene.camera.fovYDegrees)));
  const double tanX = tanY * double(f.width) / double(f.height);
  const double tile = double(f.mapSize / uint32_t(c.grid));
  const double n = f.nearPlane, fa = f.farPlane;

  f.cascadeCount = c.count;
  f.cascadeGrid = c.grid;
  // Camera view looks down -z (lookAtRH): depth = -(row 2 of the view matrix) . (p, 1).
  setCascadeInfo(f.frame, c.count, splits[0], cameraDepthRow(f.cameraView));
  for (int i = 0; i < c.count; ++i) {
    // The slice this cascade covers, widened towards the camera by the band in which the
    // previous cascade blends into it (lookup/cascades.glsl reads this cascade there).
    const double band = i == 0 ? 0.0 : c.blend * (splits[size_t(i)] - splits[size_t(i) - 1]);
    const double depths[2] = {splits[size_t(i)] - band, splits[size_t(i) + 1]};
    glm::dvec3 corners[8];
    glm::dvec3 centre(0);
    for (int k = 0; k < 8; ++k) {
      const double d = depths[k >> 2];
      const glm::vec4 view(float((k & 1 ? 1 : -1) * d * tanX), float((k & 2 ? 1 : -1) * d * tanY), float(-d), 1.0f);
      corners[k] = glm::dvec3(camToWorld * view);
      centre += corners[k] / 8.0;
    }
    double radius = 0;
    for (const glm::dvec3& p : corners) radius = std::max(radius, glm::length(p - centre));
    // One texel of slack on each side: the snapped window still holds the whole sphere.
    const double h = radius * tile / (tile - 2.0);
    const double texel = 2.0 * h / tile;
    const glm::dvec3 lc = glm::dvec3(f.lightView * glm::vec4(glm::vec3(centre), 1.0f));
    const double cx = std::floor(lc.x / texel) * texel, cy = std::floor(lc.y / texel) * texel;
    // The atlas frame of frame_cascades.glsl: uv = 0.5 + 0.5 (p.xy + o) / H (include/shadowc/frame.h).
    setCascade(f.frame, i, cx, cy, h, splits[size_t(i) + 1], f.mapSize, c.grid);
    f.cascadeWindows[size_t(i)] = {cx, cy, h, splits[size_t(i) + 1]};
    // Vulkan clip of the tile: x_c = (x - cx) / h, y_c = (y - cy) / h, z_c as fitSun's.
    glm::mat4 proj(0.0f);
    proj[0][0] = float(1.0 / h);
    proj[1][1] = float(1.0 / h);
    proj[3][0] = float(-cx / h);
    proj[3][1] = float(-cy / h);
    proj[2][2] = float(1.0 / (fa - n));
    proj[3][2] = float(-n / (fa - n));
    proj[3][3] = 1.0f;
    f.cascadeViewProj[size_t(i)] = proj * f.lightView;
  }
  for (size_t i = 0; i < splits.size(); ++i) f.cascadeSplits[i] = float(splits[i]);
}

}  // namespace shadowc::rt

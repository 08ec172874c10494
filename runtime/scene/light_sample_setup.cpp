// setupLightSamples: the views of a light-sampled spot filter.
#include "runtime/scene/light_sample_setup.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>

namespace shadowc::rt {

LightSampleConfig lightSampleConfigFromSpec(const nlohmann::json& spec) {
  LightSampleConfig c;
  if (!spec.is_object() || !spec.contains("light_samples")) return c;
  const nlohmann::json& j = spec["light_samples"];
  try {
    c.count = j.at("count").get<int>();
    c.grid = j.at("grid").get<int>();
    for (const nlohmann::json& o : j.at("offsets"))
      c.offsets.emplace_back(o.at(0).get<double>(), o.at(1).get<double>());
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(fmt::format("manifest spec.light_samples: {}", e.what()));
  }
  const bool offsetsOnLight = std::all_of(c.offsets.begin(), c.offsets.end(), [](const glm::dvec2& o) {
    return std::abs(o.x) <= 0.5 && std::abs(o.y) <= 0.5;
  });
  if (c.count < 1 || c.grid < 1 || c.grid * c.grid < c.count || c.offsets.size() != size_t(c.count) || !offsetsOnLight)
    throw std::invalid_argument(fmt::format("manifest spec.light_samples: {} views, {} offsets in a {}x{} atlas",
                                            c.count, c.offsets.size(), c.grid, c.grid));
  return c;
}

void setupLightSamples(const Scene& scene, const LightSampleConfig& c, FrameSetup& f) {
  if (c.count == 0) return;
  if (f.orthographic || f.cube || scene.light.type != LightType::Spot)
    throw SceneError(fmt::format("scene '{}': light samples need a spot light; its light is a {}", scene.name,
                                 f.cube ? "point light" : "sun"));
  if (f.mapSize / uint32_t(c.grid) < 1)
    throw SceneError(fmt::format("light samples: a map of {} has no {}x{} atlas", f.mapSize, c.grid, c.grid));
  const double width = scene.light.width;
  std::vector<glm::mat4> views;
  for (const glm::dvec2& o : c.offsets) {
    glm::mat4 v = f.lightView;
    v[3][0] -= float(width * o.x);
    v[3][1] -= float(width * o.y);
    views.push_back(v);
  }
  // The widest tangent any view needs (fitSpot's rule, from every view).
  float maxTan = 0;
  for (const Mesh& m : scene.meshes)
    for (const glm::vec3& p : m.positions)
      for (const glm::mat4& v : views) {
        const glm::vec3 q = glm::vec3(v * glm::vec4(p, 1.0f));
        if (q.z > 0) maxTan = std::max({maxTan, std::abs(q.x) / q.z, std::abs(q.y) / q.z});
      }
  f.tanHalfFov = std::max({f.tanHalfFov, maxTan * kFovMargin, 1e-6f});
  const glm::mat4 proj = spotClipMatrix(f.tanHalfFov, f.nearPlane, f.farPlane);
  f.lightViewProj = proj * f.lightView;
  f.lightSampleGrid = c.grid;
  f.lightSampleViewProj.clear();
  for (const glm::mat4& v : views) f.lightSampleViewProj.push_back(proj * v);
  setSpotLight(f.frame, glm::value_ptr(f.lightView), f.tanHalfFov, f.nearPlane, f.farPlane, scene.light.width,
               scene.light.shape == LightShape::Disk);
}

}  // namespace shadowc::rt

// setupFrame: fits the light frustum to the scene and fills ShadowcFrame (templates/frame.glsl).
#include "runtime/scene/frame_setup.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace shadowc::rt {
namespace {

// Margins: near/far are pulled apart by 2% so every surface has a normalized depth strictly
// inside (0, 1): d = 1 stays reserved for "nothing hit" (the cleared value); kFovMargin in the header.
constexpr float kNearMargin = 0.98f;
constexpr float kFarMargin = 1.02f;

}  // namespace

LightBasis lightBasis(const AreaLight& light) {
  LightBasis b;
  b.z = glm::normalize(light.direction);
  glm::vec3 up = light.up - glm::dot(light.up, b.z) * b.z;
  if (glm::length(up) < 1e-6f) {
    // up parallel to the axis (the loader rejects this; be robust for hand-built scenes).
    up = std::abs(b.z.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    up -= glm::dot(up, b.z) * b.z;
  }
  b.y = glm::normalize(up);
  b.x = glm::cross(b.y, b.z);
  return b;
}

glm::mat4 lightViewMatrix(const AreaLight& light) {
  const LightBasis b = lightBasis(light);
  glm::mat4 m(1.0f);  // column-major: m[col][row]
  for (int c = 0; c < 3; ++c) {
    m[c][0] = b.x[c];
    m[c][1] = b.y[c];
    m[c][2] = b.z[c];
  }
  m[3][0] = -glm::dot(b.x, light.position);
  m[3][1] = -glm::dot(b.y, light.position);
  m[3][2] = -glm::dot(b.z, light.position);
  return m;
}

glm::mat4 spotClipMatrix(float tanHalfFov, float nearPlane, float farPlane) {
  glm::mat4 proj(0.0f);
  const float n = nearPlane, fa = farPlane;
  proj[0][0] = 1.0f / tanHalfFov;
  proj[1][1] = 1.0f / tanHalfFov;
  proj[2][2] = fa / (fa - n);
  proj[2][3] = 1.0f;
  proj[3][2] = -fa * n / (fa - n);
  return proj;
}

namespace {

void fitSpot(const Scene& scene, FrameSetup& f) {
  // Fit to the vertices: the perspective image of a triangle in front of the light is the hull
  // of its vertices' images, so covering every vertex covers every surface.
  float maxTan = 0, minZ = std::numeric_limits<float>::max(), maxZ = 0;
  for (const Mesh& m : scene.meshes) {
    for (const glm::vec3& p : m.positions) {
      const glm::vec3 v = glm::vec3(f.lightView * glm::vec4(p, 1.0f));
      if (!(v.z > 0)) continue;  // the loader rejects such scenes; ignore here
      maxTan = std::max({maxTan, std::abs(v.x) / v.z, std::abs(v.y) / v.z});
      minZ = std::min(minZ, v.z);
      maxZ = std::max(maxZ, v.z);
    }
  }
  if (maxZ <= 0) {  // nothing in front of the light: any valid frustum
    minZ = 1;
    maxZ = 2;
    maxTan = 1;
  }
  f.tanHalfFov = std::max(maxTan * kFovMargin, 1e-6f);
  f.nearPlane = minZ * kNearMargin;
  f.farPlane = std::max(maxZ * kFarMargin, f.nearPlane * 1.0001f);

  // Vulkan clip for coverage: x_c = x / tan, y_c = y / tan (uv = 0.5 + 0.5 * ndc, row 0 = uv.y 0,
  // exactly frame.glsl's mapping), w_c = z, standard perspective depth in 0..1 (only for coverage;
  // the rasterizer stores the linear d itself).
  f.lightViewProj = spotClipMatrix(f.tanHalfFov, f.nearPlane, f.farPlane) * f.lightView;
}

// A sun: the view origin sits on the bounding sphere upstream of the scene, so every vertex has
// z > 0; the orthographic box is the vertices' extent across the direction, with the same
// margins as a spot's frustum.
void fitSun(const Scene& scene, FrameSetup& f) {
  const Bounds b = sceneBounds(scene);
  const LightBasis basis = lightBasis(scene.light);
  const glm::vec3 centre = b.empty() ? glm::vec3(0) : b.center();
  const float radius = std::max(0.5f * b.diagonal(), 1e-3f);
  const glm::vec3 origin = centre - basis.z * (1.1f * radius);
  const glm::vec3 rows[3] = {basis.x, basis.y, basis.z};
  for (int r = 0; r < 3; ++r) f.lightView[3][r] = -glm::dot(rows[r], origin);
  float maxXY = 0, minZ = std::numeric_limits<float>::max(), maxZ = 0;
  for (const Mesh& m : scene.meshes) {
    for (const glm::vec3& p : m.positions) {
      const glm::vec3 v = glm::vec3(f.lightView * glm::vec4(p, 1.0f));
      maxXY = std::max({maxXY, std::abs(v.x), std::abs(v.y)});
      minZ = std::min(minZ, v.z);
      maxZ = std::max(maxZ, v.z);
    }
  }
  if (maxZ <= 0) minZ = 1, maxZ = 2, maxXY = 1;
  f.orthographic = true;
  f.halfExtent = std::max(maxXY * kFovMargin, 1e-6f);
  f.nearPlane = minZ * kNearMargin;
  f.farPlane = std::max(maxZ * kFarMargin, f.nearPlane * 1.0001f);
  // Vulkan clip: x_c = x / halfExtent, y_c = y / halfExtent (frame_ortho.glsl's uv), z_c in 0..1.
  glm::mat4 proj(0.0f);
  proj[0][0] = 1.0f / f.halfExtent;
  proj[1][1] = 1.0f / f.halfExtent;
  proj[2][2] = 1.0f / (f.farPlane - f.nearPlane);
  proj[3][2] = -f.nearPlane / (f.farPlane - f.nearPlane);
  proj[3][3] = 1.0f;
  f.lightViewProj = proj * f.lightView;
}

void fitCamera(const Scene& scene, FrameSetup& f) {
  const uint32_t width = f.width, height = f.height;
  // Camera: near/far from the distance to the scene's bounding box.
  const Bounds b = sceneBounds(scene);
  const Camera& cam = scene.camera;
  float farDist = 1, nearDist = 0;
  if (!b.empty()) {
    const glm::vec3 closest = glm::clamp(cam.eye, b.min, b.max);
    nearDist = glm::length(closest - cam.eye);
    farDist = 0;
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
      farDist = std::max(farDist, glm::length(corner - cam.eye));
    }
  }
  f.cameraFar = std::max(farDist * 1.05f, 1e-3f);
  f.cameraNear = std::max(nearDist * 0.9f, f.cameraFar * 1e-5f);
  f.cameraView = glm::lookAtRH(cam.eye, cam.target, cam.up);
  f.cameraProj = glm::perspectiveRH_ZO(glm::radians(cam.fovYDegrees), static_cast<float>(width) / height, f.cameraNear,
                                       f.cameraFar);
  f.cameraProj[1][1] *= -1.0f;  // Vulkan's y points down: keep row 0 at the top of the image
  f.cameraViewProj = f.cameraProj * f.cameraView;
}

}  // namespace

FrameSetup setupFrame(const Scene& scene, uint32_t mapSize, uint32_t width, uint32_t height, float cubeTanHalf) {
  if (mapSize == 0 || width == 0 || height == 0) {
    throw SceneError(fmt::format("setupFrame: sizes must be positive (map {}, screen {}x{})", mapSize, width, height));
  }
  FrameSetup f;
  f.mapSize = mapSize;
  f.width = width;
  f.height = height;
  f.lightView = lightViewMatrix(scene.light);
  if (scene.light.type == LightType::Point) {
    if (mapSize < 3)
      throw SceneError(fmt::format("setupFrame: a point light's map of {} has no 3x3 face atlas", mapSize));
    fitPoint(scene, f, cubeTanHalf);
  } else if (scene.light.type == LightType::Sun) {
    fitSun(scene, f);
  } else {
    fitSpot(scene, f);
  }
  fitCamera(scene, f);

  // The integration header's functions, as an engine fills the block (include/shadowc/frame.h).
  const float* view = glm::value_ptr(f.lightView);
  if (f.cube) {
    setPointLight(f.frame, view, f.tanHalfFov, f.nearPlane, f.farPlane, scene.light.radius);
  } else if (scene.light.type == LightType::Sun) {
    setSunLight(f.frame, view, f.halfExtent, f.nearPlane, f.farPlane, glm::radians(double(scene.light.angleDegrees)));
  } else {
    setSpotLight(f.frame, view, f.tanHalfFov, f.nearPlane, f.farPlane, scene.light.width,
                 scene.light.shape == LightShape::Disk);
  }
  setMapSize(f.frame, mapSize);
  setScreenSize(f.frame, width, height);
  return f;
}

}  // namespace shadowc::rt

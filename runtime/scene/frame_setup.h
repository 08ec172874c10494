// Fits the light frustum and camera to a scene and fills the ShadowcFrame uniforms
// (templates/frame.glsl conventions) plus the matrices the rasterizer needs.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "manifest/frame_uniforms.h"
#include "runtime/scene/cube_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {

struct FrameSetup {
  ShadowcFrame frame{};         // what every pass reads (binding 0)
  glm::mat4 lightView{1};       // world -> light view (+z forward, as frame.glsl)
  glm::mat4 lightViewProj{1};   // world -> Vulkan clip for rasterizing the light depth
  glm::mat4 cameraViewProj{1};  // world -> Vulkan clip for the G-buffer
  float tanHalfFov = 1, nearPlane = 0.1f, farPlane = 100;
  // A sun (LightType::Sun): an orthographic map, uv = 0.5 + 0.5 xy / halfExtent (frame_ortho.glsl);
  // tanHalfFov is then unused.
  bool orthographic = false;
  float halfExtent = 0;
  // A point light (LightType::Point, cube_setup.h): six faces in a 3x3 atlas of the map, each with
  // its clip matrix and light-depth z row; tanHalfFov is the faces' (with the guard band).
  bool cube = false;
  std::array<glm::mat4, 6> faceViewProj{};
  std::array<glm::vec4, 6> faceZRow{};
  uint32_t mapSize = 1024, width = 512, height = 512;
  // Camera parts of cameraViewProj (= cameraProj * cameraView), for G-buffer shaders and tools.
  glm::mat4 cameraView{1};  // world -> camera view (right-handed, looking down -z)
  glm::mat4 cameraProj{1};  // Vulkan clip: y flipped (row 0 = top of the image), depth 0..1
  float cameraNear = 0.1f, cameraFar = 100;
  // A cascaded sun (cascade_setup.h; 0 = one map): cascade i is rendered with cascadeViewProj[i]
  // into tile (i mod cascadeGrid, i div cascadeGrid) of the map, an atlas of mapSize^2 texels.
  int cascadeCount = 0, cascadeGrid = 1;
  std::array<glm::mat4, kMaxCascades> cascadeViewProj{};
  std::array<float, kMaxCascades + 1> cascadeSplits{};  // camera depths, cascadeCount + 1 of them
  // setCascade's arguments for cascade i (include/shadowc/frame.h): light-view centre cx, cy of
  // its window, half-width h, far split (camera depth), as an engine passes them.
  std::array<glm::dvec4, kMaxCascades> cascadeWindows{};
  // A light-sampled spot (light_sample_setup.h; none = one view from the centre): view i is rendered
  // with lightSampleViewProj[i] into tile (i mod lightSampleGrid, i div lightSampleGrid) of the map,
  // tiles of floor(mapSize / lightSampleGrid) texels.
  int lightSampleGrid = 1;
  std::vector<glm::mat4> lightSampleViewProj;  // one per view; empty = one view
};

// The light's orthonormal frame: z = light.direction, y = light.up made orthogonal to z,
// x = y cross z. The rectangle's sides run along x and y; lightView maps (x, y, z) to view axes.
struct LightBasis {
  glm::vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
};
LightBasis lightBasis(const AreaLight& light);
// World -> light view (origin at the light centre, +z along the light axis; frame.glsl).
glm::mat4 lightViewMatrix(const AreaLight& light);

// The light frustum is widened by 2% (a sun's box too) so that silhouettes at the edge of the scene
// keep a texel or so of slack.
inline constexpr float kFovMargin = 1.02f;

// A spot light's Vulkan clip from its view: x_c = x / tan, y_c = y / tan (uv = 0.5 + 0.5 * ndc,
// frame.glsl's mapping), w_c = z, perspective depth in 0..1 (coverage only: the rasterizer stores
// linear depth itself).
glm::mat4 spotClipMatrix(float tanHalfFov, float nearPlane, float farPlane);

// The light frustum covers the scene's bounds as seen from the light centre; near/far are
// fitted to the bounds (near clamped > 0). A sun's orthographic box covers every vertex, its
// view origin placed on the scene's bounding sphere, upstream along the sun's direction.
// cubeTanHalf: a point light's face half-fov tangent (cube_setup.h; 1 only for the seam test).
FrameSetup setupFrame(const Scene& scene, uint32_t mapSize, uint32_t width, uint32_t height,
                      float cubeTanHalf = kCubeTanHalf);

}  // namespace shadowc::rt

// Fits the light frustum and camera to a scene and fills the ShadowcFrame uniforms
// (templates/frame.glsl conventions) plus the matrices the rasterizer needs.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "manifest/frame_uniforms.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {

struct FrameSetup {
  ShadowcFrame frame{};          // what every pass reads (binding 0)
  glm::mat4 lightView{1};        // world -> light view (+z forward, as frame.glsl)
  glm::mat4 lightViewProj{1};    // world -> Vulkan clip for rasterizing the light depth
  glm::mat4 cameraViewProj{1};   // world -> Vulkan clip for the G-buffer
  float tanHalfFov = 1, nearPlane = 0.1f, farPlane = 100;
  uint32_t mapSize = 1024, width = 512, height = 512;
};

// The light frustum covers the scene's bounds as seen from the light centre; near/far are
// fitted to the bounds (near clamped > 0).
FrameSetup setupFrame(const Scene& scene, uint32_t mapSize, uint32_t width, uint32_t height);

}  // namespace shadowc::rt

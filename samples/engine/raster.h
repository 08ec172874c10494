// The engine's own raster passes (shaders/*.vert, *.frag): the light-depth map, every view of
// the scene file drawn into its tile with one viewport each (normalized linear depth into an
// r32f colour target, visibility from a depth attachment that a depth_input filter reads), and
// the camera's G-buffer (world position and normal, w = 1 on geometry).
#pragma once

#include <filesystem>

#include "scene_file.h"
#include "vulkan_device.h"

namespace engine {

struct RasterTargets {
  Image linearDepth;       // r32f, map^2, COLOR_ATTACHMENT usage among others; 1 where nothing is hit
  Image depth;             // D32 or D24, map^2, DEPTH_STENCIL_ATTACHMENT usage; cleared to 1, or 0 reversed
  bool reversed = false;   // reverse Z (clip z' = w - z, GREATER): a depth_input filter with (z: reverse)
  Image position, normal;  // rgba32f, screen^2
};

// Records both passes; every target ends in VK_IMAGE_LAYOUT_GENERAL. `shaderDir` holds the .spv.
void renderScene(Device& device, const SceneFile& scene, const RasterTargets& targets,
                 const std::filesystem::path& shaderDir);

std::vector<uint32_t> readSpirv(const std::filesystem::path& file);

}  // namespace engine

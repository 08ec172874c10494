// A camera G-buffer made by ray casting (Embree) instead of rasterizing: the same layout as
// the runtime's gbuffer_position / gbuffer_normal (RGBA32F, w = 1 on geometry, 0 background,
// row 0 = top of the image, pixel centres). Lets the reference, tests and tools run without
// Vulkan, and lets the rasterizer be checked against it.
#pragma once

#include <cstdint>
#include <vector>

#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {

struct CpuGBuffer {
  uint32_t width = 0, height = 0;
  std::vector<float> positions;  // RGBA per pixel
  std::vector<float> normals;    // RGBA per pixel (xyz unit normal, w = 1 on geometry)
};

// Rays through the pixel centres of frame.cameraViewProj (inverted), all cores.
CpuGBuffer rayCastGBuffer(const Scene& scene, const FrameSetup& frame);

}  // namespace shadowc::rt

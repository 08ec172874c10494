// Rasterizes a scene twice with Vulkan's graphics pipeline: the light depth map the filters
// start from, and the camera G-buffer the shade pass reads (conventions: templates/frame.glsl,
// BRIEFING "Fixed conventions"). No culling: shadow maps need both faces.
#pragma once

#include "runtime/executor/host_image.h"
#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {

class VulkanContext;

struct RasterOutputs {
  HostImage lightDepth;       // R32F, mapSize^2, normalized linear depth d, 1.0 where nothing is hit
  HostImage gbufferPosition;  // RGBA32F, width x height, xyz world, w = 1 on geometry, 0 background
  HostImage gbufferNormal;    // RGBA32F, xyz unit world normal, 0 background
};

RasterOutputs rasterize(VulkanContext& ctx, const Scene& scene, const FrameSetup& setup);

}  // namespace shadowc::rt

// Rasterizes a scene twice with Vulkan's graphics pipeline: the light depth map the filters
// start from, and the camera G-buffer the shade pass reads (conventions: templates/frame.glsl,
// BRIEFING "Fixed conventions"). No culling: shadow maps need both faces.
#pragma once

#include <nlohmann/json.hpp>

#include "runtime/executor/host_image.h"
#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {

class VulkanContext;

// The depth attachment of the light pass as an engine would keep it (a filter's `depth_input`,
// docs/dsl.md): D32F or D24, standard (LESS, cleared to 1) or reverse Z (GREATER, cleared to 0,
// clip z' = w - z). R32F = not kept: the light pass's attachment is D32 LESS and discarded.
struct HardwareDepth {
  ImageFormat format = ImageFormat::R32F;
  bool reversed = false;
  bool kept() const { return isDepthFormat(format); }
  friend bool operator==(const HardwareDepth&, const HardwareDepth&) = default;
};
// From a manifest's spec: its `depth_input`, or not kept when absent.
HardwareDepth hardwareDepthFromSpec(const nlohmann::json& spec);

struct RasterOutputs {
  HostImage lightDepth;       // R32F, mapSize^2, normalized linear depth d, 1.0 where nothing is hit
  HostImage gbufferPosition;  // RGBA32F, width x height, xyz world, w = 1 on geometry, 0 background
  HostImage gbufferNormal;    // RGBA32F, xyz unit world normal, 0 background
  // With a kept HardwareDepth: the light pass's depth attachment (the atlas's words, as the
  // linear depth's, "nothing hit" = the far value), from the same draw as lightDepth.
  HostImage hardwareDepth;
};

RasterOutputs rasterize(VulkanContext& ctx, const Scene& scene, const FrameSetup& setup,
                        const HardwareDepth& hardwareDepth = {});

}  // namespace shadowc::rt

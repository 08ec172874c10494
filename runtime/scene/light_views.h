// The views a frame renders into its light-depth map: one for a spot or a sun, six cube faces for
// a point light (cube_setup.h), one per cascade (cascade_setup.h) or light sample
// (light_sample_setup.h). The rasterizer draws exactly these, and `shadowc export-scene` writes
// them for an engine that renders the map itself (docs/integration.md "Exporting a scene").
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "runtime/scene/frame_setup.h"

namespace shadowc::rt {

struct LightView {
  glm::mat4 viewProj{1};  // world -> Vulkan clip of this view (its tile is the whole viewport)
  glm::vec4 zRow{0};      // light-view z of a world point: dot(zRow, (p, 1)); stored d = (z - near) / (far - near)
  uint32_t x0 = 0, y0 = 0, size = 0;  // the square of map texels the view fills
};

// In the order the rasterizer draws them; texels of the map outside every view read "nothing hit".
std::vector<LightView> lightViews(const FrameSetup& f);

}  // namespace shadowc::rt

// Light samples (docs/dsl.md "light_samples"): N hard views of a spot light from the points its
// manifest lists, each a tile of one atlas map. Written into FrameSetup (the rasterizer's per-view
// matrices) and the frame's tanHalfFov, which every view shares (templates/frame_light_samples.glsl,
// the lookup's side).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {

// What the manifest's spec says ("light_samples": {count, grid, offsets}); count 0 when the
// filter has one view from the light's centre. The runtime reads the manifest only.
struct LightSampleConfig {
  int count = 0;
  int grid = 1;                     // tiles per side of the atlas
  std::vector<glm::dvec2> offsets;  // on the light, in light widths (FilterSpec lightSampleOffsets)
  friend bool operator==(const LightSampleConfig&, const LightSampleConfig&) = default;
};
// Throws std::invalid_argument on a malformed "light_samples" object.
LightSampleConfig lightSampleConfigFromSpec(const nlohmann::json& spec);

// Moves the views of `c` onto the light of `f` (setupFrame's output for a spot scene): view i is
// the light view translated to s_i = width * offsets[i], its clip matrix the shared perspective
// whose tanHalfFov is refitted so that every view covers every vertex (with setupFrame's margin),
// and the frame's tanHalfFov is that one. Throws SceneError for a sun or point light, or a map
// too small for the atlas (a tile under 1 texel).
void setupLightSamples(const Scene& scene, const LightSampleConfig& c, FrameSetup& f);

}  // namespace shadowc::rt

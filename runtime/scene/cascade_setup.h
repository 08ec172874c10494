// Cascaded shadow maps for a sun (docs/scenes.md "Cascades"): the camera-depth splits and the orthographic
// window of each cascade, written into FrameSetup (the rasterizer's per-cascade matrices) and the
// cascade fields of ShadowcFrame (templates/frame_cascades.glsl, the lookup's side).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {

enum class CascadeScheme { Uniform, Log, Practical };

// What the manifest's spec says ("cascades": {count, split, lambda, blend, grid}); count 0 when
// the filter is not cascaded. The runtime reads the manifest only.
struct CascadeConfig {
  int count = 0;
  CascadeScheme split = CascadeScheme::Practical;
  double lambda = 0.5;
  double blend = 0.1;
  int grid = 1;  // tiles per side of the atlas
  friend bool operator==(const CascadeConfig&, const CascadeConfig&) = default;
};
// Throws std::invalid_argument on a malformed "cascades" object.
CascadeConfig cascadeConfigFromSpec(const nlohmann::json& spec);

// count + 1 camera depths from `near` to `far` (Zhang et al. 2006, "parallel-split shadow maps"):
// uniform near + (far - near) i/n, logarithmic near (far/near)^(i/n), practical the lambda mix.
std::vector<double> cascadeSplitDepths(const CascadeConfig& c, double near, double far);

// The camera depths the cascades cover: from max(cameraNear, kCascadeNearFraction * cameraFar)
// (fitCamera's near is 0.9 of the distance to the scene's box, near zero when the eye is inside
// it, which would spend a logarithmic split on the first centimetre) to cameraFar.
inline constexpr double kCascadeNearFraction = 0.01;

// Fits the cascades of `c` to the camera frustum of `f` (setupFrame's output for a sun scene):
// cascade i covers the frustum slice from split i (less the previous cascade's blend band, which
// it blends over) to split i + 1, bounded by the slice's circumscribed sphere (its radius does
// not change as the camera turns, so the window's size is constant), its centre snapped to the
// cascade's texel grid (the map does not shimmer as the camera moves). Throws SceneError for a
// spot light or a map side the grid does not divide.
void setupCascades(const Scene& scene, const CascadeConfig& c, FrameSetup& f);

}  // namespace shadowc::rt

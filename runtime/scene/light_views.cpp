#include "runtime/scene/light_views.h"

#include <glm/gtc/matrix_access.hpp>

#include "runtime/scene/cube_setup.h"

namespace shadowc::rt {
namespace {

// Views i = 0..count-1 in tiles (i mod grid, i div grid) of floor(mapSize / grid) texels, all with
// the light view's z row (a cascade's or light sample's depth is the light's own).
std::vector<LightView> tiles(const FrameSetup& f, const glm::mat4* viewProj, int count, int grid) {
  const uint32_t g = uint32_t(grid), tile = f.mapSize / g;
  const glm::vec4 z = glm::row(f.lightView, 2);
  std::vector<LightView> views;
  for (int i = 0; i < count; ++i)
    views.push_back({viewProj[i], z, uint32_t(i) % g * tile, uint32_t(i) / g * tile, tile});
  return views;
}

}  // namespace

std::vector<LightView> lightViews(const FrameSetup& f) {
  if (f.cube) {
    std::vector<LightView> views;
    for (int face = 0; face < 6; ++face) {
      const glm::uvec2 o = cubeCellOrigin(face, f.mapSize);
      views.push_back({f.faceViewProj[size_t(face)], f.faceZRow[size_t(face)], o.x, o.y, cubeCellSize(f.mapSize)});
    }
    return views;
  }
  if (f.cascadeCount > 0) return tiles(f, f.cascadeViewProj.data(), f.cascadeCount, f.cascadeGrid);
  if (!f.lightSampleViewProj.empty())
    return tiles(f, f.lightSampleViewProj.data(), int(f.lightSampleViewProj.size()), f.lightSampleGrid);
  return {{f.lightViewProj, glm::row(f.lightView, 2), 0, 0, f.mapSize}};
}

}  // namespace shadowc::rt

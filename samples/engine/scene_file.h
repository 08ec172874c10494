// The engine's level: a scene written by `shadowc export-scene` (docs/integration.md
// "Exporting a scene"): triangles, the camera, the light and the views to render into the
// light-depth map. The ShadowcFrame block is filled from the light with <shadowc/frame.h>.
#pragma once

#include <shadowc/frame.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace engine {

struct LightView {
  std::array<float, 16> viewProj;  // world -> Vulkan clip, column-major
  std::array<float, 4> zRow;       // light-view z = dot(zRow, (p, 1))
  uint32_t x0, y0, size;           // the map texels it fills (the viewport)
};

struct SceneFile {
  std::string name;
  uint32_t screen = 0, map = 0;
  std::vector<float> vertices;  // per vertex: position xyz, normal xyz; three vertices a triangle
  std::array<float, 16> cameraViewProj{};
  std::array<float, 3> lightPosition{};
  float nearPlane = 0, farPlane = 0;
  std::vector<LightView> views;
  shadowc::ShadowcFrame frame{};  // filled with the header's functions from the light
};

// Reads DIR/scene.json and its mesh; throws std::runtime_error naming the file and the field.
SceneFile readSceneFile(const std::filesystem::path& dir);

}  // namespace engine

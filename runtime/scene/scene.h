// A scene: camera, one area light, triangle meshes in world space. Loaded from JSON
// (docs/scenes.md) or built in (builtin_scenes.cpp). The runtime rasterizes it and Embree
// traces it; nothing here knows about shadow filters.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shadowc::rt {

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;  // world space (transforms already applied)
  std::vector<glm::vec3> normals;    // per vertex, unit length, world space
  std::vector<uint32_t> indices;     // triangles
};

enum class LightShape { Rect, Disk };
struct AreaLight {
  LightShape shape = LightShape::Rect;
  glm::vec3 position{0, 10, 0};   // centre
  glm::vec3 direction{0, -1, 0};  // unit axis, into the scene
  glm::vec3 up{0, 0, 1};          // orients the rectangle
  float width = 1.0f;             // side (rect) or diameter (disk), world units; 0 = point light
};

struct Camera {
  glm::vec3 eye{0, 5, 10};
  glm::vec3 target{0, 0, 0};
  glm::vec3 up{0, 1, 0};
  float fovYDegrees = 45.0f;
};

struct Scene {
  std::string name;
  Camera camera;
  AreaLight light;
  std::vector<Mesh> meshes;
  // Hash of every field (geometry included), hex: the key of the reference cache.
  std::string contentHash() const;
};

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A built-in name (see builtinSceneNames()) or a path to a .json scene. Throws SceneError
// with one clear message (unknown name with suggestions, missing file, bad JSON with the
// field, mesh that fails to load with assimp's reason).
Scene loadScene(const std::string& nameOrPath);
std::vector<std::string> builtinSceneNames();

}  // namespace shadowc::rt

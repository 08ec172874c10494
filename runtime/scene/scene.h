// A scene: camera, one light (an area spot light or a sun), triangle meshes in world space. Loaded from JSON
// (docs/scenes.md) or built in (builtin_scenes.cpp). The runtime rasterizes it and Embree
// traces it; nothing here knows about shadow filters.
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace shadowc::rt {

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;  // world space (transforms already applied)
  std::vector<glm::vec3> normals;    // per vertex, unit length, world space
  std::vector<uint32_t> indices;     // triangles
};

enum class LightShape { Rect, Disk };
// Spot: an area light at `position` shining along `direction` (a perspective shadow map from its
// centre). Sun: a directional light travelling along `direction` with angular diameter
// `angleDegrees` (an orthographic map fitted to the scene; `position`, `shape` and `width` unused).
// Point: an omnidirectional sphere light of `radius` at `position` (six cube faces in a 3x3 atlas
// of the shadow map, runtime/scene/cube_setup.h; `direction`, `up`, `shape` and `width` unused).
enum class LightType { Spot, Sun, Point };
struct AreaLight {
  LightType type = LightType::Spot;
  float angleDegrees = 0.0f;  // Sun: angular diameter (the sun: about 0.53)
  float radius = 0.0f;        // Point: the sphere's radius
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
  std::string description;  // free text (docs, reports)
  Camera camera;
  AreaLight light;
  std::vector<Mesh> meshes;
  // Hash of every field (geometry included), hex: the key of the reference cache.
  std::string contentHash() const;
};

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Axis-aligned bounds of every mesh vertex (world space). Empty scene: min > max.
struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{-std::numeric_limits<float>::max()};
  bool empty() const { return min.x > max.x; }
  glm::vec3 center() const { return 0.5f * (min + max); }
  float diagonal() const { return empty() ? 0.0f : glm::length(max - min); }
};
Bounds sceneBounds(const Scene& scene);

// A built-in name (see builtinSceneNames()) or a path to a .json scene. Throws SceneError
// with one clear message (unknown name with suggestions, missing file, bad JSON with the
// field, mesh that fails to load with assimp's reason).
Scene loadScene(const std::string& nameOrPath);
std::vector<std::string> builtinSceneNames();

// The JSON text of a built-in scene (the format of docs/scenes.md, 2-space indent, trailing
// newline): what samples/scenes/<name>.json holds. Throws SceneError for an unknown name.
std::string builtinSceneJson(const std::string& name);
// One line saying what makes a built-in scene hard ("" for an unknown name).
std::string builtinSceneDescription(const std::string& name);

// Parses scene JSON text. `sourceLabel` names the text in messages (a file path);
// mesh paths are resolved against `baseDir`.
Scene parseScene(const std::string& jsonText, const std::string& sourceLabel, const std::filesystem::path& baseDir);

}  // namespace shadowc::rt

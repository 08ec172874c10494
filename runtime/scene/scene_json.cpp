// Scene JSON -> Scene (format: docs/scenes.md). Every error names the JSON path of the field
// (objects[2].size) and what was expected, in one SceneError.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "runtime/scene/cube_setup.h"
#include "runtime/scene/mesh_loader.h"
#include "runtime/scene/scene.h"
#include "runtime/scene/scene_geometry.h"
#include "support/suggest.h"

namespace shadowc::rt {
namespace {

using nlohmann::json;

const char* typeName(const json& j) {
  switch (j.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "an array";
    case json::value_t::string:
      return "a string";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::discarded:
      return "nothing";
    default:
      return "a number";
  }
}

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    throw SceneError(fmt::format("{}: error: {}: {}", source_, path, message));
  }

  void expectObject(const json& j, const std::string& path) const {
    if (!j.is_object()) fail(path, fmt::format("expected an object, got {}", typeName(j)));
  }

  // Unknown keys are errors (a typo would otherwise be silently ignored).
  void checkKeys(const json& j, const std::string& path, const std::vector<std::string>& allowed) const {
    for (const auto& [key, value] : j.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      const std::string near = support::closestMatch(key, allowed);
      fail(join(path, key), near.empty() ? fmt::format("unknown field (expected one of: {})", fmt::join(allowed, ", "))
                                         : fmt::format("unknown field (did you mean '{}'?)", near));
    }
  }

  const json& require(const json& j, const std::string& path, const char* key) const {
    auto it = j.find(key);
    if (it == j.end()) fail(join(path, key), "missing required field");
    return *it;
  }

  double number(const json& j, const std::string& path) const {
    if (!j.is_number()) fail(path, fmt::format("expected a number, got {}", typeName(j)));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(path, "expected a finite number");
    return v;
  }

  float positive(const json& j, const std::string& path) const {
    const double v = number(j, path);
    if (!(v > 0)) fail(path, fmt::format("expected a positive number, got {}", v));
    return static_cast<float>(v);
  }

  glm::vec3 vec3(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3) fail(path, fmt::format("expected an array of 3 numbers, got {}", describe(j)));
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = static_cast<float>(number(j[i], fmt::format("{}[{}]", path, i)));
    return v;
  }

  // A size: one positive number for every axis, or an array of `n` positive numbers.
  std::vector<float> sizes(const json& j, const std::string& path, size_t n) const {
    if (j.is_number()) return std::vector<float>(n, positive(j, path));
    if (!j.is_array() || j.size() != n) {
      fail(path, fmt::format("expected a positive number or an array of {} positive numbers, got {}", n, describe(j)));
    }
    std::vector<float> out;
    for (size_t i = 0; i < n; ++i) out.push_back(positive(j[i], fmt::format("{}[{}]", path, i)));
    return out;
  }

  std::string string(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, fmt::format("expected a string, got {}", typeName(j)));
    return j.get<std::string>();
  }

  glm::vec3 unitVector(const json& j, const std::string& path) const {
    const glm::vec3 v = vec3(j, path);
    const float len = glm::length(v);
    if (!(len > 0)) fail(path, "expected a non-zero vector");
    return v / len;
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

 private:
  static std::string describe(const json& j) {
    if (j.is_array()) return fmt::format("an array of {}", j.size());
    return typeName(j);
  }
  std::string source_;
};

Camera readCamera(const Reader& r, const json& j) {
  const std::string p = "camera";
  r.expectObject(j, p);
  r.checkKeys(j, p, {"eye", "target", "up", "fov_y"});
  Camera c;
  c.eye = r.vec3(r.require(j, p, "eye"), p + ".eye");
  c.target = r.vec3(r.require(j, p, "target"), p + ".target");
  if (j.contains("up")) c.up = r.unitVector(j["up"], p + ".up");
  if (j.contains("fov_y")) {
    const double fov = r.number(j["fov_y"], p + ".fov_y");
    if (!(fov > 0 && fov < 180)) r.fail(p + ".fov_y", fmt::format("expected degrees in (0, 180), got {}", fov));
    c.fovYDegrees = static_cast<float>(fov);
  }
  if (glm::length(c.target - c.eye) == 0) r.fail(p + ".target", "equals camera.eye");
  if (glm::length(glm::cross(glm::normalize(c.target - c.eye), c.up)) < 1e-4f) {
    r.fail(p + ".up", "is parallel to the viewing direction");
  }
  return c;
}

AreaLight readLight(const Reader& r, const json& j) {
  const std::string p = "light";
  r.expectObject(j, p);
  AreaLight l;
  if (j.contains("type")) {
    const std::string type = r.string(j["type"], p + ".type");
    if (type == "sun") {
      // A sun: direction of travel and angular diameter; nothing has a position.
      r.checkKeys(j, p, {"type", "direction", "up", "angle"});
      l.type = LightType::Sun;
      l.shape = LightShape::Disk;
      l.width = 0.0f;
      l.direction = r.unitVector(r.require(j, p, "direction"), p + ".direction");
      if (j.contains("up")) l.up = r.unitVector(j["up"], p + ".up");
      if (glm::length(glm::cross(l.direction, l.up)) < 1e-4f) {
        l.up = std::abs(l.direction.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
        if (j.contains("up")) r.fail(p + ".up", "is parallel to light.direction");
      }
      const double angle = r.number(r.require(j, p, "angle"), p + ".angle");
      if (!(angle > 0 && angle <= 45))
        r.fail(p + ".angle", fmt::format("expected an angular diameter in degrees in (0, 45], got {}", angle));
      l.angleDegrees = static_cast<float>(angle);
      return l;
    }
    if (type == "point") {
      // An omnidirectional sphere light: a centre and a radius; it shines every way.
      r.checkKeys(j, p, {"type", "position", "radius"});
      l.type = LightType::Point;
      l.shape = LightShape::Disk;
      l.width = 0.0f;
      l.position = r.vec3(r.require(j, p, "position"), p + ".position");
      const double radius = r.number(r.require(j, p, "radius"), p + ".radius");
      if (!(radius > 0 && radius <= 1e4))
        r.fail(p + ".radius", fmt::format("expected a sphere radius in (0, 10000], got {}", radius));
      l.radius = static_cast<float>(radius);
      return l;
    }
    if (type != "spot") {
      const std::string near = support::closestMatch(type, {"spot", "sun", "point"});
      r.fail(p + ".type", fmt::format("unknown light type '{}' (expected spot, sun or point{})", type,
                                      near.empty() ? "" : fmt::format("; did you mean '{}'?", near)));
    }
  }
  r.checkKeys(j, p, {"type", "shape", "position", "direction", "up", "size"});
  if (j.contains("shape")) {
    const std::string shape = r.string(j["shape"], p + ".shape");
    if (shape == "rect") {
      l.shape = LightShape::Rect;
    } else if (shape == "disk") {
      l.shape = LightShape::Disk;
    } else {
      const std::string near = support::closestMatch(shape, {"rect", "disk"});
      r.fail(p + ".shape", fmt::format("unknown shape '{}' (expected rect or disk{})", shape,
                                       near.empty() ? "" : fmt::format("; did you mean '{}'?", near)));
    }
  }
  l.position = r.vec3(r.require(j, p, "position"), p + ".position");
  l.direction = r.unitVector(r.require(j, p, "direction"), p + ".direction");
  if (j.contains("up")) l.up = r.unitVector(j["up"], p + ".up");
  if (glm::length(glm::cross(l.direction, l.up)) < 1e-4f) r.fail(p + ".up", "is parallel to light.direction");
  const double size = r.number(r.require(j, p, "size"), p + ".size");
  if (size < 0) r.fail(p + ".size", fmt::format("expected a width >= 0 (0 = point light), got {}", size));
  l.width = static_cast<float>(size);
  return l;
}

Transform readTransform(const Reader& r, const json& j, const std::string& p) {
  r.expectObject(j, p);
  r.checkKeys(j, p, {"translate", "rotate", "scale"});
  Transform t;
  if (j.contains("translate")) t.translate = r.vec3(j["translate"], p + ".translate");
  if (j.contains("rotate")) t.rotateDegrees = r.vec3(j["rotate"], p + ".rotate");
  if (j.contains("scale")) {
    const json& s = j["scale"];
    if (s.is_number()) {
      t.scale = glm::vec3(r.number(s, p + ".scale"));
    } else {
      t.scale = r.vec3(s, p + ".scale");
    }
    if (t.scale.x == 0 || t.scale.y == 0 || t.scale.z == 0) r.fail(p + ".scale", "has a zero component");
  }
  return t;
}

Mesh readObject(const Reader& r, const json& j, const std::string& p, size_t index,
                const std::filesystem::path& baseDir) {
  r.expectObject(j, p);
  const std::string type = r.string(r.require(j, p, "type"), p + ".type");
  const std::vector<std::string> types = {"plane", "box", "sphere", "mesh"};
  Mesh mesh;
  if (type == "plane") {
    r.checkKeys(j, p, {"type", "name", "size", "transform"});
    const auto s = r.sizes(r.require(j, p, "size"), p + ".size", 2);
    mesh = makePlane(s[0], s[1]);
  } else if (type == "box") {
    r.checkKeys(j, p, {"type", "name", "size", "transform"});
    const auto s = r.sizes(r.require(j, p, "size"), p + ".size", 3);
    mesh = makeBox({s[0], s[1], s[2]});
  } else if (type == "sphere") {
    r.checkKeys(j, p, {"type", "name", "radius", "segments", "rings", "transform"});
    const float radius = r.positive(r.require(j, p, "radius"), p + ".radius");
    auto count = [&](const char* key, int def, int minimum) {
      if (!j.contains(key)) return def;
      const std::string kp = p + "." + key;
      if (!j[key].is_number_integer()) r.fail(kp, fmt::format("expected an integer, got {}", typeName(j[key])));
      const auto v = j[key].get<long long>();
      if (v < minimum || v > 4096) r.fail(kp, fmt::format("expected an integer in [{}, 4096], got {}", minimum, v));
      return static_cast<int>(v);
    };
    mesh = makeSphere(radius, count("segments", 32, 3), count("rings", 16, 2));
  } else if (type == "mesh") {
    r.checkKeys(j, p, {"type", "name", "path", "transform"});
    const std::string rel = r.string(r.require(j, p, "path"), p + ".path");
    try {
      mesh = loadMeshFile(baseDir / rel);
    } catch (const SceneError& e) {
      r.fail(p + ".path", e.what());
    }
  } else {
    const std::string near = support::closestMatch(type, types);
    r.fail(p + ".type", fmt::format("unknown object type '{}' (expected plane, box, sphere or mesh{})", type,
                                    near.empty() ? "" : fmt::format("; did you mean '{}'?", near)));
  }
  mesh.name = j.contains("name") ? r.string(j["name"], p + ".name") : fmt::format("{}{}", type, index);
  if (j.contains("transform")) applyTransform(mesh, readTransform(r, j["transform"], p + ".transform"));
  return mesh;
}

// 1-based line and column of a byte offset (nlohmann reports the offset after the bad token).
std::pair<size_t, size_t> lineColumn(const std::string& text, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t i = 0; i < std::min(byte, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col > 1 ? col - 1 : col};
}

}  // namespace

Scene parseScene(const std::string& jsonText, const std::string& sourceLabel, const std::filesystem::path& baseDir) {
  json j;
  try {
    j = json::parse(jsonText);
  } catch (const json::parse_error& e) {
    const auto [line, col] = lineColumn(jsonText, e.byte);
    std::string detail = e.what();
    // Drop nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 2: " prefix.
    if (const size_t at = detail.find(": "); at != std::string::npos && detail.find("parse error") < at) {
      detail = detail.substr(at + 2);
    }
    throw SceneError(fmt::format("{}:{}:{}: error: malformed JSON: {}", sourceLabel, line, col, detail));
  } catch (const json::exception& e) {
    // Well-formed text nlohmann still refuses, e.g. a number beyond double's range (out_of_range
    // 406; found by fuzz_scene, now a seed in tests/fuzz/corpus/scene/).
    throw SceneError(fmt::format("{}: error: malformed JSON: {}", sourceLabel, e.what()));
  }
  Reader r(sourceLabel);
  if (!j.is_object()) r.fail("(top level)", fmt::format("expected an object, got {}", typeName(j)));
  r.checkKeys(j, "", {"name", "description", "camera", "light", "objects"});
  Scene scene;
  scene.name = j.contains("name") ? r.string(j["name"], "name") : std::filesystem::path(sourceLabel).stem().string();
  if (j.contains("description")) scene.description = r.string(j["description"], "description");
  scene.camera = readCamera(r, r.require(j, "", "camera"));
  scene.light = readLight(r, r.require(j, "", "light"));
  const json& objects = r.require(j, "", "objects");
  if (!objects.is_array()) r.fail("objects", fmt::format("expected an array, got {}", typeName(objects)));
  if (objects.empty()) r.fail("objects", "the scene has no objects (at least a receiver is needed)");
  for (size_t i = 0; i < objects.size(); ++i) {
    const std::string p = fmt::format("objects[{}]", i);
    scene.meshes.push_back(readObject(r, objects[i], p, i, baseDir));
    // The shadow map is a perspective projection from the light centre (frame.glsl): it cannot
    // cover geometry on or behind the light's plane, and an area light emits only forwards.
    if (scene.light.type == LightType::Sun) continue;  // an orthographic map covers any side
    if (scene.light.type == LightType::Point) {
      // Six faces cover every side; the sphere itself must stay clear of the geometry.
      const float d = minDistanceToMesh(scene.meshes.back(), scene.light.position);
      if (!(d > scene.light.radius))
        r.fail(p, fmt::format("'{}' comes within {:g} of the point light's centre, inside its radius {:g}",
                              scene.meshes.back().name, d, scene.light.radius));
      continue;
    }
    float minZ = std::numeric_limits<float>::max();
    for (const glm::vec3& v : scene.meshes.back().positions) {
      minZ = std::min(minZ, glm::dot(v - scene.light.position, scene.light.direction));
    }
    if (!(minZ > 0)) {
      r.fail(p, fmt::format("'{}' reaches behind the light's plane (distance along light.direction {:g}); "
                            "every object must lie in front of the light",
                            scene.meshes.back().name, minZ));
    }
  }
  return scene;
}

}  // namespace shadowc::rt

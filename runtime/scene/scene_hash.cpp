// Scene::contentHash (XXH3-128 over every field, geometry included) and sceneBounds.
#include <fmt/format.h>

#include <cstring>
#include <type_traits>

#define XXH_INLINE_ALL
#include <xxhash.h>

#include "runtime/scene/scene.h"

namespace shadowc::rt {
namespace {

// Feeds fields in a fixed order with explicit lengths, so that no two different scenes
// produce the same byte stream (e.g. moving a vertex from one mesh to the next).
class Hasher {
 public:
  Hasher() : state_(XXH3_createState()) { XXH3_128bits_reset(state_); }
  ~Hasher() { XXH3_freeState(state_); }
  Hasher(const Hasher&) = delete;
  Hasher& operator=(const Hasher&) = delete;

  void bytes(const void* p, size_t n) { XXH3_128bits_update(state_, p, n); }
  template <typename T>
  requires std::is_trivially_copyable_v<T>
  void pod(const T& v) { bytes(&v, sizeof v); }
  void str(const std::string& s) {
    pod(static_cast<uint64_t>(s.size()));
    bytes(s.data(), s.size());
  }
  template <typename T>
  void vec(const std::vector<T>& v) {
    pod(static_cast<uint64_t>(v.size()));
    bytes(v.data(), v.size() * sizeof(T));
  }
  std::string hex() const {
    const XXH128_hash_t h = XXH3_128bits_digest(state_);
    return fmt::format("{:016x}{:016x}", h.high64, h.low64);
  }

 private:
  XXH3_state_t* state_;
};

}  // namespace

std::string Scene::contentHash() const {
  static_assert(sizeof(glm::vec3) == 12, "vec3 must be tightly packed for hashing");
  Hasher h;
  h.str("shadowc-scene-v1");
  h.str(name);
  h.str(description);
  h.pod(camera.eye);
  h.pod(camera.target);
  h.pod(camera.up);
  h.pod(camera.fovYDegrees);
  h.pod(static_cast<uint32_t>(light.shape));
  h.pod(light.position);
  h.pod(light.direction);
  h.pod(light.up);
  h.pod(light.width);
  // Added with suns: spot scenes hash as before (their reference caches stay valid).
  if (light.type == LightType::Sun) {
    h.str("sun");
    h.pod(light.angleDegrees);
  }
  if (light.type == LightType::Point) {
    h.str("point");
    h.pod(light.radius);
  }
  h.pod(static_cast<uint64_t>(meshes.size()));
  for (const Mesh& m : meshes) {
    h.str(m.name);
    h.vec(m.positions);
    h.vec(m.normals);
    h.vec(m.indices);
  }
  return h.hex();
}

Bounds sceneBounds(const Scene& scene) {
  Bounds b;
  for (const Mesh& m : scene.meshes) {
    for (const glm::vec3& p : m.positions) {
      b.min = glm::min(b.min, p);
      b.max = glm::max(b.max, p);
    }
  }
  return b;
}

}  // namespace shadowc::rt

// The scene's triangles in an Embree BVH (one device, one committed scene), shared by the
// ground-truth visibility tracer and the CPU G-buffer.
#pragma once

#include <embree3/rtcore.h>

#include <glm/glm.hpp>

#include "runtime/scene/scene.h"

namespace shadowc::rt {

struct RayHit {
  bool hit = false;
  float t = 0;
  glm::vec3 position{0}, normal{0};  // world; normal interpolated from the vertex normals
  uint32_t meshIndex = 0;
};

class EmbreeScene {
 public:
  explicit EmbreeScene(const Scene& scene);  // throws std::runtime_error with Embree's error
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Is anything hit on org + t * dir for t in [0, tfar]? Thread-safe.
  bool occluded(const glm::vec3& org, const glm::vec3& dir, float tfar) const;
  // Closest hit on org + t * dir, t > 0. Thread-safe.
  RayHit intersect(const glm::vec3& org, const glm::vec3& dir) const;

  RTCScene handle() const { return scene_; }
  const Scene& scene() const { return source_; }

 private:
  const Scene& source_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace shadowc::rt

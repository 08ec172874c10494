#include "runtime/reference/cpu_gbuffer.h"

#include <tbb/parallel_for.h>

#include "runtime/reference/embree_scene.h"

namespace shadowc::rt {

CpuGBuffer rayCastGBuffer(const Scene& scene, const FrameSetup& frame) {
  CpuGBuffer g;
  g.width = frame.width;
  g.height = frame.height;
  g.positions.assign(size_t(g.width) * g.height * 4, 0.0f);
  g.normals.assign(size_t(g.width) * g.height * 4, 0.0f);
  const EmbreeScene embree(scene);
  const glm::mat4 inv = glm::inverse(frame.cameraViewProj);
  tbb::parallel_for(uint32_t{0}, g.height, [&](uint32_t y) {
    for (uint32_t x = 0; x < g.width; ++x) {
      // Vulkan: ndc (-1, -1) is the top-left corner of pixel (0, 0).
      const float nx = 2.0f * (x + 0.5f) / g.width - 1.0f;
      const float ny = 2.0f * (y + 0.5f) / g.height - 1.0f;
      const glm::vec4 a = inv * glm::vec4(nx, ny, 0.0f, 1.0f);
      const glm::vec4 b = inv * glm::vec4(nx, ny, 1.0f, 1.0f);
      const glm::vec3 org = glm::vec3(a) / a.w;
      const glm::vec3 dir = glm::vec3(b) / b.w - org;
      const RayHit h = embree.intersect(org, dir);
      if (!h.hit) continue;
      float* p = &g.positions[(size_t(y) * g.width + x) * 4];
      float* n = &g.normals[(size_t(y) * g.width + x) * 4];
      p[0] = h.position.x;
      p[1] = h.position.y;
      p[2] = h.position.z;
      p[3] = 1.0f;
      n[0] = h.normal.x;
      n[1] = h.normal.y;
      n[2] = h.normal.z;
      n[3] = 1.0f;
    }
  });
  return g;
}

}  // namespace shadowc::rt

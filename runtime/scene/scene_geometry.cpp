#include "runtime/scene/scene_geometry.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <utility>

namespace shadowc::rt {

Mesh makePlane(float sizeX, float sizeZ) {
  Mesh m;
  m.name = "plane";
  const float hx = 0.5f * sizeX, hz = 0.5f * sizeZ;
  m.positions = {{-hx, 0, -hz}, {hx, 0, -hz}, {hx, 0, hz}, {-hx, 0, hz}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  // Counter-clockwise seen from +y (the side the normal points to).
  m.indices = {0, 2, 1, 0, 3, 2};
  return m;
}

Mesh makeBox(const glm::vec3& size) {
  Mesh m;
  m.name = "box";
  const glm::vec3 h = 0.5f * size;
  // Each face: normal n, two in-plane axes u, v with u x v = n so (0,1,2),(0,2,3) is CCW from outside.
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const glm::vec3& n : normals) {
    const glm::vec3 u = std::abs(n.y) > 0.5f ? glm::vec3(0, 0, n.y) : glm::vec3(0, 1, 0);
    const glm::vec3 v = glm::cross(n, u);  // u x v = n
    const auto base = static_cast<uint32_t>(m.positions.size());
    const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const glm::vec2& c : corners) {
      m.positions.push_back(h * (n + c.x * u + c.y * v));
      m.normals.push_back(n);
    }
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return m;
}

Mesh makeSphere(float radius, int segments, int rings) {
  Mesh m;
  m.name = "sphere";
  const double pi = std::numbers::pi;
  for (int r = 0; r <= rings; ++r) {
    const double theta = pi * r / rings;  // from +y down to -y
    for (int s = 0; s <= segments; ++s) {
      const double phi = 2.0 * pi * s / segments;
      const glm::vec3 n(static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::cos(theta)),
                        static_cast<float>(-std::sin(theta) * std::sin(phi)));
      m.positions.push_back(radius * n);
      m.normals.push_back(n);
    }
  }
  const auto row = static_cast<uint32_t>(segments + 1);
  for (uint32_t r = 0; r < static_cast<uint32_t>(rings); ++r) {
    for (uint32_t s = 0; s < static_cast<uint32_t>(segments); ++s) {
      const uint32_t a = r * row + s, b = a + row;
      // Skip the degenerate triangles at the poles.
      if (r != 0) m.indices.insert(m.indices.end(), {a, b, a + 1});
      if (r + 1 != static_cast<uint32_t>(rings)) m.indices.insert(m.indices.end(), {a + 1, b, b + 1});
    }
  }
  return m;
}

glm::mat4 Transform::matrix() const {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
  m = glm::rotate(m, glm::radians(rotateDegrees.z), glm::vec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotateDegrees.y), glm::vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotateDegrees.x), glm::vec3(1, 0, 0));
  return glm::scale(m, scale);
}

void applyTransform(Mesh& mesh, const Transform& t) {
  const glm::mat4 m = t.matrix();
  const glm::mat3 nm = glm::transpose(glm::inverse(glm::mat3(m)));
  for (glm::vec3& p : mesh.positions) p = glm::vec3(m * glm::vec4(p, 1.0f));
  for (glm::vec3& n : mesh.normals) {
    const glm::vec3 tn = nm * n;
    const float len = glm::length(tn);
    n = len > 0 ? tn / len : glm::vec3(0, 1, 0);
  }
  if (glm::determinant(glm::mat3(m)) < 0) {
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
  }
}

}  // namespace shadowc::rt

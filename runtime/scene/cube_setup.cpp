// A point light's cube faces (cube_setup.h).
#include "runtime/scene/cube_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/scene/frame_setup.h"

namespace shadowc::rt {
namespace {

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::vec3 closestOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const float denom = va + vb + vc;
  if (!(std::abs(denom) > 0)) return a;  // degenerate triangle
  return a + ab * (vb / denom) + ac * (vc / denom);
}

}  // namespace

glm::mat3 cubeFaceRows(int face) {
  const int a = face / 2;
  const float s = (face % 2) ? -1.0f : 1.0f;
  glm::mat3 m(0.0f);  // column-major: m[col][row]
  m[(a + 1) % 3][0] = 1.0f;
  m[(a + 2) % 3][1] = 1.0f;
  m[a][2] = s;
  return m;
}

int cubeFaceOf(const glm::vec3& v) {
  const glm::vec3 q = glm::abs(v);
  const int a = (q.x >= q.y && q.x >= q.z) ? 0 : (q.y >= q.z ? 1 : 2);
  return 2 * a + (v[a] < 0 ? 1 : 0);
}

uint32_t cubeCellSize(uint32_t mapSize) { return mapSize / 3; }

glm::uvec2 cubeCellOrigin(int face, uint32_t mapSize) {
  const uint32_t n = cubeCellSize(mapSize);
  return {uint32_t(face % 3) * n, uint32_t(face / 3) * n};
}

glm::vec2 cubeAtlasUV(const glm::vec3& p, float tanHalf, uint32_t mapSize) {
  const int f = cubeFaceOf(p);
  const glm::vec3 q = cubeFaceRows(f) * p;
  const glm::vec2 uvFace = 0.5f + 0.5f * glm::vec2(q.x, q.y) / (std::max(q.z, 1e-20f) * tanHalf);
  const float cell = float(cubeCellSize(mapSize)) / float(mapSize);
  return (glm::vec2(float(f % 3), float(f / 3)) + uvFace) * cell;
}

float minDistanceToMesh(const Mesh& mesh, const glm::vec3& point) {
  float best = std::numeric_limits<float>::max();
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::vec3& a = mesh.positions.at(mesh.indices[i]);
    const glm::vec3& b = mesh.positions.at(mesh.indices[i + 1]);
    const glm::vec3& c = mesh.positions.at(mesh.indices[i + 2]);
    best = std::min(best, glm::length(closestOnTriangle(point, a, b, c) - point));
  }
  return best;
}

void fitPoint(const Scene& scene, FrameSetup& f, float tanHalf) {
  f.cube = true;
  f.tanHalfFov = tanHalf;
  f.lightView = glm::mat4(1.0f);
  f.lightView[3] = glm::vec4(-scene.light.position, 1.0f);
  // Near: a point of a face's frustum has z_f >= |p| / sqrt(1 + 2 tanHalf^2), so the closest
  // triangle, at distance dmin, is in front of near = dmin / sqrt(1 + 2 t^2) in every face. Far:
  // z_f <= |p|. Margins as a spot's (frame_setup.cpp): d = 1 stays "nothing hit".
  float dmin = std::numeric_limits<float>::max(), dmax = 0;
  for (const Mesh& m : scene.meshes) {
    dmin = std::min(dmin, minDistanceToMesh(m, scene.light.position));
    for (const glm::vec3& p : m.positions) dmax = std::max(dmax, glm::length(p - scene.light.position));
  }
  if (!(dmax > 0)) dmin = 1, dmax = 2;
  f.nearPlane = std::max(0.98f * dmin / std::sqrt(1.0f + 2.0f * tanHalf * tanHalf), 1e-6f * dmax);
  f.farPlane = std::max(1.02f * dmax, f.nearPlane * 1.0001f);
  const float n = f.nearPlane, fa = f.farPlane;
  glm::mat4 proj(0.0f);  // frame_setup.cpp's spot clip: x / t, y / t, w = z
  proj[0][0] = 1.0f / tanHalf;
  proj[1][1] = 1.0f / tanHalf;
  proj[2][2] = fa / (fa - n);
  proj[2][3] = 1.0f;
  proj[3][2] = -fa * n / (fa - n);
  for (int face = 0; face < 6; ++face) {
    const glm::mat4 faceView = glm::mat4(cubeFaceRows(face)) * f.lightView;
    f.faceViewProj[face] = proj * faceView;
    for (int c = 0; c < 4; ++c) f.faceZRow[face][c] = faceView[c][2];
  }
  f.lightViewProj = f.faceViewProj[0];
}

}  // namespace shadowc::rt

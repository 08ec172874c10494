// A point light's cube map (templates/frame_cube.glsl): six perspective faces from the light's
// centre, packed into a 3x3 atlas of the one 2D shadow map (cells of floor(mapSize / 3) texels,
// face f = 2 axis + (negative) in cell (f % 3, f / 3), the third row empty). Each face is rendered
// with tan(half fov) = tanHalf > 1: its cell holds its 90 degrees plus a guard band of the
// neighbouring directions, which is what lets kernels filter across a face seam.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

#include "runtime/scene/scene.h"

namespace shadowc::rt {

struct FrameSetup;

// The runtime's face half-fov tangent: a guard band of (1 - 1/1.5) / 2 = 1/6 of the face each side
// (plan/shade_plan.cpp sizes SHADOWC_CUBE_KERNEL_MAX from it). 1 = no guard band (the seam test's
// sibling: kernels near a seam then read another face's cell).
constexpr float kCubeTanHalf = 1.5f;

// Rows (x_f, y_f, z_f) of face f in light view: z_f = s p[a], x_f = p[(a+1)%3], y_f = p[(a+2)%3].
glm::mat3 cubeFaceRows(int face);
// Face of the direction's major axis (ties: x before y before z), as frame_cube.glsl picks it.
int cubeFaceOf(const glm::vec3& lightViewDir);
uint32_t cubeCellSize(uint32_t mapSize);                // floor(mapSize / 3)
glm::uvec2 cubeCellOrigin(int face, uint32_t mapSize);  // texel of the cell's corner
// Atlas uv of a light-view point (frame_cube.glsl's shadowc_lightSpace.xy), for tests and tools.
glm::vec2 cubeAtlasUV(const glm::vec3& lightViewPos, float tanHalf, uint32_t mapSize);

// Smallest distance from `point` to the mesh's triangles (the near plane and the loader's check).
float minDistanceToMesh(const Mesh& mesh, const glm::vec3& point);

// Fills a point light's frame: lightView = translation to the centre, near/far covering every
// triangle in every face's frustum, the six faces' clip matrices and z rows, lightParams =
// (tanHalf, near, far, 2 radius), lightShape.x = 4.
void fitPoint(const Scene& scene, FrameSetup& f, float tanHalf);

}  // namespace shadowc::rt

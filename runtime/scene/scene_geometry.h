// Primitive meshes for scenes (plane, box, UV sphere) in local space, and the object
// transform (translate * rotate * scale) that places them in the world.
#pragma once

#include <glm/glm.hpp>

#include "runtime/scene/scene.h"

namespace shadowc::rt {

// Square-ish plane in local y = 0, normal +y, centred, sides sizeX (along x) by sizeZ (along z).
Mesh makePlane(float sizeX, float sizeZ);
// Axis-aligned box centred at the origin, flat-shaded (24 vertices, normals per face).
Mesh makeBox(const glm::vec3& size);
// UV sphere centred at the origin: `segments` around y, `rings` from pole to pole.
Mesh makeSphere(float radius, int segments, int rings);

struct Transform {
  glm::vec3 translate{0};
  glm::vec3 rotateDegrees{0};  // applied x first, then y, then z (R = Rz * Ry * Rx)
  glm::vec3 scale{1};
  glm::mat4 matrix() const;  // T * R * S
};

// Applies `t` in place: positions by the matrix, normals by its inverse transpose
// (renormalized). A negative-determinant transform flips the winding to keep it outward.
void applyTransform(Mesh& mesh, const Transform& t);

}  // namespace shadowc::rt

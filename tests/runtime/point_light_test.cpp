// A point light in the scene format, the frame and the Embree reference: the
// JSON form loads and is checked; the reference's directions lie on the cone the sphere subtends
// with equal solid angle per stratum; the cube atlas mapping of runtime/scene/cube_setup.h (the
// one frame_cube.glsl mirrors) agrees with each face's clip matrix, with siblings that a wrong
// face or no guard band disagree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "runtime/reference/embree_reference.h"
#include "runtime/scene/cube_setup.h"
#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"

namespace shadowc::rt {
namespace {

std::string errorOf(const std::string& light, const std::string& objects = R"([{"type": "plane", "size": 4}])") {
  try {
    parseScene(
        R"({"camera": {"eye": [0, 3, 3], "target": [0, 0, 0]}, "light": )" + light + R"(, "objects": )" + objects + "}",
        "t.json", ".");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(PointLight, JsonFormLoadsAndIsChecked) {
  const Scene s = parseScene(R"({"camera": {"eye": [0, 3, 3], "target": [0, 0, 0]},
    "light": {"type": "point", "position": [0, 1, 0], "radius": 0.1},
    "objects": [{"type": "plane", "size": 4}, {"type": "box", "size": 0.2, "transform": {"translate": [0, 1.5, 0]}}]})",
                             "t.json", ".");
  EXPECT_EQ(s.light.type, LightType::Point);
  EXPECT_FLOAT_EQ(s.light.radius, 0.1f);
  EXPECT_FLOAT_EQ(s.light.position.y, 1.0f);  // a box above the light is fine: six faces
  EXPECT_NE(errorOf(R"({"type": "point", "position": [0, 1, 0], "radius": 0})").find("light.radius: expected"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "point", "position": [0, 1, 0]})").find("light.radius: missing required field"),
            std::string::npos);
  EXPECT_NE(
      errorOf(R"({"type": "point", "position": [0, 1, 0], "radius": 1, "direction": [0, -1, 0]})").find("direction"),
      std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "pointt", "position": [0, 1, 0], "radius": 1})").find("did you mean 'point'"),
            std::string::npos);
  // The sphere must clear the geometry (the plane passes 0.05 below a light of radius 0.1).
  EXPECT_NE(errorOf(R"({"type": "point", "position": [0, 0.05, 0], "radius": 0.1})").find("inside its radius"),
            std::string::npos);
  EXPECT_EQ(errorOf(R"({"type": "point", "position": [0, 0.2, 0], "radius": 0.1})"), "(no error)");
  // The radius is part of the content hash (the reference cache key).
  Scene wider = s;
  wider.light.radius = 0.2f;
  EXPECT_NE(s.contentHash(), wider.contentHash());
}

TEST(PointLight, ReferenceDirectionsCoverTheSubtendedConeUniformly) {
  AreaLight l;
  l.type = LightType::Point;
  l.position = {0, 2, 0};
  l.radius = 0.5f;
  const glm::vec3 from(0, 0, 0);
  const double cosMax = std::sqrt(1.0 - 0.25 * 0.25);  // sin = R / D = 0.25
  constexpr int n = 32;
  double meanCos = 0, maxAngle = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::vec3 d = pointSampleDirection(l, from, i, j, n, 0.5f, 0.5f);
      EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
      meanCos += d.y / (n * n);
      maxAngle = std::max(maxAngle, std::acos(std::min(1.0, double(d.y))));
    }
  // Uniform in solid angle on the cap: E[cos] = (1 + cosMax) / 2; every direction inside it.
  EXPECT_NEAR(meanCos, 0.5 * (1 + cosMax), 2e-4);
  EXPECT_LE(maxAngle, std::asin(0.25) + 1e-4);
  EXPECT_GT(maxAngle, 0.9 * std::asin(0.25));
  // Sibling: a sphere twice as wide has a visibly different mean (the check can fail).
  l.radius = 1.0f;
  double wider = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) wider += pointSampleDirection(l, from, i, j, n, 0.5f, 0.5f).y / (n * n);
  EXPECT_GT(std::abs(wider - 0.5 * (1 + cosMax)), 10 * 2e-4);
}

// The atlas uv of a light-view point (frame_cube.glsl's mapping) from the face's clip matrix.
glm::vec2 uvFromClip(const FrameSetup& f, int face, const glm::vec3& world) {
  const glm::vec4 c = f.faceViewProj[face] * glm::vec4(world, 1.0f);
  const glm::vec2 uvFace = 0.5f + 0.5f * glm::vec2(c.x, c.y) / c.w;
  const float cell = float(cubeCellSize(f.mapSize)) / float(f.mapSize);
  return (glm::vec2(float(face % 3), float(face / 3)) + uvFace) * cell;
}

TEST(PointLight, AtlasMappingMatchesEachFaceProjection) {
  const Scene scene = loadScene("point_room");
  ASSERT_EQ(scene.light.type, LightType::Point);
  const FrameSetup f = setupFrame(scene, 1536, 64, 64);
  ASSERT_TRUE(f.cube);
  EXPECT_FLOAT_EQ(f.frame.lightParams[0], kCubeTanHalf);
  EXPECT_FLOAT_EQ(f.frame.lightParams[3], 2 * scene.light.radius);
  EXPECT_FLOAT_EQ(f.frame.lightShape[0], 4.0f);
  int checked = 0, wrongFaceAgrees = 0;
  for (const Mesh& m : scene.meshes)
    for (const glm::vec3& w : m.positions) {
      const glm::vec3 p = w - scene.light.position;
      const int face = cubeFaceOf(p);
      const glm::vec3 q = cubeFaceRows(face) * p;
      // In front of its face, beyond near, before far, and the face's z row gives z_f.
      EXPECT_GT(q.z, f.nearPlane);
      EXPECT_LT(q.z, f.farPlane);
      EXPECT_NEAR(glm::dot(f.faceZRow[face], glm::vec4(w, 1.0f)), q.z, 1e-4f * f.farPlane);
      const glm::vec2 uv = cubeAtlasUV(p, kCubeTanHalf, f.mapSize);
      const glm::vec2 clip = uvFromClip(f, face, w);
      EXPECT_NEAR(uv.x, clip.x, 1e-5f);
      EXPECT_NEAR(uv.y, clip.y, 1e-5f);
      // Its direction's own face keeps it within the face's 90 degrees, inside the guard band.
      const glm::vec2 local = uv / (float(cubeCellSize(f.mapSize)) / f.mapSize) - glm::vec2(face % 3, face / 3);
      const float band = 0.5f * (1 - 1 / kCubeTanHalf);
      EXPECT_GE(std::min(local.x, local.y), band - 1e-5f);
      EXPECT_LE(std::max(local.x, local.y), 1 - band + 1e-5f);
      // Sibling: another face's projection puts it somewhere else.
      const glm::vec2 other = uvFromClip(f, (face + 2) % 6, w);
      if (glm::length(other - uv) < 1e-3f) ++wrongFaceAgrees;
      ++checked;
    }
  EXPECT_GT(checked, 100);
  EXPECT_EQ(wrongFaceAgrees, 0);
}

TEST(PointLight, FaceSelectionFollowsTheMajorAxis) {
  EXPECT_EQ(cubeFaceOf({2, 1, -1}), 0);
  EXPECT_EQ(cubeFaceOf({-2, 1, -1}), 1);
  EXPECT_EQ(cubeFaceOf({0.1f, 3, 1}), 2);
  EXPECT_EQ(cubeFaceOf({0.1f, -3, 1}), 3);
  EXPECT_EQ(cubeFaceOf({0.1f, 0.2f, 1}), 4);
  EXPECT_EQ(cubeFaceOf({0.1f, 0.2f, -1}), 5);
  // Every face's rows are a rotation or reflection (orthonormal) with z_f = |major axis|.
  for (int f = 0; f < 6; ++f) {
    const glm::mat3 r = cubeFaceRows(f);
    const glm::mat3 rrt = r * glm::transpose(r);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_FLOAT_EQ(rrt[i][j], i == j ? 1.0f : 0.0f);
    const glm::vec3 axis = glm::transpose(r)[2];  // row 2
    EXPECT_FLOAT_EQ(std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z), 1.0f);
    EXPECT_EQ(cubeFaceOf(axis), f);
  }
}

}  // namespace
}  // namespace shadowc::rt

// Scene loading: the JSON format's fields and transforms, and one clear SceneError per mistake.
#include <gtest/gtest.h>

#include <fstream>
#include <glm/gtc/constants.hpp>

#include "runtime/scene/scene.h"
#include "support/test_support.h"

namespace shadowc::rt {
namespace {

std::string errorOf(const std::string& text, const std::filesystem::path& baseDir = ".") {
  try {
    parseScene(text, "t.json", baseDir);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string loadError(const std::string& nameOrPath) {
  try {
    loadScene(nameOrPath);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// A valid scene with `objects` spliced in.
std::string withObjects(const std::string& objects) {
  return R"({"camera": {"eye": [0, 5, 5], "target": [0, 0, 0]},
  "light": {"position": [0, 5, 0], "direction": [0, -1, 0], "size": 1},
  "objects": )" +
         objects + "}";
}

TEST(SceneLoad, PrimitivesAndTransforms) {
  const Scene s = parseScene(withObjects(R"([
    {"type": "plane", "size": [4, 2]},
    {"type": "box", "name": "b", "size": [1, 2, 3], "transform": {"translate": [0, 1, 0], "scale": 2}},
    {"type": "sphere", "radius": 0.5, "segments": 8, "rings": 4, "transform": {"translate": [1, 1, 1]}},
    {"type": "box", "size": 1, "transform": {"rotate": [0, 90, 0], "translate": [2, 1, 0], "scale": [2, 1, 1]}}
  ])"),
                             "t.json", ".");
  ASSERT_EQ(s.meshes.size(), 4u);
  EXPECT_EQ(s.name, "t");
  EXPECT_EQ(s.meshes[0].name, "plane0");
  EXPECT_EQ(s.meshes[1].name, "b");
  auto bounds = [](const Mesh& m) {
    Scene one;
    one.meshes = {m};
    return sceneBounds(one);
  };
  const Bounds plane = bounds(s.meshes[0]);
  EXPECT_FLOAT_EQ(plane.min.x, -2);
  EXPECT_FLOAT_EQ(plane.max.z, 1);
  const Bounds box = bounds(s.meshes[1]);
  EXPECT_FLOAT_EQ(box.min.y, -1);  // (2 * size 2) / 2 below y = 1
  EXPECT_FLOAT_EQ(box.max.z, 3);
  const Bounds sphere = bounds(s.meshes[2]);
  EXPECT_NEAR(sphere.max.y, 1.5f, 1e-6f);
  EXPECT_NEAR(sphere.min.y, 0.5f, 1e-6f);
  // Scale first, then rotate 90 degrees about y (x -> -z): the box is 2 long along z.
  const Bounds rotated = bounds(s.meshes[3]);
  EXPECT_NEAR(rotated.max.z - rotated.min.z, 2.0f, 1e-5f);
  EXPECT_NEAR(rotated.max.x - rotated.min.x, 1.0f, 1e-5f);
  // Normals follow the transform: the +x face of a box rotated about y now faces -z.
  bool facesMinusZ = false;
  for (const glm::vec3& n : s.meshes[3].normals) facesMinusZ |= glm::length(n - glm::vec3(0, 0, -1)) < 1e-5f;
  EXPECT_TRUE(facesMinusZ);
  EXPECT_EQ(s.light.shape, LightShape::Rect);
  EXPECT_FLOAT_EQ(s.camera.fovYDegrees, 45.0f);
}

TEST(SceneLoad, UnknownBuiltinSuggestsAndListsNames) {
  const std::string e = loadError("two_plane");
  EXPECT_NE(e.find("unknown scene 'two_plane'"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'two_planes'"), std::string::npos) << e;
  EXPECT_NE(e.find("stacked_planes"), std::string::npos) << e;  // the list
  EXPECT_EQ(loadError("zzzzzzzzzzzz").find("did you mean"), std::string::npos);
}

TEST(SceneLoad, MissingFile) {
  const std::string e = loadError("no/such/scene.json");
  EXPECT_NE(e.find("no/such/scene.json: error: scene file not found"), std::string::npos) << e;
}

TEST(SceneLoad, MalformedJsonGivesLineAndColumn) {
  const std::string e = errorOf("{\n  \"camera\": {\n    \"eye\": [0, 1,, 2]\n  }\n}");
  EXPECT_NE(e.find("t.json:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("malformed JSON"), std::string::npos) << e;
  EXPECT_EQ(e.find("[json.exception"), std::string::npos) << e;
}

TEST(SceneLoad, MissingFieldNamesItsPath) {
  const std::string e = errorOf(withObjects(R"([{"type": "plane", "size": 2}, {"type": "box"}])"));
  EXPECT_NE(e.find("t.json: error: objects[1].size: missing required field"), std::string::npos) << e;
  EXPECT_NE(errorOf(R"({"light": {}, "objects": []})").find("camera: missing required field"), std::string::npos);
}

TEST(SceneLoad, IllTypedFieldNamesItsPath) {
  std::string e = errorOf(withObjects(R"([{"type": "plane", "size": "big"}])"));
  EXPECT_NE(e.find("objects[0].size: expected a positive number or an array of 2"), std::string::npos) << e;
  e = errorOf(withObjects(R"([{"type": "box", "size": [1, -2, 1]}])"));
  EXPECT_NE(e.find("objects[0].size[1]: expected a positive number"), std::string::npos) << e;
  e = errorOf(withObjects(R"([{"type": "sphere", "radius": 1, "transform": {"translate": [0, 2]}}])"));
  EXPECT_NE(e.find("objects[0].transform.translate: expected an array of 3 numbers, got an array of 2"),
            std::string::npos)
      << e;
}

TEST(SceneLoad, TyposGetSuggestions) {
  std::string e = errorOf(withObjects(R"([{"type": "plane", "sise": 2}])"));
  EXPECT_NE(e.find("objects[0].sise: unknown field (did you mean 'size'?)"), std::string::npos) << e;
  e = errorOf(withObjects(R"([{"type": "spere", "radius": 2}])"));
  EXPECT_NE(e.find("did you mean 'sphere'"), std::string::npos) << e;
}

TEST(SceneLoad, NoObjects) {
  const std::string e = errorOf(withObjects("[]"));
  EXPECT_NE(e.find("objects: the scene has no objects"), std::string::npos) << e;
}

TEST(SceneLoad, ObjectBehindTheLightIsRejected) {
  const std::string e = errorOf(withObjects(R"([{"type": "box", "size": 1, "transform": {"translate": [0, 5, 0]}}])"));
  EXPECT_NE(e.find("objects[0]: 'box0' reaches behind the light's plane"), std::string::npos) << e;
}

TEST(SceneLoad, MeshErrorsCarryTheReason) {
  const auto dir = test::freshTempDir("scene_mesh");
  std::string e = errorOf(withObjects(R"([{"type": "mesh", "path": "missing.obj"}])"), dir);
  EXPECT_NE(e.find("objects[0].path:"), std::string::npos) << e;
  EXPECT_NE(e.find("file not found"), std::string::npos) << e;
  std::ofstream(dir / "broken.ply") << "ply\nformat ascii 1.0\nelement vertex banana\nend_header\n";
  e = errorOf(withObjects(R"([{"type": "mesh", "path": "broken.ply"}])"), dir);
  EXPECT_NE(e.find("cannot load mesh:"), std::string::npos) << e;
  EXPECT_GT(e.size(), e.find("cannot load mesh:") + 20) << "assimp's reason is missing: " << e;
}

TEST(SceneLoad, MeshFromAFileRelativeToTheScene) {
  const auto dir = test::freshTempDir("scene_mesh_ok");
  std::ofstream(dir / "tri.obj") << "v -1 0 -1\nv 1 0 -1\nv 0 0 1\nf 1 3 2\n";
  std::ofstream(dir / "s.json") << withObjects(
      R"([{"type": "mesh", "path": "tri.obj", "transform": {"translate": [0, 1, 0]}}])");
  const Scene s = loadScene((dir / "s.json").string());
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].indices.size(), 3u);
  EXPECT_FLOAT_EQ(s.meshes[0].positions[0].y, 1.0f);
  EXPECT_NEAR(std::abs(s.meshes[0].normals[0].y), 1.0f, 1e-5f);
}

}  // namespace
}  // namespace shadowc::rt

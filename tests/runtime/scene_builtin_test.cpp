// Built-in scenes: all load, are well formed, match their samples/scenes/*.json files, and hash stably.
#include <gtest/gtest.h>

#include <cmath>

#include "runtime/scene/scene.h"
#include "support/test_support.h"

namespace shadowc::rt {
namespace {

TEST(SceneBuiltin, HasEveryRequiredHardCase) {
  const auto names = builtinSceneNames();
  for (const char* required :
       {"two_planes", "stacked_planes", "contact", "overlapping_occluders", "large_penumbra", "small_penumbra",
        "depth_range", "grazing", "thin_occluders", "empty", "fully_occluded", "mesh", "duck", "spider", "engine"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), required), names.end()) << required;
    EXPECT_FALSE(builtinSceneDescription(required).empty()) << required;
  }
}

TEST(SceneBuiltin, EveryBuiltinLoadsWellFormed) {
  for (const std::string& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    const Scene s = loadScene(name);
    EXPECT_EQ(s.name, name);
    ASSERT_FALSE(s.meshes.empty());
    for (const Mesh& m : s.meshes) {
      ASSERT_EQ(m.positions.size(), m.normals.size()) << m.name;
      ASSERT_FALSE(m.indices.empty()) << m.name;
      ASSERT_EQ(m.indices.size() % 3, 0u) << m.name;
      for (uint32_t i : m.indices) ASSERT_LT(i, m.positions.size()) << m.name;
      for (const glm::vec3& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << m.name;
    }
  }
}

TEST(SceneBuiltin, SampleFilesAreTheBuiltins) {
  // samples/scenes/<name>.json is what users read; regenerate with SHADOWC_UPDATE_GOLDEN=1.
  for (const std::string& name : builtinSceneNames()) {
    const auto path = test::sourceDir() / "samples" / "scenes" / (name + ".json");
    EXPECT_EQ(test::compareGolden(path, builtinSceneJson(name)), "") << path;
    if (std::filesystem::exists(path)) {
      EXPECT_EQ(loadScene(path.string()).contentHash(), loadScene(name).contentHash()) << name;
    }
  }
}

TEST(SceneBuiltin, MeshSceneLoadsTheKnotThroughAssimp) {
  const Scene s = loadScene("mesh");
  const auto it = std::find_if(s.meshes.begin(), s.meshes.end(), [](const Mesh& m) { return m.name == "knot"; });
  ASSERT_NE(it, s.meshes.end());
  EXPECT_EQ(it->indices.size() / 3, 1920u);  // scripts/gen_knot_mesh.py: 96 x 10 x 2 triangles
  // Outward normals: the tube normals point away from the knot's centre line on average, i.e.
  // the mean of dot(n, p - centroid) is positive.
  glm::vec3 c(0);
  for (const glm::vec3& p : it->positions) c += p;
  c /= static_cast<float>(it->positions.size());
  double outward = 0;
  for (size_t i = 0; i < it->positions.size(); ++i) outward += glm::dot(it->normals[i], it->positions[i] - c);
  EXPECT_GT(outward, 0.0);
}

// The real-mesh scenes load Debian's assimp-testmodels files (COLLADA, OBJ, binary glTF 2) through
// assimp, with every part kept: the triangle counts are those of the files, and each model
// stands on the floor (lowest vertex within 2 % of its height above y = 0).
TEST(SceneBuiltin, RealMeshScenesLoadTheDebianModelsThroughAssimp) {
  for (const auto& [name, triangles] :
       std::vector<std::pair<std::string, size_t>>{{"duck", 4212}, {"spider", 1368}, {"engine", 121496}}) {
    SCOPED_TRACE(name);
    const Scene s = loadScene(name);
    const auto it = std::find_if(s.meshes.begin(), s.meshes.end(), [&](const Mesh& m) { return m.name == name; });
    ASSERT_NE(it, s.meshes.end());
    EXPECT_EQ(it->indices.size() / 3, triangles);
    float lo = 1e30f, hi = -1e30f;
    for (const glm::vec3& p : it->positions) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
    EXPECT_GE(lo, -0.02f * (hi - lo));
    EXPECT_LE(lo, 0.02f * (hi - lo));
  }
}

TEST(SceneBuiltin, ContentHashIsStableAndSeesEveryField) {
  const Scene a = loadScene("two_planes");
  const std::string h = a.contentHash();
  EXPECT_EQ(h.size(), 32u);
  EXPECT_EQ(h, loadScene("two_planes").contentHash());
  auto changed = [&](auto mutate) {
    Scene b = a;
    mutate(b);
    return b.contentHash() != h;
  };
  EXPECT_TRUE(changed([](Scene& s) { s.camera.eye.x += 1e-6f; }));
  EXPECT_TRUE(changed([](Scene& s) { s.camera.fovYDegrees += 1; }));
  EXPECT_TRUE(changed([](Scene& s) { s.light.width *= 2; }));
  EXPECT_TRUE(changed([](Scene& s) { s.light.shape = LightShape::Disk; }));
  EXPECT_TRUE(changed([](Scene& s) { s.meshes[1].positions[0].y += 1e-6f; }));
  EXPECT_TRUE(changed([](Scene& s) { s.meshes[1].normals[0] = -s.meshes[1].normals[0]; }));
  EXPECT_TRUE(changed([](Scene& s) { std::swap(s.meshes[0].indices[0], s.meshes[0].indices[1]); }));
  // Moving a triangle from one mesh to the next is a different scene.
  EXPECT_TRUE(changed([](Scene& s) { s.meshes[0].indices.resize(3); }));
  EXPECT_FALSE(changed([](Scene&) {}));
}

TEST(SceneBuiltin, BoundsCoverEveryVertex) {
  const Scene s = loadScene("contact");
  const Bounds b = sceneBounds(s);
  ASSERT_FALSE(b.empty());
  EXPECT_FLOAT_EQ(b.min.y, 0.0f);  // everything rests on the floor
  EXPECT_FLOAT_EQ(b.min.x, -5.0f);
  EXPECT_FLOAT_EQ(b.max.z, 5.0f);
  EXPECT_TRUE(sceneBounds(Scene{}).empty());
}

}  // namespace
}  // namespace shadowc::rt

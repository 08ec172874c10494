// `shadowc export-scene` (docs/integration.md "Exporting a scene"): an engine that fills its
// ShadowcFrame from the exported light with include/shadowc/frame.h's functions gets the run
// harness's frame byte for byte, for a spot, a cascaded sun and a point light; the light views
// are the rasterizer's and the triangles the scene's. Siblings: a light value one float step off
// gives another frame; a filter for another light type is one message and writes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "driver/driver.h"
#include "emit/emit_support.h"
#include "runtime/harness/scene_run.h"
#include "runtime/scene/light_views.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

using nlohmann::json;

std::vector<float> floats(const json& a) { return a.get<std::vector<float>>(); }

// The frame as an engine fills it from scene.json (docs/integration.md), nothing else read.
ShadowcFrame engineFrame(const json& j) {
  ShadowcFrame f{};
  const json& l = j["light"];
  const std::vector<float> view = floats(l["view"]);
  const float near = l["near"], far = l["far"];
  const std::string type = l["type"];
  if (type == "spot")
    setSpotLight(f, view.data(), l["tan_half_fov"], near, far, l["width"], l["disk"]);
  else if (type == "sun")
    setSunLight(f, view.data(), l["half_extent"], near, far, l["angle_radians"].get<double>());
  else
    setPointLight(f, view.data(), l["face_tan_half_fov"], near, far, l["radius"]);
  setMapSize(f, j["map"]);
  setScreenSize(f, j["screen"], j["screen"]);
  if (j.contains("cascades")) {
    const json& c = j["cascades"];
    const std::vector<float> row = floats(c["camera_depth_row"]);
    setCascadeInfo(f, c["count"], c["first_split"].get<double>(), row.data());
    for (int i = 0; i < c["count"].get<int>(); ++i) {
      const std::vector<double> w = c["windows"][size_t(i)].get<std::vector<double>>();
      setCascade(f, i, w[0], w[1], w[2], w[3], j["map"], c["grid"]);
    }
  }
  return f;
}

struct Exported {
  json scene;
  std::string mesh;
};
Exported exportScene(const std::string& scene, const std::string& extra = "") {
  const auto dir = test::freshTempDir("export-scene");
  const test::CliResult c =
      test::runShadowc("export-scene " + scene + " -o " + dir.string() + " --screen 64 --map 256 " + extra);
  EXPECT_EQ(c.code, 0) << c.err;
  Exported e{json::parse(test::readFile(dir / "scene.json")), test::readFile(dir / "mesh.f32")};
  std::filesystem::remove_all(dir);
  return e;
}

std::string cascadedSun() {
  const auto dir = test::freshTempDir("export-scene-filter");
  std::string text = test::withLight(test::readFile(test::samplePath("pcss_poisson")), "light sun(angle: 0.53)");
  text.insert(text.rfind('}'), "    cascades 4\n");
  const auto path = dir / "pcss_poisson.shadow";
  std::ofstream(path) << text;
  return path.string();
}

rt::FrameSetup harnessSetup(const std::string& sceneName, const nlohmann::json& spec) {
  rt::SceneSettings s;
  s.map = 256;
  s.screen = 64;
  rt::setFilterViews(s, spec);
  return rt::fitFrame(rt::loadScene(sceneName), s);
}

TEST(ExportScene, AnEngineFillsTheHarnessFrameAndDrawsItsViewsFromTheExport) {
  const std::string sun = cascadedSun();
  struct Case {
    std::string scene, extra;
    nlohmann::json spec;
  };
  for (const Case& c : {Case{"two_planes", "", json::object()}, Case{"sun_two_planes", "--filter " + sun, json()},
                        Case{"point_room", "", json::object()}}) {
    const Exported e = exportScene(c.scene, c.extra);
    ASSERT_EQ(e.scene["format"], "shadowc-scene-export");
    // The filter's spec as the harness reads it (compiled the same way the export compiled it).
    nlohmann::json spec = c.spec;
    if (spec.is_null()) {
      const driver::Result r = driver::compileFile(sun);
      ASSERT_TRUE(r.ok) << r.log;
      spec = r.artifact->manifest.spec;
    }
    const rt::FrameSetup h = harnessSetup(c.scene, spec);
    const ShadowcFrame f = engineFrame(e.scene);
    EXPECT_EQ(std::memcmp(&f, &h.frame, sizeof f), 0) << c.scene << ": the engine's frame is not the harness's";
    if (c.scene == "sun_two_planes") {
      EXPECT_EQ(e.scene["cascades"]["count"], 4);
    }

    // The views, exactly the rasterizer's.
    const std::vector<rt::LightView> views = rt::lightViews(h);
    ASSERT_EQ(e.scene["light_views"].size(), views.size()) << c.scene;
    for (size_t i = 0; i < views.size(); ++i) {
      const json& v = e.scene["light_views"][i];
      const std::vector<float> m = floats(v["view_proj"]), z = floats(v["z_row"]);
      EXPECT_EQ(std::memcmp(m.data(), glm::value_ptr(views[i].viewProj), 64), 0) << c.scene << " view " << i;
      EXPECT_EQ(std::memcmp(z.data(), glm::value_ptr(views[i].zRow), 16), 0) << c.scene << " view " << i;
      EXPECT_EQ(v["tile"], json::array({views[i].x0, views[i].y0, views[i].size}));
    }
    const std::vector<float> cam = floats(e.scene["camera"]["view_proj"]);
    EXPECT_EQ(std::memcmp(cam.data(), glm::value_ptr(h.cameraViewProj), 64), 0) << c.scene;

    // The triangles: every index of every mesh expanded, position then normal.
    const rt::Scene scene = rt::loadScene(c.scene);
    size_t triangles = 0;
    for (const rt::Mesh& m : scene.meshes) triangles += m.indices.size() / 3;
    ASSERT_EQ(e.scene["mesh"]["triangles"], triangles);
    ASSERT_EQ(e.mesh.size(), triangles * 3 * 6 * sizeof(float));
    const rt::Mesh& last = scene.meshes.back();
    const uint32_t idx = last.indices.back();
    float v[6];
    std::memcpy(v, e.mesh.data() + e.mesh.size() - sizeof v, sizeof v);
    EXPECT_EQ(glm::vec3(v[0], v[1], v[2]), last.positions[idx]) << c.scene;
    EXPECT_EQ(glm::vec3(v[3], v[4], v[5]), last.normals[idx]) << c.scene;

    // Sibling: the near plane one float step off is another frame.
    json off = e.scene;
    off["light"]["near"] = std::nextafter(off["light"]["near"].get<float>(), 1e9f);
    const ShadowcFrame g = engineFrame(off);
    EXPECT_NE(std::memcmp(&g, &h.frame, sizeof g), 0) << c.scene;
  }
}

TEST(ExportScene, AFilterForAnotherLightIsOneMessageAndWritesNothing) {
  const auto dir = test::freshTempDir("export-scene-refused");
  const test::CliResult c =
      test::runShadowc("export-scene two_planes -o " + (dir / "out").string() + " --filter " + cascadedSun());
  EXPECT_NE(c.code, 0);
  EXPECT_NE(c.err.find("is for a sun but scene 'two_planes' has a spot light"), std::string::npos) << c.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  const test::CliResult bad = test::runShadowc("export-scene two_planes -o " + (dir / "out").string() + " --map 0");
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("--screen and --map must be positive"), std::string::npos) << bad.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace shadowc

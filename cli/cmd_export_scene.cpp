// `shadowc export-scene SCENE -o DIR [--screen N] [--map N] [--filter F]`: a built-in or .json
// scene as an engine holds its level (docs/integration.md "Exporting a scene"): the triangles,
// the camera, the light with the arguments of include/shadowc/frame.h's functions, and the views
// to render into the light-depth map (rasterizer's lightViews), fitted exactly as `validate`
// fits them at those sizes. An engine that renders these and fills its frame block from them
// sees what `validate` sees, so its visibility can be compared with validate's. CPU only.
#include <fmt/core.h>

#include <glm/gtc/type_ptr.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "cli/commands.h"
#include "driver/driver.h"
#include "runtime/harness/scene_run.h"
#include "runtime/images/atomic_file.h"
#include "runtime/scene/light_views.h"

namespace shadowc::cli {
namespace {

using nlohmann::ordered_json;

ordered_json matrix(const glm::mat4& m) {  // column-major, as glm and GLSL store it
  ordered_json a = ordered_json::array();
  for (int i = 0; i < 16; ++i) a.push_back(glm::value_ptr(m)[i]);
  return a;
}
ordered_json vec4(const glm::vec4& v) { return ordered_json::array({v.x, v.y, v.z, v.w}); }

// The light as the frame header's set*Light functions take it (frame_setup.cpp calls the same).
ordered_json lightJson(const rt::Scene& scene, const rt::FrameSetup& f) {
  ordered_json j;
  j["position"] = ordered_json::array({scene.light.position.x, scene.light.position.y, scene.light.position.z});
  j["view"] = matrix(f.lightView);
  j["near"] = f.nearPlane;
  j["far"] = f.farPlane;
  if (f.cube) {
    j["type"] = "point";
    j["face_tan_half_fov"] = f.tanHalfFov;
    j["radius"] = scene.light.radius;
  } else if (scene.light.type == rt::LightType::Sun) {
    j["type"] = "sun";
    j["half_extent"] = f.halfExtent;
    j["angle_radians"] = glm::radians(double(scene.light.angleDegrees));
  } else {
    j["type"] = "spot";
    j["tan_half_fov"] = f.tanHalfFov;
    j["width"] = scene.light.width;
    j["disk"] = scene.light.shape == rt::LightShape::Disk;
  }
  return j;
}

// Triangle soup, three vertices a triangle, each position xyz then normal xyz (float32).
std::string meshBytes(const rt::Scene& scene, size_t& triangles) {
  std::vector<float> v;
  for (const rt::Mesh& m : scene.meshes)
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3)
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t idx = m.indices[i + k];
        if (idx >= m.positions.size() || idx >= m.normals.size())
          throw rt::SceneError(fmt::format("scene '{}': mesh '{}' index {} out of range", scene.name, m.name, idx));
        v.insert(v.end(), {m.positions[idx].x, m.positions[idx].y, m.positions[idx].z, m.normals[idx].x,
                           m.normals[idx].y, m.normals[idx].z});
      }
  triangles = v.size() / 18;
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float));
}

}  // namespace

CommandRunner registerExportScene(CLI::App& app) {
  struct Options {
    std::string scene, out, filter;
    uint32_t screen = 256, map = 1024;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "export-scene", "Write a scene's triangles, camera, light and light views for an engine (docs/integration.md)");
  sub->add_option("scene", o->scene, "Built-in scene name or scene .json file")->required();
  sub->add_option("-o,--out", o->out, "Output folder: scene.json and mesh.f32")->required();
  sub->add_option("--screen", o->screen, "Screen width and height in pixels")->capture_default_str();
  sub->add_option("--map", o->map, "Shadow-map side in texels")->capture_default_str();
  sub->add_option("--filter", o->filter,
                  "Filter description (.shadow) whose light views to fit: its cascades, light samples");
  return [o]() -> int {
    if (o->screen == 0 || o->map == 0) throw std::invalid_argument("--screen and --map must be positive");
    const rt::Scene scene = rt::loadScene(o->scene);  // one located message for a bad name or file
    rt::SceneSettings settings;
    settings.map = o->map;
    settings.screen = o->screen;
    if (!o->filter.empty()) {
      const driver::Result r = driver::compileFile(o->filter);
      if (!r.log.empty()) fmt::print(stderr, "{}", r.log);
      if (!r.artifact) return 1;
      rt::checkLightType(r.artifact->manifest, scene.light.type, scene.name);
      rt::setFilterViews(settings, r.artifact->manifest.spec);
    }
    const rt::FrameSetup f = rt::fitFrame(scene, settings);

    size_t triangles = 0;
    const std::string mesh = meshBytes(scene, triangles);
    ordered_json j;
    j["format"] = "shadowc-scene-export";
    j["version"] = 1;
    j["scene"] = scene.name;
    j["screen"] = o->screen;
    j["map"] = o->map;
    j["mesh"] = {{"file", "mesh.f32"}, {"triangles", triangles}};
    j["camera"] = {{"view_proj", matrix(f.cameraViewProj)}};
    j["light"] = lightJson(scene, f);
    if (f.cascadeCount > 0) {
      ordered_json windows = ordered_json::array();
      for (int i = 0; i < f.cascadeCount; ++i) {
        const glm::dvec4& w = f.cascadeWindows[size_t(i)];
        windows.push_back(ordered_json::array({w.x, w.y, w.z, w.w}));
      }
      j["cascades"] = {{"count", f.cascadeCount},
                       {"grid", f.cascadeGrid},
                       {"first_split", f.frame.cascadeInfo[1]},
                       {"camera_depth_row", ordered_json::array({f.frame.cameraDepth[0], f.frame.cameraDepth[1],
                                                                 f.frame.cameraDepth[2], f.frame.cameraDepth[3]})},
                       {"windows", windows}};
    }
    ordered_json views = ordered_json::array();
    for (const rt::LightView& v : rt::lightViews(f))
      views.push_back({{"view_proj", matrix(v.viewProj)}, {"z_row", vec4(v.zRow)}, {"tile", {v.x0, v.y0, v.size}}});
    j["light_views"] = views;
    const std::filesystem::path dir = o->out;
    std::filesystem::create_directories(dir);
    rt::writeFileAtomically(dir / "mesh.f32", mesh);
    rt::writeFileAtomically(dir / "scene.json", j.dump(1) + "\n");
    fmt::print("export-scene: {} ({} triangles, {} light views, {}x{} screen, map {}) -> {}\n", scene.name, triangles,
               views.size(), o->screen, o->screen, o->map, (dir / "scene.json").string());
    return 0;
  };
}

}  // namespace shadowc::cli

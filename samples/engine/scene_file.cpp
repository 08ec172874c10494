#include "scene_file.h"

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace engine {
namespace {

using nlohmann::json;

template <size_t N>
std::array<float, N> floats(const json& a) {
  const std::vector<float> v = a.get<std::vector<float>>();
  if (v.size() != N) throw std::runtime_error("expected " + std::to_string(N) + " numbers");
  std::array<float, N> out{};
  std::copy(v.begin(), v.end(), out.begin());
  return out;
}

std::string readAll(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error(p.string() + ": cannot read (write it with `shadowc export-scene SCENE -o DIR`)");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The ShadowcFrame an engine fills from its light (include/shadowc/frame.h).
void fillFrame(const json& j, SceneFile& s) {
  shadowc::ShadowcFrame& f = s.frame;
  const json& l = j.at("light");
  const std::array<float, 16> view = floats<16>(l.at("view"));
  const std::string type = l.at("type");
  if (type == "spot")
    shadowc::setSpotLight(f, view.data(), l.at("tan_half_fov"), s.nearPlane, s.farPlane, l.at("width"), l.at("disk"));
  else if (type == "sun")
    shadowc::setSunLight(f, view.data(), l.at("half_extent"), s.nearPlane, s.farPlane,
                         l.at("angle_radians").get<double>());
  else if (type == "point")
    shadowc::setPointLight(f, view.data(), l.at("face_tan_half_fov"), s.nearPlane, s.farPlane, l.at("radius"));
  else
    throw std::runtime_error("light.type '" + type + "' is not spot, sun or point");
  shadowc::setMapSize(f, s.map);
  shadowc::setScreenSize(f, s.screen, s.screen);
  if (!j.contains("cascades")) return;
  const json& c = j["cascades"];
  const std::array<float, 4> row = floats<4>(c.at("camera_depth_row"));
  const int count = c.at("count");
  shadowc::setCascadeInfo(f, count, c.at("first_split").get<double>(), row.data());
  for (int i = 0; i < count; ++i) {
    const std::vector<double> w = c.at("windows").at(size_t(i)).get<std::vector<double>>();
    shadowc::setCascade(f, i, w.at(0), w.at(1), w.at(2), w.at(3), s.map, c.at("grid"));
  }
}

}  // namespace

SceneFile readSceneFile(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "scene.json";
  SceneFile s;
  try {
    const json j = json::parse(readAll(file));
    if (j.value("format", std::string()) != "shadowc-scene-export" || j.value("version", 0) != 1)
      throw std::runtime_error(file.string() + ": not a shadowc-scene-export version 1");
    s.name = j.at("scene");
    s.screen = j.at("screen");
    s.map = j.at("map");
    s.cameraViewProj = floats<16>(j.at("camera").at("view_proj"));
    s.lightPosition = floats<3>(j.at("light").at("position"));
    s.nearPlane = j.at("light").at("near");
    s.farPlane = j.at("light").at("far");
    for (const json& v : j.at("light_views")) {
      const std::vector<uint32_t> tile = v.at("tile").get<std::vector<uint32_t>>();
      s.views.push_back({floats<16>(v.at("view_proj")), floats<4>(v.at("z_row")), tile.at(0), tile.at(1), tile.at(2)});
    }
    fillFrame(j, s);
    const std::string mesh = readAll(dir / j.at("mesh").at("file").get<std::string>());
    const size_t triangles = j.at("mesh").at("triangles");
    if (mesh.size() != triangles * 18 * sizeof(float))
      throw std::runtime_error("the mesh holds " + std::to_string(mesh.size()) + " bytes, not " +
                               std::to_string(triangles) + " triangles");
    s.vertices.resize(triangles * 18);
    std::memcpy(s.vertices.data(), mesh.data(), mesh.size());
  } catch (const json::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  } catch (const std::out_of_range& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
  return s;
}

}  // namespace engine

#include "sweep/sweep_scene.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "runtime/images/atomic_file.h"
#include "shadowc_source_dir.h"

namespace shadowc::sweep {
namespace {

// A label as a file name: anything but letters, digits, '.', '-' and '_' becomes '_'.
std::string fileSlug(const std::string& label) {
  std::string s = label;
  for (char& c : s)
    if (!std::isalnum((unsigned char)c) && c != '.' && c != '-' && c != '_') c = '_';
  return s;
}

}  // namespace

ResolvedScene resolveScene(const SceneEntry& entry, const std::filesystem::path& outDir) {
  ResolvedScene r;
  r.nameOrPath = entry.scene;
  if (entry.lightSize) {
    const bool isFile = entry.scene.ends_with(".json");
    std::string text;
    std::filesystem::path baseDir;
    if (isFile) {
      std::ifstream in(entry.scene, std::ios::binary);
      if (!in) throw rt::SceneError(fmt::format("{}: error: cannot read the scene", entry.scene));
      std::ostringstream s;
      s << in.rdbuf();
      text = s.str();
      baseDir = std::filesystem::absolute(std::filesystem::path(entry.scene)).parent_path();
    } else {
      text = rt::builtinSceneJson(entry.scene);  // throws SceneError with suggestions
      baseDir = std::filesystem::path(SHADOWC_SOURCE_DIR) / "samples" / "scenes";
    }
    nlohmann::ordered_json j;
    try {
      j = nlohmann::ordered_json::parse(text);
    } catch (const std::exception& e) {
      throw rt::SceneError(fmt::format("{}: error: malformed JSON: {}", entry.scene, e.what()));
    }
    if (!j.is_object() || !j.contains("light") || !j["light"].is_object())
      throw rt::SceneError(fmt::format("{}: error: light: needed to replace its size", entry.scene));
    if (j["light"].value("type", std::string("spot")) == "sun")
      throw rt::SceneError(fmt::format("{}: error: light: a sun has an angle, not a size to replace", entry.scene));
    j["name"] = entry.label;
    // A point light's size is its diameter (the frame's lightWidth, 2 radius).
    if (j["light"].value("type", std::string("spot")) == "point")
      j["light"]["radius"] = 0.5 * *entry.lightSize;
    else
      j["light"]["size"] = *entry.lightSize;
    if (j.contains("objects") && j["objects"].is_array())
      for (auto& o : j["objects"])
        if (o.is_object() && o.contains("path") && o["path"].is_string() &&
            std::filesystem::path(o["path"].get<std::string>()).is_relative())
          o["path"] = (baseDir / o["path"].get<std::string>()).lexically_normal().string();
    const std::filesystem::path file = std::filesystem::absolute(outDir / "scenes" / (fileSlug(entry.label) + ".json"));
    rt::writeFileAtomically(file, j.dump(2) + "\n");
    r.nameOrPath = file.string();
  }
  const rt::Scene scene = rt::loadScene(r.nameOrPath);
  r.hash = scene.contentHash();
  r.lightWidth = scene.light.type == rt::LightType::Point ? 2.0f * scene.light.radius : scene.light.width;
  r.lightType = scene.light.type;
  r.name = scene.name;
  return r;
}

}  // namespace shadowc::sweep

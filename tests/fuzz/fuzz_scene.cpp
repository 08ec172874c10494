// libFuzzer target: the JSON scene loader (runtime/scene/scene_json.cpp, parseScene).
// Bad input must end in one SceneError; any other exception escapes and counts as a finding.
// Mesh paths resolve against an empty directory, so "mesh" objects only exercise the
// not-found path (loading real files is assimp's job, not this parser's).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "runtime/scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::filesystem::path emptyDir = [] {
    auto p = std::filesystem::temp_directory_path() / "shadowc-fuzz-scene-empty";
    std::filesystem::create_directories(p);
    return p;
  }();
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)shadowc::rt::parseScene(text, "fuzz.json", emptyDir);
  } catch (const shadowc::rt::SceneError&) {
  }
  return 0;
}

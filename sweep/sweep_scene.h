// A sweep's scene entry made runnable: a built-in name or .json path as it is, or — when the
// entry replaces the light's width — a derived scene written to DIR/scenes/<label>.json (the
// harness loads scenes by name or path only), with mesh paths made absolute.
#pragma once

#include <filesystem>
#include <string>

#include "runtime/scene/scene.h"
#include "sweep/sweep_spec.h"

namespace shadowc::sweep {

struct ResolvedScene {
  std::string nameOrPath;  // what rt::SceneSettings::scene gets
  std::string hash;        // rt::Scene::contentHash()
  float lightWidth = 0;
  rt::LightType lightType = rt::LightType::Spot;  // for the light check before any trace
  std::string name;                               // rt::Scene::name
};

// Throws rt::SceneError (the loader's message) for a bad scene.
ResolvedScene resolveScene(const SceneEntry& entry, const std::filesystem::path& outDir);

}  // namespace shadowc::sweep

// Shared by the accuracy, closed-form and end-to-end GPU tests: compile a filter description
// with the driver (once per process and label), run its passes through the run harness on
// lavapipe, either on a prepared built-in scene (rt::prepareScene + rt::runOnScene, compared with
// the Embree ground truth) or on crafted inputs (a depth map and G-buffer receivers placed
// exactly with an identity light view; rt::runPasses).
#pragma once

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <regex>
#include <string>
#include <vector>

#include "driver/driver.h"
#include "manifest/frame_uniforms.h"
#include "runtime/harness/run_harness.h"
#include "runtime/harness/scene_run.h"
#include "runtime/metrics/metrics.h"
#include "support/test_support.h"
#include "validation/stability/crafted_run.h"

namespace shadowc::test {

struct CompiledFilter {
  FilterSpec spec;
  CompiledPasses passes;  // manifest + SPIR-V in memory
};

inline std::string sampleSource(const std::string& name) {
  return readFile(sourceDir() / "samples" / "filters" / (name + ".shadow"));
}

// Compiles `source` once per process under `label` (and `counters`: the instrumented build,
// docs/manifest.md "Work counters", cached apart from the plain one). Fails the test (fatal)
// when it does not compile.
inline const CompiledFilter* compileFilterCached(const std::string& label, const std::string& source,
                                                 bool optimize = true, bool counters = false) {
  static std::map<std::string, std::unique_ptr<CompiledFilter>> cache;
  const std::string key = counters ? label + " (counters)" : label;
  auto it = cache.find(key);
  if (it != cache.end()) return it->second.get();
  driver::Options options;
  options.optimize = optimize;
  options.counters = counters;
  const driver::Result compiled = driver::compileSource(source, label + ".shadow", options);
  if (!compiled.artifact) {
    ADD_FAILURE() << label << ": " << compiled.log;
    return nullptr;
  }
  auto cf = std::make_unique<CompiledFilter>();
  cf->spec = compiled.artifact->spec;
  cf->passes = compiled.artifact->passes();
  return (cache[key] = std::move(cf)).get();
}

// A frame whose light view is the identity (world = light view), so crafted receivers have a
// known uv and depth: tanHalfFov 1, near 1, far 11.
inline constexpr float kNear = 1.0f, kFar = 11.0f;
inline ShadowcFrame identityFrame(uint32_t map, uint32_t w, uint32_t h, float lightWidth) {
  // The stability suite builds the same frame; one definition serves both.
  return validation::makeFrame(validation::LightFrame{1.0, kNear, kFar, lightWidth}, map, w, h);
}

// A receiver at shadow-map uv (u, v) and normalized depth d, facing the light centre (so a
// slope-scaled bias reduces to its constant).
struct Receiver {
  double u, v, d;
};
struct CraftedGBuffer {
  rt::HostImage position, normal;
};
inline CraftedGBuffer craftGBuffer(const std::vector<Receiver>& receivers, uint32_t w, uint32_t h) {
  std::vector<float> pos(size_t(w) * h * 4, 0.0f), nrm(size_t(w) * h * 4, 0.0f);
  for (size_t i = 0; i < receivers.size() && i < size_t(w) * h; ++i) {
    const Receiver& r = receivers[i];
    const double z = kNear + r.d * (kFar - kNear);
    const double x = (2 * r.u - 1) * z, y = (2 * r.v - 1) * z;
    const double len = std::sqrt(x * x + y * y + z * z);
    pos[i * 4 + 0] = float(x);
    pos[i * 4 + 1] = float(y);
    pos[i * 4 + 2] = float(z);
    pos[i * 4 + 3] = 1.0f;
    nrm[i * 4 + 0] = float(-x / len);
    nrm[i * 4 + 1] = float(-y / len);
    nrm[i * 4 + 2] = float(-z / len);
  }
  return {rt::HostImage::fromFloats(w, h, ImageFormat::RGBA32F, pos),
          rt::HostImage::fromFloats(w, h, ImageFormat::RGBA32F, nrm)};
}

// Crafted inputs for the run harness: an R32F depth map and a crafted G-buffer.
inline rt::RunInputs craftedInputs(uint32_t map, uint32_t w, uint32_t h, const ShadowcFrame& frame,
                                   const std::vector<float>& depth, const CraftedGBuffer& g) {
  return rt::RunInputs{frame,      map,     w, h, rt::HostImage::fromFloats(map, map, ImageFormat::R32F, depth),
                       g.position, g.normal};
}

// Reference cache next to the shadowc binary (the build dir), never the user's cache.
inline std::filesystem::path referenceCacheDir() {
  return std::filesystem::path(test::shadowcBinary()).parent_path() / "accuracy-reference-cache";
}

// One rasterized scene with its Embree reference, prepared once per process per key.
inline const rt::PreparedScene& sceneCase(rt::VulkanContext& ctx, const std::string& name, uint32_t map,
                                          uint32_t screen, int samples) {
  static std::map<std::string, std::shared_ptr<const rt::PreparedScene>> cache;
  const std::string key = fmt::format("{}/{}/{}/{}", name, map, screen, samples);
  auto it = cache.find(key);
  if (it != cache.end()) return *it->second;
  rt::SceneSettings settings;
  settings.scene = name;
  settings.screen = screen;
  settings.map = map;
  settings.referenceSamples = samples;
  settings.referenceCache = referenceCacheDir();
  return *(cache[key] = rt::prepareScene(ctx, settings));
}

// sceneCase prepared for the light views `passes` asks for (cascades, light samples:
// rt::prepareSceneForFilter, the cached reference shared); the cached scene itself when it has them.
inline std::shared_ptr<const rt::PreparedScene> sceneCaseFor(rt::VulkanContext& ctx, const std::string& name,
                                                             uint32_t map, uint32_t screen, int samples,
                                                             const CompiledPasses& passes) {
  const rt::PreparedScene& base = sceneCase(ctx, name, map, screen, samples);
  // The cache owns the base for the whole process: a non-owning pointer to it.
  return rt::prepareSceneForFilter(ctx, std::shared_ptr<const rt::PreparedScene>(&base, [](const rt::PreparedScene*) {}),
                                   passes.manifest.spec);
}

// Filter text `text` with its `keyword` setting line replaced by `keyword value`, or the setting
// added before the closing brace when the text has none.
inline std::string withSetting(const std::string& text, const std::string& keyword, const std::string& value) {
  const std::regex line("\n\\s*" + keyword + "\\s[^\n]*");
  if (std::regex_search(text, line)) return std::regex_replace(text, line, "\n    " + keyword + " " + value);
  const size_t close = text.rfind('}');
  return text.substr(0, close) + "    " + keyword + " " + value + "\n}\n";
}

// Sample `sample` with its bias line replaced by `bias` (appended when it has none): the bias tests
// compare a sample against the same filter with another bias.
inline std::string withBias(const std::string& sample, const std::string& bias) {
  return withSetting(sampleSource(sample), "bias", bias);
}

// Runs `source` (compiled once per label) on built-in `scene` and returns its metrics, failing the
// test when too few geometry pixels were compared or any value is non-finite or out of [0, 1].
inline rt::Metrics runOnBuiltinScene(rt::VulkanContext& ctx, const std::string& label, const std::string& source,
                                     const std::string& scene, uint32_t map, uint32_t screen, int samples) {
  const CompiledFilter* cf = compileFilterCached(label, source);
  EXPECT_NE(cf, nullptr) << label;
  if (!cf) return {};
  const auto sc = sceneCaseFor(ctx, scene, map, screen, samples, cf->passes);
  const rt::Metrics m = rt::runOnScene(ctx, cf->passes, *sc).metrics;
  EXPECT_GT(m.compared, screen * screen / 8) << "too few geometry pixels";
  EXPECT_EQ(m.nonFinite, 0u) << label;
  EXPECT_EQ(m.outOfRange, 0u) << label;
  return m;
}

// Largest |a - b| over two equally long arrays, with its index; NaN counts as infinite.
struct MaxError {
  double error = 0;
  size_t index = 0;
};
inline MaxError maxAbsError(const std::vector<double>& a, const std::vector<double>& b) {
  MaxError m;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    double e = std::fabs(a[i] - b[i]);
    if (std::isnan(e)) e = INFINITY;
    if (e > m.error) m = {e, i};
  }
  return m;
}

}  // namespace shadowc::test

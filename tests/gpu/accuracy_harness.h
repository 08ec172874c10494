// Shared by the accuracy, closed-form and end-to-end GPU tests: compile a filter description
// in process (once per process and label), run its passes on lavapipe either on a rasterized
// built-in scene or on crafted inputs (a depth map and G-buffer receivers placed exactly with
// an identity light view), and compare against the Embree ground truth.
#pragma once

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "emit/filter_emitter.h"
#include "emit/output_writer.h"
#include "manifest/frame_uniforms.h"
#include "runtime/executor/pass_executor.h"
#include "runtime/metrics/metrics.h"
#include "runtime/raster/rasterizer.h"
#include "runtime/reference/embree_reference.h"
#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"
#include "spec/load_filter.h"
#include "support/test_support.h"
#include "validation/stability/crafted_run.h"

namespace shadowc::test {

struct CompiledFilter {
  FilterSpec spec;
  Manifest manifest;
  std::filesystem::path dir;  // manifest.json, *.spv
};

inline std::string sampleSource(const std::string& name) {
  return readFile(sourceDir() / "samples" / "filters" / (name + ".shadow"));
}

// Compiles `source` once per process under `label` (the compiled files stay in a temp dir for
// the whole run). Fails the test (fatal) when it does not compile.
inline const CompiledFilter* compileFilterCached(const std::string& label, const std::string& source,
                                                 bool optimize = true) {
  static std::map<std::string, std::unique_ptr<CompiledFilter>> cache;
  auto it = cache.find(label);
  if (it != cache.end()) return it->second.get();
  const LoadResult loaded = loadFilterSource(source, label + ".shadow");
  if (!loaded.spec) {
    ADD_FAILURE() << label << ": " << formatDiagnostics(loaded);
    return nullptr;
  }
  EmitOptions options;
  options.optimize = optimize;
  const FilterEmitResult emitted = emitFilter(*loaded.spec, options);
  if (!emitted.ok) {
    ADD_FAILURE() << label << ": " << emitted.log;
    return nullptr;
  }
  auto cf = std::make_unique<CompiledFilter>();
  cf->spec = *loaded.spec;
  cf->manifest = emitted.manifest;
  cf->dir = freshTempDir("accuracy_" + label);
  const std::string err = writeFilesAtomically(cf->dir, emitted.files);
  if (!err.empty()) {
    ADD_FAILURE() << err;
    return nullptr;
  }
  return (cache[label] = std::move(cf)).get();
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

// An executor for a compiled filter with the three inputs uploaded by role.
inline std::unique_ptr<rt::PassExecutor> makeExecutor(rt::VulkanContext& ctx, const CompiledFilter& cf, uint32_t map,
                                                      uint32_t w, uint32_t h, const ShadowcFrame& frame,
                                                      const rt::HostImage& depth, const rt::HostImage& position,
                                                      const rt::HostImage& normal) {
  auto ex = std::make_unique<rt::PassExecutor>(ctx, cf.manifest, cf.dir, map, w, h);
  ex->setFrame(frame);
  auto uploadRole = [&](ImageRole role, const rt::HostImage& image) {
    const std::string name = ex->imageWithRole(role);
    if (!name.empty()) ex->upload(name, image);
  };
  uploadRole(ImageRole::InputDepth, depth);
  uploadRole(ImageRole::InputPosition, position);
  uploadRole(ImageRole::InputNormal, normal);
  return ex;
}

inline std::vector<float> downloadVisibility(rt::PassExecutor& ex) {
  return ex.download(ex.imageWithRole(ImageRole::OutputVisibility)).channel(0);
}

// Reference cache next to the shadowc binary (the build dir), never the user's cache.
inline std::filesystem::path referenceCacheDir() {
  return std::filesystem::path(SHADOWC_BINARY).parent_path() / "accuracy-reference-cache";
}

// One rasterized scene with its Embree reference, computed once per process per key.
struct SceneCase {
  rt::Scene scene;
  rt::FrameSetup setup;
  rt::RasterOutputs raster;
  std::vector<float> reference;
  std::vector<uint8_t> mask;
};
inline const SceneCase& sceneCase(rt::VulkanContext& ctx, const std::string& name, uint32_t map, uint32_t screen,
                                  int samples) {
  static std::map<std::string, std::unique_ptr<SceneCase>> cache;
  const std::string key = fmt::format("{}/{}/{}/{}", name, map, screen, samples);
  auto it = cache.find(key);
  if (it != cache.end()) return *it->second;
  auto sc = std::make_unique<SceneCase>();
  sc->scene = rt::loadScene(name);
  sc->setup = rt::setupFrame(sc->scene, map, screen, screen);
  sc->raster = rt::rasterize(ctx, sc->scene, sc->setup);
  const std::vector<float> positions = sc->raster.gbufferPosition.floats();
  const rt::ReferenceResult ref = rt::traceReference(sc->scene, positions, sc->raster.gbufferNormal.floats(), screen,
                                                     screen, samples, referenceCacheDir());
  sc->reference = ref.visibility;
  sc->mask = rt::geometryMask(positions);
  return *(cache[key] = std::move(sc));
}

// Runs every pass of the filter on the scene's rasterized inputs; the visibility image.
inline std::vector<float> runOnScene(rt::VulkanContext& ctx, const CompiledFilter& cf, const SceneCase& sc) {
  auto ex = makeExecutor(ctx, cf, sc.setup.mapSize, sc.setup.width, sc.setup.height, sc.setup.frame,
                         sc.raster.lightDepth, sc.raster.gbufferPosition, sc.raster.gbufferNormal);
  ex->run();
  return downloadVisibility(*ex);
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

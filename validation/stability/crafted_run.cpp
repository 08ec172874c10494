#include "validation/stability/crafted_run.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "emit/filter_emitter.h"
#include "emit/output_writer.h"
#include "runtime/executor/pass_executor.h"
#include "spec/load_filter.h"

namespace shadowc::validation {
namespace {

// Compiled filters live in one temp folder per process, removed at exit.
struct CompileCache {
  std::filesystem::path root;
  std::map<std::string, std::unique_ptr<CompiledFilter>> filters;
  std::mutex mutex;
  CompileCache() { root = std::filesystem::temp_directory_path() / fmt::format("shadowc-stability-{}", ::getpid()); }
  ~CompileCache() {
    std::error_code ec;
    std::filesystem::remove_all(root, ec);
  }
};

CompileCache& cache() {
  static CompileCache c;
  return c;
}

}  // namespace

float DepthMap::at(int x, int y) const {
  const int last = int(size) - 1;
  x = std::clamp(x, 0, last);
  y = std::clamp(y, 0, last);
  return depth[size_t(y) * size + size_t(x)];
}

DepthMap constantMap(uint32_t size, float d) { return {size, std::vector<float>(size_t(size) * size, d)}; }

FilterSpec specFromSource(const std::string& text, const std::string& name) {
  const LoadResult loaded = loadFilterSource(text, name + ".shadow");
  if (!loaded.spec)
    throw std::runtime_error(fmt::format("filter {} does not check:\n{}", name, formatDiagnostics(loaded)));
  return *loaded.spec;
}

const CompiledFilter& compileCached(const FilterSpec& spec) {
  CompileCache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  const std::string key = specToJson(spec).dump() + (spec.naiveUnguarded ? "|naive" : "");
  auto it = c.filters.find(key);
  if (it != c.filters.end()) return *it->second;
  const FilterEmitResult emitted = emitFilter(spec, EmitOptions{});
  if (!emitted.ok) throw std::runtime_error(fmt::format("filter {} does not compile:\n{}", spec.name, emitted.log));
  auto cf = std::make_unique<CompiledFilter>();
  cf->spec = spec;
  cf->manifest = emitted.manifest;
  cf->dir = c.root / fmt::format("{:03}_{}", c.filters.size(), spec.name);
  std::filesystem::create_directories(cf->dir);
  const std::string err = writeFilesAtomically(cf->dir, emitted.files);
  if (!err.empty()) throw std::runtime_error(err);
  return *(c.filters[key] = std::move(cf));
}

ShadowcFrame makeFrame(const LightFrame& light, uint32_t mapSize, uint32_t w, uint32_t h) {
  ShadowcFrame f{};
  for (int i = 0; i < 4; ++i) f.lightView[i * 5] = 1.0f;  // light view = world
  f.lightParams[0] = float(light.tanHalfFov);
  f.lightParams[1] = float(light.nearZ);
  f.lightParams[2] = float(light.farZ);
  f.lightParams[3] = float(light.lightWidth);
  f.mapInfo[0] = float(mapSize);
  f.mapInfo[1] = 1.0f / float(mapSize);
  f.screenInfo[0] = float(w);
  f.screenInfo[1] = float(h);
  f.screenInfo[2] = 1.0f / float(w);
  f.screenInfo[3] = 1.0f / float(h);
  return f;
}

std::array<double, 3> receiverPosition(const LightFrame& light, const Receiver& r) {
  const double z = light.nearZ + r.d * (light.farZ - light.nearZ);
  return {(2 * r.u - 1) * z * light.tanHalfFov, (2 * r.v - 1) * z * light.tanHalfFov, z};
}

double gpuReceiverDepth(const LightFrame& light, const Receiver& r) {
  const float z = float(receiverPosition(light, r)[2]);
  const float n = float(light.nearZ), f = float(light.farZ);
  return double((z - n) / (f - n));
}

CraftedResult runCrafted(rt::VulkanContext& ctx, const CompiledFilter& filter, const DepthMap& map,
                         const std::vector<Receiver>& receivers, const LightFrame& light,
                         const std::vector<std::string>& downloads) {
  const uint32_t count = uint32_t(std::max<size_t>(receivers.size(), 1));
  const uint32_t w = std::min<uint32_t>(count, 64), h = (count + w - 1) / w;
  std::vector<float> pos(size_t(w) * h * 4, 0.0f), nrm(size_t(w) * h * 4, 0.0f);
  for (size_t i = 0; i < receivers.size(); ++i) {
    const auto p = receiverPosition(light, receivers[i]);
    std::array<double, 3> n;
    if (receivers[i].normal) {
      n = *receivers[i].normal;
    } else {
      const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      n = {-p[0] / len, -p[1] / len, -p[2] / len};
    }
    for (int c = 0; c < 3; ++c) {
      pos[i * 4 + c] = float(p[c]);
      nrm[i * 4 + c] = float(n[c]);
    }
    pos[i * 4 + 3] = 1.0f;
  }
  rt::PassExecutor ex(ctx, filter.manifest, filter.dir, map.size, w, h);
  ex.setFrame(makeFrame(light, map.size, w, h));
  ex.upload(ex.imageWithRole(ImageRole::InputDepth),
            rt::HostImage::fromFloats(map.size, map.size, ImageFormat::R32F, map.depth));
  ex.upload(ex.imageWithRole(ImageRole::InputPosition), rt::HostImage::fromFloats(w, h, ImageFormat::RGBA32F, pos));
  ex.upload(ex.imageWithRole(ImageRole::InputNormal), rt::HostImage::fromFloats(w, h, ImageFormat::RGBA32F, nrm));
  ex.run();
  CraftedResult result;
  result.visibility = ex.download(ex.imageWithRole(ImageRole::OutputVisibility)).channel(0);
  result.visibility.resize(receivers.size());
  for (const std::string& name : downloads) result.images.emplace(name, ex.download(name));
  return result;
}

}  // namespace shadowc::validation

#include "validation/stability/crafted_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "driver/driver.h"
#include "runtime/harness/run_harness.h"

namespace shadowc::validation {
namespace {

struct CompileCache {
  std::map<std::string, std::unique_ptr<CompiledFilter>> filters;
  std::mutex mutex;
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
  driver::Options options;
  options.stopAfter = driver::Stage::Check;
  const driver::Result checked = driver::compileSource(text, name + ".shadow", options);
  if (!checked.spec) throw std::runtime_error(fmt::format("filter {} does not check:\n{}", name, checked.log));
  return *checked.spec;
}

const CompiledFilter& compileCached(const FilterSpec& spec, bool naiveDemo) {
  CompileCache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  const std::string key = specToJson(spec).dump() + (spec.naiveUnguarded ? "|naive" : "");
  auto it = c.filters.find(key);
  if (it != c.filters.end()) return *it->second;
  driver::Options options;
  options.checkBuiltSpec = !naiveDemo;
  const driver::Result compiled = driver::compileSpec(spec, options);
  if (!compiled.artifact)
    throw std::runtime_error(fmt::format("filter {} does not compile:\n{}", spec.name, compiled.log));
  auto cf = std::make_unique<CompiledFilter>();
  cf->spec = spec;
  cf->passes = compiled.artifact->passes();
  return *(c.filters[key] = std::move(cf));
}

LightFrame sunFrame(double halfExtent, double nearZ, double farZ, double angleDegrees) {
  LightFrame l;
  l.projection = Projection::Sun;
  l.halfExtent = halfExtent;
  l.nearZ = nearZ;
  l.farZ = farZ;
  l.lightWidth = sunPenumbraSlope(angleDegrees);
  return l;
}

LightFrame pointFrame(double tanHalf, double nearZ, double farZ, double radius) {
  LightFrame l;
  l.projection = Projection::Point;
  l.tanHalfFov = tanHalf;
  l.nearZ = nearZ;
  l.farZ = farZ;
  l.lightWidth = 2 * radius;
  return l;
}

ShadowcFrame makeFrame(const LightFrame& light, uint32_t mapSize, uint32_t w, uint32_t h) {
  ShadowcFrame f{};
  for (int i = 0; i < 4; ++i) f.lightView[i * 5] = 1.0f;  // light view = world
  // runtime/scene/frame_setup.cpp: lightParams.x is the sun's halfExtent, else tan(half fov).
  f.lightParams[0] = float(light.projection == Projection::Sun ? light.halfExtent : light.tanHalfFov);
  f.lightParams[1] = float(light.nearZ);
  f.lightParams[2] = float(light.farZ);
  f.lightParams[3] = float(light.lightWidth);
  f.lightShape[0] = light.projection == Projection::Point ? 4.0f : light.projection == Projection::Sun ? 3.0f : 0.0f;
  f.mapInfo[0] = float(mapSize);
  f.mapInfo[1] = 1.0f / float(mapSize);
  f.screenInfo[0] = float(w);
  f.screenInfo[1] = float(h);
  f.screenInfo[2] = 1.0f / float(w);
  f.screenInfo[3] = 1.0f / float(h);
  return f;
}

std::array<double, 3> receiverPosition(const LightFrame& light, const Receiver& r) {
  if (r.position) return *r.position;
  const double z = light.nearZ + r.d * (light.farZ - light.nearZ);
  switch (light.projection) {
    case Projection::Spot:
      return {(2 * r.u - 1) * z * light.tanHalfFov, (2 * r.v - 1) * z * light.tanHalfFov, z};
    case Projection::Sun:
      return {(2 * r.u - 1) * light.halfExtent, (2 * r.v - 1) * light.halfExtent, z};
    case Projection::Point:
      break;
  }
  throw std::runtime_error("a point light's receiver needs its position (cubeReceiver)");
}

std::array<double, 3> receiverNormal(const LightFrame& light, const Receiver& r) {
  if (r.normal) return *r.normal;
  if (light.projection == Projection::Sun) return {0.0, 0.0, -1.0};  // facing the sun
  const auto p = receiverPosition(light, r);
  const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  return {-p[0] / len, -p[1] / len, -p[2] / len};
}

double gpuReceiverDepth(const LightFrame& light, const Receiver& r) {
  const auto p = receiverPosition(light, r);
  float z = float(p[2]);
  if (light.projection == Projection::Point) {  // frame_cube.glsl: the face's z, from fp32 p
    const std::array<float, 3> pf = {float(p[0]), float(p[1]), float(p[2])};
    const std::array<float, 3> q = {std::fabs(pf[0]), std::fabs(pf[1]), std::fabs(pf[2])};
    const int a = (q[0] >= q[1] && q[0] >= q[2]) ? 0 : (q[1] >= q[2] ? 1 : 2);
    z = std::max(pf[a] < 0 ? -pf[a] : pf[a], 1e-20f);
  }
  const float n = float(light.nearZ), f = float(light.farZ);
  return double((z - n) / (f - n));
}

int cubeFace(const std::array<double, 3>& p) {
  const double q[3] = {std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])};
  const int a = (q[0] >= q[1] && q[0] >= q[2]) ? 0 : (q[1] >= q[2] ? 1 : 2);
  return 2 * a + (p[a] < 0 ? 1 : 0);
}

std::array<double, 3> cubeFaceCoords(int face, const std::array<double, 3>& p) {
  const int a = face / 2;
  const double s = (face % 2) ? -1.0 : 1.0;
  return {p[(a + 1) % 3], p[(a + 2) % 3], s * p[a]};
}

std::array<double, 3> cubeFromFace(int face, const std::array<double, 3>& q) {
  const int a = face / 2;
  const double s = (face % 2) ? -1.0 : 1.0;
  std::array<double, 3> p{};
  p[(a + 1) % 3] = q[0];
  p[(a + 2) % 3] = q[1];
  p[a] = s * q[2];
  return p;
}

Receiver cubeReceiver(const LightFrame& light, uint32_t mapSize, const std::array<double, 3>& p, int face) {
  const int f = face < 0 ? cubeFace(p) : face;
  const auto q = cubeFaceCoords(f, p);
  const double z = std::max(q[2], 1e-20);
  const double cell = double(mapSize / 3) / double(mapSize);
  Receiver r;
  r.u = (f % 3 + 0.5 + 0.5 * q[0] / (z * light.tanHalfFov)) * cell;
  r.v = (f / 3 + 0.5 + 0.5 * q[1] / (z * light.tanHalfFov)) * cell;
  r.d = (z - light.nearZ) / (light.farZ - light.nearZ);
  r.position = p;
  return r;
}

CraftedResult runCrafted(rt::VulkanContext& ctx, const CompiledFilter& filter, const DepthMap& map,
                         const std::vector<Receiver>& receivers, const LightFrame& light,
                         const std::vector<std::string>& downloads) {
  const uint32_t count = uint32_t(std::max<size_t>(receivers.size(), 1));
  const uint32_t w = std::min<uint32_t>(count, 64), h = (count + w - 1) / w;
  std::vector<float> pos(size_t(w) * h * 4, 0.0f), nrm(size_t(w) * h * 4, 0.0f);
  for (size_t i = 0; i < receivers.size(); ++i) {
    const auto p = receiverPosition(light, receivers[i]);
    const std::array<double, 3> n = receiverNormal(light, receivers[i]);
    for (int c = 0; c < 3; ++c) {
      pos[i * 4 + c] = float(p[c]);
      nrm[i * 4 + c] = float(n[c]);
    }
    pos[i * 4 + 3] = 1.0f;
  }
  rt::RunInputs inputs;
  inputs.frame = makeFrame(light, map.size, w, h);
  inputs.mapSize = map.size;
  inputs.width = w;
  inputs.height = h;
  inputs.lightDepth = rt::HostImage::fromFloats(map.size, map.size, ImageFormat::R32F, map.depth);
  inputs.position = rt::HostImage::fromFloats(w, h, ImageFormat::RGBA32F, pos);
  inputs.normal = rt::HostImage::fromFloats(w, h, ImageFormat::RGBA32F, nrm);
  rt::RunOptions options;
  options.downloads = downloads;
  rt::RunOutputs out = rt::runPasses(ctx, filter.passes, inputs, options);
  CraftedResult result;
  result.visibility = std::move(out.visibility);
  result.visibility.resize(receivers.size());
  result.images = std::move(out.images);
  return result;
}

}  // namespace shadowc::validation

#include "runtime/reference/embree_scene.h"

#include <fmt/format.h>

#include <cstring>
#include <limits>
#include <stdexcept>

namespace shadowc::rt {
namespace {

void throwIfError(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) throw std::runtime_error(fmt::format("Embree: {} failed (error {})", what, int(e)));
}

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene) : source_(scene) {
  device_ = rtcNewDevice(nullptr);
  if (device_ == nullptr) throw std::runtime_error("Embree: cannot create a device");
  scene_ = rtcNewScene(device_);
  // Robust traversal: watertight, so rays cannot leak through shared edges of a box or a mesh.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& m = scene.meshes[i];
    if (m.indices.size() < 3 || m.positions.empty()) continue;
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // New (Embree-owned) buffers: Embree pads them for its 16-byte vertex loads.
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), m.positions.size()));
    auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(uint32_t), m.indices.size() / 3));
    throwIfError(device_, "buffer allocation");
    std::memcpy(v, m.positions.data(), m.positions.size() * sizeof(glm::vec3));
    std::memcpy(idx, m.indices.data(), (m.indices.size() / 3) * 3 * sizeof(uint32_t));
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(scene_, g, i);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(scene_);
  throwIfError(device_, "scene build");
}

EmbreeScene::~EmbreeScene() {
  if (scene_ != nullptr) rtcReleaseScene(scene_);
  if (device_ != nullptr) rtcReleaseDevice(device_);
}

bool EmbreeScene::occluded(const glm::vec3& org, const glm::vec3& dir, float tfar) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay ray{};
  ray.org_x = org.x;
  ray.org_y = org.y;
  ray.org_z = org.z;
  ray.dir_x = dir.x;
  ray.dir_y = dir.y;
  ray.dir_z = dir.z;
  ray.tnear = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xFFFFFFFFu;
  rtcOccluded1(scene_, &ctx, &ray);
  return ray.tfar == -std::numeric_limits<float>::infinity();
}

RayHit EmbreeScene::intersect(const glm::vec3& org, const glm::vec3& dir) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh{};
  rh.ray.org_x = org.x;
  rh.ray.org_y = org.y;
  rh.ray.org_z = org.z;
  rh.ray.dir_x = dir.x;
  rh.ray.dir_y = dir.y;
  rh.ray.dir_z = dir.z;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &ctx, &rh);
  RayHit out;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return out;
  const Mesh& m = source_.meshes[rh.hit.geomID];
  const uint32_t* tri = &m.indices[3 * rh.hit.primID];
  const float u = rh.hit.u, v = rh.hit.v, w = 1.0f - u - v;
  out.hit = true;
  out.t = rh.ray.tfar;
  out.meshIndex = rh.hit.geomID;
  // Barycentric interpolation (what a rasterizer's varyings give), not org + t * dir.
  out.position = w * m.positions[tri[0]] + u * m.positions[tri[1]] + v * m.positions[tri[2]];
  const glm::vec3 n = w * m.normals[tri[0]] + u * m.normals[tri[1]] + v * m.normals[tri[2]];
  const float len = glm::length(n);
  out.normal = len > 0 ? n / len : glm::vec3(0, 1, 0);
  return out;
}

}  // namespace shadowc::rt

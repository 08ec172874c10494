// shadowc/frame.h — the ShadowcFrame uniform block (std140) that shadowc's lookups and shade pass
// read, and functions that fill it from an engine's light. Installed with shadowc
// (`cmake --install`, target shadowc::frame); header-only, the C++ standard library only, GLM
// overloads when <glm/glm.hpp> is on the include path (define SHADOWC_FRAME_NO_GLM to leave them
// out). This struct is the one definition of the layout: templates/frame_block.glsl declares the
// same members and tests/engine/frame_header_test.cpp checks every offset against glslang's
// reflection of that block. Conventions: docs/integration.md "The frame block", docs/scenes.md.
//
// A filter without cascades reads the first kFrameBaseSize bytes; a cascaded sun the whole
// struct. One buffer of sizeof(ShadowcFrame) serves both.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace shadowc {

inline constexpr int kMaxCascades = 8;

// lightShape.x: which light the frame describes.
enum class FrameLightShape : int { Rect = 0, Disk = 1, Point = 2, Sun = 3, Cube = 4 };

struct alignas(16) ShadowcFrame {
  float lightView[16];              // column-major world -> light view (+z from the light into the scene)
  float lightParams[4];             // x tanHalfFov (sun: halfExtent), y near, z far, w lightWidth
  float lightShape[4];              // x FrameLightShape: 0 rect, 1 disk, 2 point (size 0), 3 sun, 4 cube
  float mapInfo[4];                 // x map size (texels), y 1/size
  float screenInfo[4];              // width, height, 1/width, 1/height
  float cascadeInfo[4];             // x count, y camera depth where cascade 0 starts
  float cameraDepth[4];             // camera view depth of world p: dot(xyz, p) + w
  float cascades[kMaxCascades][4];  // light-view offset xy, atlas-frame halfExtent, far split
};
inline constexpr std::size_t kFrameBaseSize = 128;  // the block of every filter without cascades
static_assert(sizeof(ShadowcFrame) == 288);
static_assert(offsetof(ShadowcFrame, lightView) == 0);
static_assert(offsetof(ShadowcFrame, lightParams) == 64);
static_assert(offsetof(ShadowcFrame, lightShape) == 80);
static_assert(offsetof(ShadowcFrame, mapInfo) == 96);
static_assert(offsetof(ShadowcFrame, screenInfo) == 112);
static_assert(offsetof(ShadowcFrame, cascadeInfo) == kFrameBaseSize);
static_assert(offsetof(ShadowcFrame, cameraDepth) == 144);
static_assert(offsetof(ShadowcFrame, cascades) == 160);

// One member of the block: its GLSL name, std140 offset and size in bytes. The generated
// <filter>.h lists the members its filter reads with these.
struct FrameField {
  const char* name;
  std::size_t offset;
  std::size_t size;
};
inline constexpr FrameField kFrameFields[] = {
    {"lightView", offsetof(ShadowcFrame, lightView), sizeof(ShadowcFrame::lightView)},
    {"lightParams", offsetof(ShadowcFrame, lightParams), sizeof(ShadowcFrame::lightParams)},
    {"lightShape", offsetof(ShadowcFrame, lightShape), sizeof(ShadowcFrame::lightShape)},
    {"mapInfo", offsetof(ShadowcFrame, mapInfo), sizeof(ShadowcFrame::mapInfo)},
    {"screenInfo", offsetof(ShadowcFrame, screenInfo), sizeof(ShadowcFrame::screenInfo)},
    {"cascadeInfo", offsetof(ShadowcFrame, cascadeInfo), sizeof(ShadowcFrame::cascadeInfo)},
    {"cameraDepth", offsetof(ShadowcFrame, cameraDepth), sizeof(ShadowcFrame::cameraDepth)},
    {"cascades", offsetof(ShadowcFrame, cascades), sizeof(ShadowcFrame::cascades)},
};

namespace frame_detail {
inline void setView(ShadowcFrame& f, const float view[16]) {
  for (int i = 0; i < 16; ++i) f.lightView[i] = view[i];
}
inline void setParams(ShadowcFrame& f, float x, float nearPlane, float farPlane, float w, FrameLightShape shape) {
  f.lightParams[0] = x;
  f.lightParams[1] = nearPlane;
  f.lightParams[2] = farPlane;
  f.lightParams[3] = w;
  f.lightShape[0] = static_cast<float>(static_cast<int>(shape));
  f.lightShape[1] = f.lightShape[2] = f.lightShape[3] = 0.0f;
}
}  // namespace frame_detail

// A spot (area light, perspective map from its centre): `view` maps world to the light's view
// (origin at its centre, +z along its axis), the map is the perspective projection with
// uv = 0.5 + 0.5 xy / (z tanHalfFov) and stores d = (z - near) / (far - near); `width` is the
// rectangle's side or the disk's diameter in world units, 0 for a point-sized spot.
inline void setSpotLight(ShadowcFrame& f, const float view[16], float tanHalfFov, float nearPlane, float farPlane,
                         float width, bool disk) {
  frame_detail::setView(f, view);
  const FrameLightShape shape =
      width <= 0 ? FrameLightShape::Point : (disk ? FrameLightShape::Disk : FrameLightShape::Rect);
  frame_detail::setParams(f, tanHalfFov, nearPlane, farPlane, width, shape);
}

// A sun (orthographic map): uv = 0.5 + 0.5 xy / halfExtent, d linear in z between near and far;
// `angleRadians` is the sun's angular diameter, stored as its penumbra slope 2 tan(angle / 2).
inline void setSunLight(ShadowcFrame& f, const float view[16], float halfExtent, float nearPlane, float farPlane,
                        double angleRadians) {
  frame_detail::setView(f, view);
  frame_detail::setParams(f, halfExtent, nearPlane, farPlane, static_cast<float>(2.0 * std::tan(0.5 * angleRadians)),
                          FrameLightShape::Sun);
}

// An omnidirectional point light (a sphere of `radius`) rendered as six faces into a 3x3 atlas
// (docs/manifest.md "Point lights: the cube atlas"): `view` is the translation to the light's
// centre (world axes), each face a perspective map of tan(half fov) `faceTanHalfFov` (> 1 gives
// the guard band the kernels stay in), depth linear in the face's z.
inline void setPointLight(ShadowcFrame& f, const float view[16], float faceTanHalfFov, float nearPlane, float farPlane,
                          float radius) {
  frame_detail::setView(f, view);
  frame_detail::setParams(f, faceTanHalfFov, nearPlane, farPlane, 2.0f * radius, FrameLightShape::Cube);
}

inline void setMapSize(ShadowcFrame& f, std::uint32_t mapSize) {
  f.mapInfo[0] = static_cast<float>(mapSize);
  f.mapInfo[1] = 1.0f / static_cast<float>(mapSize);
  f.mapInfo[2] = f.mapInfo[3] = 0.0f;
}

inline void setScreenSize(ShadowcFrame& f, std::uint32_t width, std::uint32_t height) {
  f.screenInfo[0] = static_cast<float>(width);
  f.screenInfo[1] = static_cast<float>(height);
  f.screenInfo[2] = 1.0f / static_cast<float>(width);
  f.screenInfo[3] = 1.0f / static_cast<float>(height);
}

// Cascades of a sun (docs/scenes.md "Cascades"): `count` cascades, the first starting at camera
// depth `firstSplit`; `cameraDepthRow` gives a world point's camera depth as dot(xyz, p) + w (for
// a right-handed view looking down -z: minus the view matrix's third row).
inline void setCascadeInfo(ShadowcFrame& f, int count, double firstSplit, const float cameraDepthRow[4]) {
  f.cascadeInfo[0] = static_cast<float>(count);
  f.cascadeInfo[1] = static_cast<float>(firstSplit);
  f.cascadeInfo[2] = f.cascadeInfo[3] = 0.0f;
  for (int k = 0; k < 4; ++k) f.cameraDepth[k] = cameraDepthRow[k];
}

// Cascade i, rendered into tile (i mod grid, i div grid) of the square atlas of side mapSize
// (a multiple of grid) with the orthographic window centred at light-view (cx, cy), half-width h,
// covering camera depths up to farSplit. Stores the atlas frame of templates/frame_cascades.glsl:
// uv = 0.5 + 0.5 (p.xy + o) / H with H = h mapSize / T, T = mapSize / grid, o = h (2t + 1) - H - c.
inline void setCascade(ShadowcFrame& f, int i, double cx, double cy, double h, double farSplit, std::uint32_t mapSize,
                       int grid) {
  const double tile = static_cast<double>(mapSize / static_cast<std::uint32_t>(grid));
  const double H = h * static_cast<double>(mapSize) / tile;
  const double tx = static_cast<double>(i % grid), ty = static_cast<double>(i / grid);
  f.cascades[i][0] = static_cast<float>(2.0 * h * (tx + 0.5) - H - cx);
  f.cascades[i][1] = static_cast<float>(2.0 * h * (ty + 0.5) - H - cy);
  f.cascades[i][2] = static_cast<float>(H);
  f.cascades[i][3] = static_cast<float>(farSplit);
}

}  // namespace shadowc

#if !defined(SHADOWC_FRAME_NO_GLM) && defined(__has_include)
#if __has_include(<glm/glm.hpp>)
#include <glm/glm.hpp>
namespace shadowc {
// The same functions taking GLM's column-major matrices.
inline void setSpotLight(ShadowcFrame& f, const glm::mat4& view, float tanHalfFov, float nearPlane, float farPlane,
                         float width, bool disk) {
  setSpotLight(f, &view[0][0], tanHalfFov, nearPlane, farPlane, width, disk);
}
inline void setSunLight(ShadowcFrame& f, const glm::mat4& view, float halfExtent, float nearPlane, float farPlane,
                        double angleRadians) {
  setSunLight(f, &view[0][0], halfExtent, nearPlane, farPlane, angleRadians);
}
inline void setPointLight(ShadowcFrame& f, const glm::mat4& view, float faceTanHalfFov, float nearPlane, float farPlane,
                          float radius) {
  setPointLight(f, &view[0][0], faceTanHalfFov, nearPlane, farPlane, radius);
}
inline void setCascadeInfo(ShadowcFrame& f, int count, double firstSplit, const glm::vec4& cameraDepthRow) {
  setCascadeInfo(f, count, firstSplit, &cameraDepthRow[0]);
}
// The camera-depth row of a right-handed view matrix looking down -z (glm::lookAtRH).
inline glm::vec4 cameraDepthRow(const glm::mat4& cameraView) {
  return -glm::vec4(cameraView[0][2], cameraView[1][2], cameraView[2][2], cameraView[3][2]);
}
}  // namespace shadowc
#endif
#endif

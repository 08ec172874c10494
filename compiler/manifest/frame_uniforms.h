// ShadowcFrame: the C++ mirror of templates/frame_block.glsl (std140). The runtime fills it; the
// layout is asserted here so that a change to one side without the other fails to build.
// The cascade fields at the end are declared in the GLSL block only for a cascaded sun
// (SHADOWC_CASCADES); every other filter's block is the first 128 bytes of this struct, so one
// buffer of sizeof(ShadowcFrame) serves both (runtime/scene/cascade_setup.cpp fills the tail).
#pragma once

#include <cstddef>

namespace shadowc {

inline constexpr int kMaxCascades = 8;

struct alignas(16) ShadowcFrame {
  float lightView[16];              // column-major world -> light view
  float lightParams[4];             // tanHalfFov, near, far, lightWidth
  float lightShape[4];              // 0 rect / 1 disk / 2 point
  float mapInfo[4];                 // size, 1/size
  float screenInfo[4];              // width, height, 1/width, 1/height
  float cascadeInfo[4];             // count, camera depth where cascade 0 starts
  float cameraDepth[4];             // camera view depth of world p: dot(xyz, p) + w
  float cascades[kMaxCascades][4];  // light-view offset xy, atlas-frame halfExtent, far split
};
static_assert(sizeof(ShadowcFrame) == 288);
static_assert(offsetof(ShadowcFrame, lightParams) == 64);
static_assert(offsetof(ShadowcFrame, screenInfo) == 112);
static_assert(offsetof(ShadowcFrame, cascadeInfo) == 128);
static_assert(offsetof(ShadowcFrame, cascades) == 160);

}  // namespace shadowc

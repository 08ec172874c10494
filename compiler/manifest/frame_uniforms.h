// ShadowcFrame: the C++ mirror of templates/frame.glsl (std140). The runtime fills it; the
// layout is asserted here so that a change to one side without the other fails to build.
#pragma once

#include <cstddef>

namespace shadowc {

struct alignas(16) ShadowcFrame {
  float lightView[16];    // column-major world -> light view
  float lightParams[4];   // tanHalfFov, near, far, lightWidth
  float lightShape[4];    // 0 rect / 1 disk / 2 point
  float mapInfo[4];       // size, 1/size
  float screenInfo[4];    // width, height, 1/width, 1/height
};
static_assert(sizeof(ShadowcFrame) == 128);
static_assert(offsetof(ShadowcFrame, lightParams) == 64);
static_assert(offsetof(ShadowcFrame, screenInfo) == 112);

}  // namespace shadowc

#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// sat_rows.comp — first half of the summed-area table (vssm-yang2010 L2-L4 and sec. 6.4):
// one invocation per row (dispatch mode "rows": gl_GlobalInvocationID.x = y) runs a serial
// prefix sum along x of the encoded moments, for every layer. Storage conventions and the
// inclusive box-sum rule are in sat_common.glsl; uint additions wrap mod 2^32 on purpose.
#ifndef SHADOWC_LAYERS
#define SHADOWC_LAYERS 1
#endif
#ifndef SHADOWC_MOMENTS_FORMAT
#define SHADOWC_MOMENTS_FORMAT rg32f
#endif
#include "passes/sat_common.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(set = 0, binding = 0, SHADOWC_MOMENTS_FORMAT) readonly uniform image2DArray momentsIn;
layout(set = 0, binding = 1, SHADOWC_SAT_FORMAT) writeonly uniform SHADOWC_SAT_IMAGE satOut;

void main() {
  const ivec2 size = imageSize(momentsIn).xy;
  const int y = int(gl_GlobalInvocationID.x);
  if (y >= size.y) return;
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
    SHADOWC_SAT_VALUE sum = SHADOWC_SAT_VALUE(0);
    for (int x = 0; x < size.x; ++x) {
      sum += shadowc_satEncode(imageLoad(momentsIn, ivec3(x, y, layer)));
      imageStore(satOut, ivec3(x, y, layer), sum);
    }
  }
}

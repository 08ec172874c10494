#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// sat_columns.comp — second half of the summed-area table: one invocation per column
// (dispatch mode "columns": gl_GlobalInvocationID.x = x) adds the row sums down y, in place.
// Each invocation owns its column, so no barrier is needed. The serial (CPU) form; an int32 table
// also has the GPU form sat_columns_parallel.comp. See sat_common.glsl.
#ifndef SHADOWC_LAYERS
#define SHADOWC_LAYERS 1
#endif
#include "passes/sat_common.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(set = 0, binding = 0, SHADOWC_SAT_FORMAT) uniform SHADOWC_SAT_IMAGE sat;

void main() {
  const ivec2 size = imageSize(sat).xy;
  const int x = int(gl_GlobalInvocationID.x);
  if (x >= size.x) return;
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
    SHADOWC_SAT_VALUE sum = SHADOWC_SAT_VALUE(0);
    int y = 0;
    for (; y + SHADOWC_SAT_BATCH <= size.y; y += SHADOWC_SAT_BATCH) {
      SHADOWC_SAT_VALUE v[SHADOWC_SAT_BATCH];  // read before any is written (sat_common.glsl)
      for (int i = 0; i < SHADOWC_SAT_BATCH; ++i) v[i] = imageLoad(sat, ivec3(x, y + i, layer));
      for (int i = 0; i < SHADOWC_SAT_BATCH; ++i) {
        sum += v[i];
        imageStore(sat, ivec3(x, y + i, layer), sum);
      }
    }
    for (; y < size.y; ++y) {  // the rest, fewer than a batch
      sum += imageLoad(sat, ivec3(x, y, layer));
      imageStore(sat, ivec3(x, y, layer), sum);
    }
  }
}

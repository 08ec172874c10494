#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// sat_columns_parallel.comp — the GPU form of sat_columns.comp (same binding, same table bit for
// bit): one workgroup per column (dispatch mode "column_groups": gl_WorkGroupID.x = x) of
// SHADOWC_SAT_TILE_CHUNKS invocations adds the row sums down y, in place, in the blocked order
// (sat_common.glsl, sat_tiles.glsl). Every texel of a tile is read before the tile's barriers and
// written after them, and a column belongs to one workgroup, so in place is safe.
#ifndef SHADOWC_LAYERS
#define SHADOWC_LAYERS 1
#endif
#include "passes/sat_tiles.glsl"

layout(local_size_x = SHADOWC_SAT_TILE_CHUNKS, local_size_y = 1, local_size_z = 1) in;
layout(set = 0, binding = 0, SHADOWC_SAT_FORMAT) uniform SHADOWC_SAT_IMAGE sat;

void main() {
  const ivec2 size = imageSize(sat).xy;
  const int x = int(gl_WorkGroupID.x);  // the same in the whole workgroup: the barriers stay uniform
  if (x >= size.x) return;
  const uint i = gl_LocalInvocationID.x;
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
    SHADOWC_SAT_VALUE tileCarry = SHADOWC_SAT_VALUE(0);
    for (int tile = 0; tile < size.y; tile += SHADOWC_SAT_TILE_CHUNKS * SHADOWC_SAT_BATCH) {
      const int y = tile + int(i) * SHADOWC_SAT_BATCH;
      const int n = clamp(size.y - y, 0, SHADOWC_SAT_BATCH);
      SHADOWC_SAT_VALUE local[SHADOWC_SAT_BATCH];
      precise SHADOWC_SAT_VALUE run = SHADOWC_SAT_VALUE(0);
      for (int k = 0; k < SHADOWC_SAT_BATCH; ++k) {
        if (k < n) run += imageLoad(sat, ivec3(x, y + k, layer));
        local[k] = run;
      }
      const SHADOWC_SAT_VALUE carry = shadowc_satTileCarry(i, run, tileCarry);
      for (int k = 0; k < n; ++k) {
        precise SHADOWC_SAT_VALUE s = carry + local[k];
        imageStore(sat, ivec3(x, y + k, layer), s);
      }
    }
  }
}

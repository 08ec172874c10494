#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// sat_rows_parallel.comp — the GPU form of sat_rows.comp (same bindings, same table bit for bit):
// one workgroup per row (dispatch mode "row_groups": gl_WorkGroupID.x = y) of
// SHADOWC_SAT_TILE_CHUNKS invocations, each adding up a chunk of SHADOWC_SAT_BATCH texels, the
// carries folded in shared memory (sat_tiles.glsl) in the blocked order of sat_common.glsl
// (Nehab et al. 2011). Fused (SHADOWC_SAT_FROM_DEPTH 1) it warps the light depth itself, as
// sat_rows.comp does; each layer reads the depth again (the parallel form is not bound by reads).
#ifndef SHADOWC_LAYERS
#define SHADOWC_LAYERS 1
#endif
#ifndef SHADOWC_MOMENTS_FORMAT
#define SHADOWC_MOMENTS_FORMAT rg32f
#endif
#ifndef SHADOWC_SAT_FROM_DEPTH
#define SHADOWC_SAT_FROM_DEPTH 0
#endif
#ifndef SHADOWC_SPLITS_FROM_IMAGE
#define SHADOWC_SPLITS_FROM_IMAGE 0
#endif
#include "passes/sat_tiles.glsl"

layout(local_size_x = SHADOWC_SAT_TILE_CHUNKS, local_size_y = 1, local_size_z = 1) in;
#if SHADOWC_SAT_FROM_DEPTH
layout(set = 0, binding = 0) uniform sampler2D shadowDepth;
#if SHADOWC_SPLITS_FROM_IMAGE
layout(set = 0, binding = 2) uniform sampler2D splitsImage;  // r32f, texel (i, 0) = split i (lloyd.comp)
#endif
#include "passes/layer_moments.glsl"
#else
layout(set = 0, binding = 0, SHADOWC_MOMENTS_FORMAT) readonly uniform image2DArray momentsIn;
#endif
layout(set = 0, binding = 1, SHADOWC_SAT_FORMAT) writeonly uniform SHADOWC_SAT_IMAGE satOut;

SHADOWC_SAT_VALUE encodedTexel(int x, int y, int layer) {
#if SHADOWC_SAT_FROM_DEPTH
  return shadowc_satEncode(shadowc_layerMoments(texelFetch(shadowDepth, ivec2(x, y), 0).r, layer));
#else
  return shadowc_satEncode(imageLoad(momentsIn, ivec3(x, y, layer)));
#endif
}

void main() {
#if SHADOWC_SAT_FROM_DEPTH
  const ivec2 size = textureSize(shadowDepth, 0);
#else
  const ivec2 size = imageSize(momentsIn).xy;
#endif
  const int y = int(gl_WorkGroupID.x);  // the same in the whole workgroup: the barriers stay uniform
  if (y >= size.y) return;
  const uint i = gl_LocalInvocationID.x;
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
    SHADOWC_SAT_VALUE tileCarry = SHADOWC_SAT_VALUE(0);
    for (int tile = 0; tile < size.x; tile += SHADOWC_SAT_TILE_CHUNKS * SHADOWC_SAT_BATCH) {
      const int x = tile + int(i) * SHADOWC_SAT_BATCH;
      const int n = clamp(size.x - x, 0, SHADOWC_SAT_BATCH);
      SHADOWC_SAT_VALUE local[SHADOWC_SAT_BATCH];
      precise SHADOWC_SAT_VALUE run = SHADOWC_SAT_VALUE(0);
      for (int k = 0; k < SHADOWC_SAT_BATCH; ++k) {
        if (k < n) run += encodedTexel(x + k, y, layer);
        local[k] = run;
      }
      const SHADOWC_SAT_VALUE carry = shadowc_satTileCarry(i, run, tileCarry);
      for (int k = 0; k < n; ++k) {
        precise SHADOWC_SAT_VALUE s = carry + local[k];
        imageStore(satOut, ivec3(x + k, y, layer), s);
      }
    }
  }
}

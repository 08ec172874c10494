#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// sat_rows.comp — first half of the summed-area table (vssm-yang2010 L2-L4 and sec. 6.4):
// one invocation per row (dispatch mode "rows": gl_GlobalInvocationID.x = y) runs a serial
// prefix sum along x of the encoded moments, for every layer, in the blocked order. The serial
// (CPU) form; sat_rows_parallel.comp is the GPU form. Storage conventions, the order and the
// inclusive box-sum rule are in sat_common.glsl; uint additions wrap mod 2^32 on purpose.
// SHADOWC_SAT_FROM_DEPTH 1 (fused): the scan reads the light depth and warps it itself
// (layer_moments.glsl), so no moments pass and no moments image exist: one texel read and one
// texel write per texel and layer, against two of each for moments.comp followed by this pass.
// The values summed are bit for bit what the moments pass would store: a SAT's moments image is
// always fp32 (plan/image_formats.cpp), so the table is identical to the unfused one.
// SHADOWC_SAT_FROM_DEPTH 0: the scan reads the moments image (after a blur, or beside mips).
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
#include "passes/sat_common.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
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

void main() {
#if SHADOWC_SAT_FROM_DEPTH
  const ivec2 size = textureSize(shadowDepth, 0);
#else
  const ivec2 size = imageSize(momentsIn).xy;
#endif
  const int y = int(gl_GlobalInvocationID.x);
  if (y >= size.y) return;
  // The blocked order (sat_common.glsl): a chunk is one batch.
#if SHADOWC_SAT_FROM_DEPTH
  // x outer, layers inner: each depth texel is read once for all layers.
  SHADOWC_SAT_VALUE tileCarry[SHADOWC_LAYERS], groupCarry[SHADOWC_LAYERS], chunkCarry[SHADOWC_LAYERS];
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer)
    tileCarry[layer] = groupCarry[layer] = chunkCarry[layer] = SHADOWC_SAT_VALUE(0);
  int x = 0, chunk = 0;
  for (; x + SHADOWC_SAT_BATCH <= size.x; x += SHADOWC_SAT_BATCH, ++chunk) {
    float d[SHADOWC_SAT_BATCH];  // read before any is written (sat_common.glsl)
    for (int i = 0; i < SHADOWC_SAT_BATCH; ++i) d[i] = texelFetch(shadowDepth, ivec2(x + i, y), 0).r;
    SHADOWC_SAT_VALUE base[SHADOWC_LAYERS], local[SHADOWC_LAYERS];
    for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
      precise SHADOWC_SAT_VALUE b = (tileCarry[layer] + groupCarry[layer]) + chunkCarry[layer];
      base[layer] = b;
      local[layer] = SHADOWC_SAT_VALUE(0);
    }
    for (int i = 0; i < SHADOWC_SAT_BATCH; ++i)
      for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
        precise SHADOWC_SAT_VALUE l = local[layer] + shadowc_satEncode(shadowc_layerMoments(d[i], layer));
        local[layer] = l;
        precise SHADOWC_SAT_VALUE s = base[layer] + l;
        imageStore(satOut, ivec3(x + i, y, layer), s);
      }
    for (int layer = 0; layer < SHADOWC_LAYERS; ++layer)
      shadowc_satCarry(chunk, local[layer], tileCarry[layer], groupCarry[layer], chunkCarry[layer]);
  }
  // The rest, fewer than a batch: the last chunk, one texel at a time.
  SHADOWC_SAT_VALUE base[SHADOWC_LAYERS], local[SHADOWC_LAYERS];
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
    precise SHADOWC_SAT_VALUE b = (tileCarry[layer] + groupCarry[layer]) + chunkCarry[layer];
    base[layer] = b;
    local[layer] = SHADOWC_SAT_VALUE(0);
  }
  for (; x < size.x; ++x) {
    const float d = texelFetch(shadowDepth, ivec2(x, y), 0).r;
    for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
      precise SHADOWC_SAT_VALUE l = local[layer] + shadowc_satEncode(shadowc_layerMoments(d, layer));
      local[layer] = l;
      precise SHADOWC_SAT_VALUE s = base[layer] + l;
      imageStore(satOut, ivec3(x, y, layer), s);
    }
  }
#else
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
    SHADOWC_SAT_VALUE tileCarry = SHADOWC_SAT_VALUE(0), groupCarry = tileCarry, chunkCarry = tileCarry;
    int x = 0, chunk = 0;
    for (; x + SHADOWC_SAT_BATCH <= size.x; x += SHADOWC_SAT_BATCH, ++chunk) {
      vec4 m[SHADOWC_SAT_BATCH];  // read before any is written (sat_common.glsl)
      for (int i = 0; i < SHADOWC_SAT_BATCH; ++i) m[i] = imageLoad(momentsIn, ivec3(x + i, y, layer));
      precise SHADOWC_SAT_VALUE base = (tileCarry + groupCarry) + chunkCarry;
      precise SHADOWC_SAT_VALUE local = SHADOWC_SAT_VALUE(0);
      for (int i = 0; i < SHADOWC_SAT_BATCH; ++i) {
        local += shadowc_satEncode(m[i]);
        precise SHADOWC_SAT_VALUE s = base + local;
        imageStore(satOut, ivec3(x + i, y, layer), s);
      }
      shadowc_satCarry(chunk, local, tileCarry, groupCarry, chunkCarry);
    }
    // The rest, fewer than a batch: the last chunk, one texel at a time.
    precise SHADOWC_SAT_VALUE base = (tileCarry + groupCarry) + chunkCarry;
    precise SHADOWC_SAT_VALUE local = SHADOWC_SAT_VALUE(0);
    for (; x < size.x; ++x) {
      local += shadowc_satEncode(imageLoad(momentsIn, ivec3(x, y, layer)));
      precise SHADOWC_SAT_VALUE s = base + local;
      imageStore(satOut, ivec3(x, y, layer), s);
    }
  }
#endif
}

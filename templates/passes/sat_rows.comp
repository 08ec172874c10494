#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// sat_rows.comp — first half of the summed-area table (vssm-yang2010 L2-L4 and sec. 6.4):
// one invocation per row (dispatch mode "rows": gl_GlobalInvocationID.x = y) runs a serial
// prefix sum along x of the encoded moments, for every layer: the serial (CPU) form; an int32
// table also has the GPU form sat_rows_parallel.comp (sat_common.glsl "Two forms"). Storage
// conventions and the inclusive box-sum rule are in sat_common.glsl; uint additions wrap mod 2^32
// on purpose.
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
#if SHADOWC_SAT_FROM_DEPTH
  // x outer, layers inner: each depth texel is read once for all layers.
  SHADOWC_SAT_VALUE sum[SHADOWC_LAYERS];
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) sum[layer] = SHADOWC_SAT_VALUE(0);
  int x = 0;
  for (; x + SHADOWC_SAT_BATCH <= size.x; x += SHADOWC_SAT_BATCH) {
    float d[SHADOWC_SAT_BATCH];  // read before any is written (sat_common.glsl)
    for (int i = 0; i < SHADOWC_SAT_BATCH; ++i) d[i] = texelFetch(shadowDepth, ivec2(x + i, y), 0).r;
    for (int i = 0; i < SHADOWC_SAT_BATCH; ++i)
      for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
        sum[layer] += shadowc_satEncode(shadowc_layerMoments(d[i], layer));
        imageStore(satOut, ivec3(x + i, y, layer), sum[layer]);
      }
  }
  for (; x < size.x; ++x) {  // the rest, fewer than a batch
    const float d = texelFetch(shadowDepth, ivec2(x, y), 0).r;
    for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
      sum[layer] += shadowc_satEncode(shadowc_layerMoments(d, layer));
      imageStore(satOut, ivec3(x, y, layer), sum[layer]);
    }
  }
#else
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
    SHADOWC_SAT_VALUE sum = SHADOWC_SAT_VALUE(0);
    int x = 0;
    for (; x + SHADOWC_SAT_BATCH <= size.x; x += SHADOWC_SAT_BATCH) {
      vec4 m[SHADOWC_SAT_BATCH];  // read before any is written (sat_common.glsl)
      for (int i = 0; i < SHADOWC_SAT_BATCH; ++i) m[i] = imageLoad(momentsIn, ivec3(x + i, y, layer));
      for (int i = 0; i < SHADOWC_SAT_BATCH; ++i) {
        sum += shadowc_satEncode(m[i]);
        imageStore(satOut, ivec3(x + i, y, layer), sum);
      }
    }
    for (; x < size.x; ++x) {  // the rest, fewer than a batch
      sum += shadowc_satEncode(imageLoad(momentsIn, ivec3(x, y, layer)));
      imageStore(satOut, ivec3(x, y, layer), sum);
    }
  }
#endif
}

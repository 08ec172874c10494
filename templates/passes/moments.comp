#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// moments.comp — shadow depth -> warped moments, one invocation per texel, every layer.
// Moments per warp: see moments_warp.glsl (vsm-tutorial; lauritzen2008 sec. 3.2 for EVSM).
// Layered VSM (lauritzen2008 sec. 3-4): layer i stores the moments of d remapped into
// [split_i - overlap, split_{i+1} + overlap]. Splits are folded constants (uniform or
// explicit placement), or read from the `splits` image (Lloyd placement, sec. 4.1) when
// SHADOWC_SPLITS_FROM_IMAGE is 1.
#ifndef SHADOWC_LAYERS
#define SHADOWC_LAYERS 1
#endif
#ifndef SHADOWC_SPLITS
#define SHADOWC_SPLITS float[](0.0, 1.0)
#endif
#ifndef SHADOWC_OVERLAP
#define SHADOWC_OVERLAP 0.0
#endif
#ifndef SHADOWC_MOMENTS_FORMAT
#define SHADOWC_MOMENTS_FORMAT rg32f
#endif
#ifndef SHADOWC_SPLITS_FROM_IMAGE
#define SHADOWC_SPLITS_FROM_IMAGE 0
#endif
#include "passes/moments_warp.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(set = 0, binding = 0) uniform sampler2D shadowDepth;
layout(set = 0, binding = 1, SHADOWC_MOMENTS_FORMAT) writeonly uniform image2DArray momentsOut;
#if SHADOWC_SPLITS_FROM_IMAGE
layout(set = 0, binding = 2) uniform sampler2D splitsImage;  // r32f, texel (i, 0) = split i (lloyd.comp)
#endif

void main() {
  const ivec2 size = textureSize(shadowDepth, 0);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  const float d = texelFetch(shadowDepth, p, 0).r;
#if SHADOWC_LAYERS == 1
  imageStore(momentsOut, ivec3(p, 0), shadowc_warpMoments(d));
#else
#if !SHADOWC_SPLITS_FROM_IMAGE
  const float splits[SHADOWC_LAYERS + 1] = SHADOWC_SPLITS;
#endif
  for (int i = 0; i < SHADOWC_LAYERS; ++i) {
#if SHADOWC_SPLITS_FROM_IMAGE
    const float lo = texelFetch(splitsImage, ivec2(i, 0), 0).r;
    const float hi = texelFetch(splitsImage, ivec2(i + 1, 0), 0).r;
#else
    const float lo = splits[i], hi = splits[i + 1];
#endif
    const float t = shadowc_layerRemap(d, lo - SHADOWC_OVERLAP, hi + SHADOWC_OVERLAP);
    imageStore(momentsOut, ivec3(p, i), shadowc_warpMoments(t));
  }
#endif
}

#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// moments.comp — shadow depth -> warped moments, one invocation per texel, every layer.
// Moments per warp: moments_warp.glsl (vsm-tutorial; lauritzen2008 sec. 3.2 for EVSM); layers
// and splits: layer_moments.glsl. Planned only when something besides a summed-area table reads
// the moments (blur, mips, a lookup without SAT); otherwise sat_rows.comp warps the depth itself.
#ifndef SHADOWC_MOMENTS_FORMAT
#define SHADOWC_MOMENTS_FORMAT rg32f
#endif
#ifndef SHADOWC_SPLITS_FROM_IMAGE
#define SHADOWC_SPLITS_FROM_IMAGE 0
#endif

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(set = 0, binding = 0) uniform sampler2D shadowDepth;
layout(set = 0, binding = 1, SHADOWC_MOMENTS_FORMAT) writeonly uniform image2DArray momentsOut;
#if SHADOWC_SPLITS_FROM_IMAGE
layout(set = 0, binding = 2) uniform sampler2D splitsImage;  // r32f, texel (i, 0) = split i (lloyd.comp)
#endif
#include "passes/layer_moments.glsl"

void main() {
  const ivec2 size = textureSize(shadowDepth, 0);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  const float d = texelFetch(shadowDepth, p, 0).r;
  for (int i = 0; i < SHADOWC_LAYERS; ++i) imageStore(momentsOut, ivec3(p, i), shadowc_layerMoments(d, i));
}

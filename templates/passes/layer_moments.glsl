// layer_moments.glsl — the moments one light-depth texel stores in layer `layer`, shared by the
// moments pass (moments.comp) and the fused SAT row pass (sat_rows.comp with
// SHADOWC_SAT_FROM_DEPTH, which warps the depth inside its scan: no moments image at all).
// Layered VSM (lauritzen2008 sec. 3-4): layer i stores the moments of d remapped into
// [split_i - overlap, split_{i+1} + overlap]. Splits are folded constants (uniform or explicit
// placement), or read from `splitsImage` (Lloyd placement, sec. 4.1; the including pass declares
// it) when SHADOWC_SPLITS_FROM_IMAGE is 1.
#ifndef SHADOWC_LAYER_MOMENTS_GLSL
#define SHADOWC_LAYER_MOMENTS_GLSL

#ifndef SHADOWC_LAYERS
#define SHADOWC_LAYERS 1
#endif
#ifndef SHADOWC_SPLITS
#define SHADOWC_SPLITS float[](0.0, 1.0)
#endif
#ifndef SHADOWC_OVERLAP
#define SHADOWC_OVERLAP 0.0
#endif
#ifndef SHADOWC_SPLITS_FROM_IMAGE
#define SHADOWC_SPLITS_FROM_IMAGE 0
#endif
#include "passes/moments_warp.glsl"

vec4 shadowc_layerMoments(float d, int layer) {
#if SHADOWC_LAYERS == 1
  return shadowc_warpMoments(d);
#else
#if SHADOWC_SPLITS_FROM_IMAGE
  const float lo = texelFetch(splitsImage, ivec2(layer, 0), 0).r;
  const float hi = texelFetch(splitsImage, ivec2(layer + 1, 0), 0).r;
#else
  const float splits[SHADOWC_LAYERS + 1] = SHADOWC_SPLITS;
  const float lo = splits[layer], hi = splits[layer + 1];
#endif
  return shadowc_warpMoments(shadowc_layerRemap(d, lo - SHADOWC_OVERLAP, hi + SHADOWC_OVERLAP));
#endif
}

#endif

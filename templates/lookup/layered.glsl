// layered.glsl — layered variance shadow maps (lauritzen2008 sec. 3.3-3.4, 5). The depth range
// is split at s_0 < s_1 < ... < s_N; layer i stores the moments of the depth linearly remapped
// into [p_i, q_i] = [s_i - delta, s_{i+1} + delta] and clamped (eq. 6; briefing table, the
// prefilter passes use the same ranges). A receiver at depth d is resolved in the single layer j
// with s_j <= d < s_{j+1} (sec. 3.3: nearer layers are at least as lit, farther ones give 1),
// using that layer's warp of d and minimum variance sigma^2_min / (q_j - p_j)^2 (eq. 7). Within
// delta of a split the two neighbouring layers are blended linearly (sec. 5 "transition region"),
// which hides the discontinuity at layer borders.
// Guards: (q - p) is floored at 1e-6 before dividing; splits come either from the compiler
// (uniform/explicit, const table) or from the Lloyd relaxation image (binding 8).
#ifndef SHADOWC_LAYERED_GLSL
#define SHADOWC_LAYERED_GLSL

float shadowc_split(int i) { SHADOWC_COUNT(SHADOWC_WORK_SPLIT_FETCHES, SHADOWC_LAYERS > 1 && SHADOWC_HAS_SPLITS_TEXTURE != 0)
#if SHADOWC_LAYERS > 1
#if SHADOWC_HAS_SPLITS_TEXTURE
  return texelFetch(shadowc_splitsTexture, ivec2(i, 0), 0).r;
#else
  return shadowc_splitTable[i];
#endif
#else
  return i == 0 ? 0.0 : 1.0;
#endif
}

vec2 shadowc_layerRange(int i) {
#if SHADOWC_LAYERS > 1
  return vec2(shadowc_split(i) - SHADOWC_OVERLAP, shadowc_split(i + 1) + SHADOWC_OVERLAP);
#else
  return vec2(0.0, 1.0);  // a single layer is the unwarped depth (plain VSM)
#endif
}

// Receiver depth in layer i's warped space (eq. 6).
float shadowc_layerDepth(float d, int i) {
#if SHADOWC_LAYERS > 1
  vec2 r = shadowc_layerRange(i);
  return clamp((d - r.x) / max(r.y - r.x, 1e-6), 0.0, 1.0);
#else
  return d;
#endif
}

// Per-layer minimum variance (eq. 7).
float shadowc_layerMinVariance(int i) {
#if SHADOWC_LAYERS > 1
  vec2 r = shadowc_layerRange(i);
  float w = max(r.y - r.x, 1e-6);
  return SHADOWC_MIN_VARIANCE / (w * w);
#else
  return SHADOWC_MIN_VARIANCE;
#endif
}

// The layer j with s_j <= d < s_{j+1} (first / last layer below / above the range).
int shadowc_layerOf(float d) {
  int j = 0;
  for (int i = 1; i < SHADOWC_LAYERS; ++i)
    if (d >= shadowc_split(i)) j = i;
  return j;
}

#endif

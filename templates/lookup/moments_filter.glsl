// moments_filter.glsl — the filtered moments of a kernel and the estimator of the filter's warp.
// The mean moments over a texel rectangle come from the summed-area table when there is one
// (sat.glsl, exact box), else from the moments image itself: one trilinear fetch at the
// rectangle's centre at the mip level whose texel matches the kernel width (prefilter mips), or
// the bilinear level-0 value (a fixed kernel realised by the blur prefilter).
// Estimators by warp (briefing table for the stored channels):
//   linear -> Chebyshev (chebyshev.glsl), exp -> ESM (esm.glsl), evsm2/4 -> EVSM (evsm.glsl),
//   power_cdf -> power-CDF (power_cdf.glsl), msm -> Hamburger 4MSM (msm.glsl).
#ifndef SHADOWC_MOMENTS_FILTER_GLSL
#define SHADOWC_MOMENTS_FILTER_GLSL

#if SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_VSSM
// Mean moments over an inclusive texel rectangle (VSSM sub-kernels).
vec4 shadowc_rectMoments(ivec4 rect, int layer) { SHADOWC_COUNT(SHADOWC_WORK_MOMENT_FETCHES, SHADOWC_HAS_SAT == 0)
#if SHADOWC_HAS_SAT
  return shadowc_summedMean(rect, layer);
#else
  vec2 uv = vec2(rect.xy + rect.zw + 1) * 0.5 / vec2(shadowc_mapSize());
  float w = float(max(rect.z - rect.x, rect.w - rect.y) + 1);
  return textureLod(shadowc_moments, vec3(uv, float(layer)), SHADOWC_MIPS != 0 ? log2(w) : 0.0);
#endif
}

// Mean moments over a box in texel units (kernel.glsl, shadowc_kernelBox): fractional corners
// when the filter asks for them, else the box's whole texels.
vec4 shadowc_boxMoments(vec4 box, int layer) {
#if SHADOWC_HAS_SAT && SHADOWC_SAT_FRACTIONAL
  return shadowc_summedMeanBox(box, layer);
#else
  return shadowc_rectMoments(ivec4(box.xy, box.zw - 1.0), layer);
#endif
}
#endif

// Mean moments of a kernel `w` texels wide centred at uv (rect = its clamped texel rectangle).
// Without a SAT the fetch stays at the receiver's own uv, so bilinear filtering keeps it smooth.
vec4 shadowc_kernelMoments(vec2 uv, ivec4 rect, float w, int layer) { SHADOWC_COUNT(SHADOWC_WORK_MOMENT_FETCHES, SHADOWC_HAS_SAT == 0)
#if SHADOWC_HAS_SAT && SHADOWC_SAT_FRACTIONAL
  return shadowc_summedMeanBox(shadowc_kernelBox(uv * vec2(shadowc_mapSize()), w), layer);
#elif SHADOWC_HAS_SAT
  return shadowc_summedMean(rect, layer);
#else
  return textureLod(shadowc_moments, vec3(uv, float(layer)), SHADOWC_MIPS != 0 ? log2(max(w, 1.0)) : 0.0);
#endif
}

// Visibility from mean moments m for a receiver at (layer-warped) depth d.
float shadowc_estimate(vec4 m, float d, float minVariance) {
#if SHADOWC_WARP == SHADOWC_WARP_LINEAR
#if SHADOWC_HAS_SAT
  minVariance = max(minVariance, shadowc_satVarianceFloor);  // sat.glsl: int32 box-mean noise
#endif
  return shadowc_reduceBleeding(shadowc_chebyshev(m.x, m.y, d, minVariance));
#elif SHADOWC_WARP == SHADOWC_WARP_EXP
  return shadowc_esm(m.x, d);
#elif SHADOWC_WARP == SHADOWC_WARP_EVSM2 || SHADOWC_WARP == SHADOWC_WARP_EVSM4
  return shadowc_evsm(m, d, minVariance);
#elif SHADOWC_WARP == SHADOWC_WARP_MSM
  return shadowc_reduceBleeding(shadowc_msm(m, d));
#else
  return shadowc_powerCdf(m.xyz, d);
#endif
}

float shadowc_layerVisibility(vec2 uv, ivec4 rect, float w, float d, int layer) {
  return shadowc_estimate(shadowc_kernelMoments(uv, rect, w, layer), shadowc_layerDepth(d, layer),
                          shadowc_layerMinVariance(layer));
}

// Visibility of a receiver at biased depth d over a kernel, through the layers.
float shadowc_filteredVisibility(vec2 uv, ivec4 rect, float w, float d) {
  int j = shadowc_layerOf(d);
  float v = shadowc_layerVisibility(uv, rect, w, d, j);
#if SHADOWC_LAYER_BLEND
  // Transition regions of width 2 delta around each split (lauritzen2008 sec. 5).
  const float delta = SHADOWC_OVERLAP;
  if (j + 1 < SHADOWC_LAYERS && d > shadowc_split(j + 1) - delta) {
    float t = clamp((d - (shadowc_split(j + 1) - delta)) / (2.0 * delta), 0.0, 1.0);
    v = mix(v, shadowc_layerVisibility(uv, rect, w, d, j + 1), t);
  } else if (j > 0 && d < shadowc_split(j) + delta) {
    float t = clamp((d - (shadowc_split(j) - delta)) / (2.0 * delta), 0.0, 1.0);
    v = mix(shadowc_layerVisibility(uv, rect, w, d, j - 1), v, t);
  }
#endif
  return v;
}

// The moments technique: kernel width fixed, or driven by a PCSS blocker search on the depth map
// (or the whole search region when there is no blocker estimate), then the filtered estimate.
float shadowc_momentsTechnique(shadowc_Receiver r) {
#if SHADOWC_KERNEL_PENUMBRA
#if SHADOWC_BLOCKER_KIND == SHADOWC_BLOCKER_SEARCH
  float zb = shadowc_blockerSearch(r, shadowc_searchTexels(r)); SHADOWC_COUNT(SHADOWC_WORK_BLOCKERS_FOUND, zb >= 0.0)
  if (zb < 0.0) return 1.0;
  float w = shadowc_penumbraTexels(r, zb);
#else
  float w = shadowc_searchTexels(r);
#endif
#else
  float w = SHADOWC_KERNEL_FIXED_TEXELS;
#endif
  return shadowc_filteredVisibility(r.uv, shadowc_kernelRect(r.texel, w), w, r.d);
}

#endif

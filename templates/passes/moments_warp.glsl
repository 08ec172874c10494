// moments_warp.glsl — the depth warps stored in the `moments` image, shared by the moments
// pass and (through #include "passes/moments_warp.glsl") any lookup that warps the receiver
// depth the same way. All warps act on normalized linear depth d in [0,1] (frame.glsl).
//   SHADOWC_WARP 0 linear     rg   (d, d^2)                         vsm-tutorial; vssm-yang2010 eq. 1
//   SHADOWC_WARP 1 exp        r    exp(c+ (d - 1))                  ESM; <= 1 so fp16/unorm keep precision
//   SHADOWC_WARP 2 evsm2      rg   (e+, e+^2), e+ = exp(c+ (d - 1))  lauritzen2008 sec. 3.2 (positive warp)
//   SHADOWC_WARP 3 evsm4      rgba (e+, e+^2, -e-, e-^2), e- = exp(-c- (d - 1)) >= 1 (negative warp)
//   SHADOWC_WARP 4 power_cdf  rgb  (min, max, mean) of d; a unused  power-cdf
//   SHADOWC_WARP 5 msm        rgba (d, d^2, d^3, d^4), quantized for 16-bit storage
//                                                                 Peters & Klein 2015 (msm_moments.glsl)
// Layered (SHADOWC_LAYERS > 1): layer i first remaps d linearly into its range
// [p_i, q_i] = [split_i - overlap, split_{i+1} + overlap], clamped to [0,1] (lauritzen2008 eq. 6).
#ifndef SHADOWC_MOMENTS_WARP_GLSL
#define SHADOWC_MOMENTS_WARP_GLSL

#ifndef SHADOWC_WARP
#define SHADOWC_WARP 0
#endif
#ifndef SHADOWC_EXP_POSITIVE
#define SHADOWC_EXP_POSITIVE 40.0
#endif
#ifndef SHADOWC_EXP_NEGATIVE
#define SHADOWC_EXP_NEGATIVE 5.0
#endif
#if SHADOWC_WARP == 5
#include "passes/msm_moments.glsl"
#endif

vec4 shadowc_warpMoments(float d) {
#if SHADOWC_WARP == 0
  return vec4(d, d * d, 0.0, 0.0);
#elif SHADOWC_WARP == 1
  return vec4(exp(SHADOWC_EXP_POSITIVE * (d - 1.0)), 0.0, 0.0, 0.0);
#elif SHADOWC_WARP == 2
  float e = exp(SHADOWC_EXP_POSITIVE * (d - 1.0));
  return vec4(e, e * e, 0.0, 0.0);
#elif SHADOWC_WARP == 3
  float ep = exp(SHADOWC_EXP_POSITIVE * (d - 1.0));
  float en = exp(-SHADOWC_EXP_NEGATIVE * (d - 1.0));
  return vec4(ep, ep * ep, -en, en * en);
#elif SHADOWC_WARP == 5
  return shadowc_msmEncode(d);
#else
  return vec4(d, d, d, 0.0);  // min, max, mean of a single texel
#endif
}

// lauritzen2008 eq. 6: phi_i(t) = clamp((t - p_i) / (q_i - p_i), 0, 1).
float shadowc_layerRemap(float d, float p, float q) { return clamp((d - p) / max(q - p, 1e-6), 0.0, 1.0); }

#endif

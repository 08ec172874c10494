// sat.glsl — box means of the moments from the summed-area table (Crow 1984; vssm-yang2010
// sec. 6.4, Lauritzen 2007). Convention (shared with the SAT prefilter pass): INCLUSIVE corners,
//   S(x, y) = sum of v(i, j) over 0 <= i <= x, 0 <= j <= y,
// so the sum over texels [x0, x1] x [y0, y1] (inclusive) is
//   S(x1, y1) - S(x0 - 1, y1) - S(x1, y0 - 1) + S(x0 - 1, y0 - 1),  with S(-1, .) = S(., -1) = 0.
// Storage kinds:
//   int32:         v in [0, 1] stored as uint(round(v * 65536)) (16.16 fixed point); the sums
//                  wrap around mod 2^32 and the 4-corner difference is done in uint, which is
//                  exact as long as the box sum itself fits in 32 bits: the compiler caps the
//                  kernel at 255 texels (255^2 * 65536 < 2^32). Mean = sum / (65536 * area).
//   fp32 centered: sums of (v - 0.5); mean = sum / area + 0.5 (the usual precision fix).
//   fp32 naive:    plain sums; kept so the stability suite can show its error (FACTS.md).
// Guards: rectangles are clamped to the map by the caller (kernel.glsl) and their area is >= 1.
#ifndef SHADOWC_SAT_GLSL
#define SHADOWC_SAT_GLSL

// Variance noise of int32 box means (issue 9, defect 2): each stored value is within half a
// quantum (2^-17) of the exact one, so a box mean of x and of x^2 each err by up to e = 2^-17 and
// E[x^2] - E[x]^2 by up to e (1 + 2 E[x]) + e^2 <= 3 * 2^-17 = 2.29e-5, plus fp32 rounding of the
// means: 2.4e-5. A smaller minimum variance (the default is 1e-5) lets that noise, not the
// depths, decide Chebyshev on small and flat boxes, so linear moments read from an int32 SAT use
// at least this floor (intent_reference.cpp uses the same).
#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
const float shadowc_satVarianceFloor = 2.4e-5;
#else
const float shadowc_satVarianceFloor = 0.0;
#endif

#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
uvec4 shadowc_summedCorner(int x, int y, int layer) {
  if (x < 0 || y < 0) return uvec4(0u);
  return texelFetch(shadowc_summedArea, ivec3(x, y, layer), 0);
}
#else
vec4 shadowc_summedCorner(int x, int y, int layer) {
  if (x < 0 || y < 0) return vec4(0.0);
  return texelFetch(shadowc_summedArea, ivec3(x, y, layer), 0);
}
#endif

// Mean of the moments over the inclusive texel rectangle (x0, y0, x1, y1).
vec4 shadowc_summedMean(ivec4 rect, int layer) {
  float area = float((rect.z - rect.x + 1) * (rect.w - rect.y + 1));
  area = max(area, 1.0);
#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
  uvec4 sum = shadowc_summedCorner(rect.z, rect.w, layer) - shadowc_summedCorner(rect.x - 1, rect.w, layer) -
              shadowc_summedCorner(rect.z, rect.y - 1, layer) + shadowc_summedCorner(rect.x - 1, rect.y - 1, layer);
  return vec4(sum) / (65536.0 * area);
#else
  vec4 sum = shadowc_summedCorner(rect.z, rect.w, layer) - shadowc_summedCorner(rect.x - 1, rect.w, layer) -
             shadowc_summedCorner(rect.z, rect.y - 1, layer) + shadowc_summedCorner(rect.x - 1, rect.y - 1, layer);
#if SHADOWC_SAT_KIND == SHADOWC_SAT_FP32_CENTERED
  return sum / area + 0.5;
#else
  return sum / area;
#endif
#endif
}

#endif

// sat.glsl — box means of the moments from the summed-area table (Crow 1984; vssm-yang2010
// sec. 6.4, Lauritzen 2007). Convention (shared with the SAT prefilter pass): INCLUSIVE corners,
//   S(x, y) = sum of v(i, j) over 0 <= i <= x, 0 <= j <= y,
// so the sum over texels [x0, x1] x [y0, y1] (inclusive) is
//   S(x1, y1) - S(x0 - 1, y1) - S(x1, y0 - 1) + S(x0 - 1, y0 - 1),  with S(-1, .) = S(., -1) = 0.
// Storage kinds:
//   int32:         v in [0, 1] stored as uint(round(v * 65536)) (16.16 fixed point); the sums
//                  wrap around mod 2^32 and the 4-corner difference is done in uint, which is
//                  exact as long as the box sum itself fits in 32 bits (255^2 * 65536 < 2^32).
//                  A wider box (SHADOWC_SAT_PIECES > 1) is cut into pieces of at most 255 texels
//                  a side, each an exact uint box sum, added in float (kernels up
//                  to the whole map, below). Mean = sum / (65536 * area).
//   fp32 centered: sums of (v - 0.5); mean = sum / area + 0.5 (the usual fix, still 0.09 off on
//                  1x1 boxes of a 2048^2 map: docs/stability.md; exponential warps are E0420).
//   fp32 naive:    plain sums; kept so the stability suite can show its error (docs/stability.md).
// Guards: rectangles are clamped to the map by the caller (kernel.glsl) and their area is >= 1.
#ifndef SHADOWC_SAT_GLSL
#define SHADOWC_SAT_GLSL

// Variance noise of int32 box means: each stored value is within half a
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
uvec4 shadowc_summedCorner(int x, int y, int layer) { SHADOWC_COUNT(SHADOWC_WORK_SAT_FETCHES, 1)
  uvec4 v = texelFetch(shadowc_summedArea, ivec3(max(x, 0), max(y, 0), layer), 0);
  return x < 0 || y < 0 ? uvec4(0u) : v;
}
#else
vec4 shadowc_summedCorner(int x, int y, int layer) { SHADOWC_COUNT(SHADOWC_WORK_SAT_FETCHES, 1)
  vec4 v = texelFetch(shadowc_summedArea, ivec3(max(x, 0), max(y, 0), layer), 0);
  return x < 0 || y < 0 ? vec4(0.0) : v;
}
#endif

// The type of a SAT corner / box sum, and a box sum over `area` texels turned into mean moments
// (one definition for every caller: vssm.glsl's shared-corner walk sums corners itself).
#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
#define shadowc_SatSum uvec4
#else
#define shadowc_SatSum vec4
#endif
vec4 shadowc_satMeanOfSum(shadowc_SatSum sum, float area) {
#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
  return vec4(sum) / (65536.0 * area);
#elif SHADOWC_SAT_KIND == SHADOWC_SAT_FP32_CENTERED
  return sum / area + 0.5;
#else
  return sum / area;
#endif
}

#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32 && SHADOWC_SAT_PIECES > 1
#define SHADOWC_SAT_WIDE 1
#else
#define SHADOWC_SAT_WIDE 0
#endif

#if SHADOWC_SAT_WIDE
// Wide int32 boxes (kernels up to the whole map at bounded cost, without giving
// up the 16.16 precision small boxes need; fewer fractional bits would raise the variance noise
// of every 1x1 box by 2^(16-F), see shadowc_satVarianceFloor). Along each axis the box is cut
// into pieces of at most 255 texels; each piece box sum fits in 32 bits, so its wrap-around
// difference is exact, and the pieces are added in float (relative error <= P^2 * 2^-24 of the
// sum, far under the variance floor). A row of P pieces reads 2 (P + 1) corners: 4 for a box
// within 255 texels (bit-identical to the plain query), 60 for a whole 1024^2 map (P = 5).
const int shadowc_satPiece = 255;

// Start (exclusive, -1 based like the corners) of piece `i` of the texels [lo, hi] on one axis.
int shadowc_satCut(int lo, int hi, int i) { return min(lo - 1 + i * shadowc_satPiece, hi); }

vec4 shadowc_summedSum(ivec4 rect, int layer) {
  ivec2 pieces = (rect.zw - rect.xy + shadowc_satPiece) / shadowc_satPiece;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < SHADOWC_SAT_PIECES && j < pieces.y; ++j) {
    int y0 = shadowc_satCut(rect.y, rect.w, j);
    int y1 = shadowc_satCut(rect.y, rect.w, j + 1);
    uvec4 lo0 = shadowc_summedCorner(rect.x - 1, y0, layer);
    uvec4 hi0 = shadowc_summedCorner(rect.x - 1, y1, layer);
    for (int i = 1; i <= SHADOWC_SAT_PIECES && i <= pieces.x; ++i) {
      int x1 = shadowc_satCut(rect.x, rect.z, i);
      uvec4 lo1 = shadowc_summedCorner(x1, y0, layer);
      uvec4 hi1 = shadowc_summedCorner(x1, y1, layer);
      sum += vec4(hi1 - hi0 - lo1 + lo0);
      lo0 = lo1;
      hi0 = hi1;
    }
  }
  return sum;
}
#endif

// Mean of the moments over the inclusive texel rectangle (x0, y0, x1, y1).
vec4 shadowc_summedMean(ivec4 rect, int layer) {
  float area = float((rect.z - rect.x + 1) * (rect.w - rect.y + 1));
  area = max(area, 1.0);
#if SHADOWC_SAT_WIDE
  return shadowc_summedSum(rect, layer) / (65536.0 * area);
#else
  shadowc_SatSum sum = shadowc_summedCorner(rect.z, rect.w, layer) - shadowc_summedCorner(rect.x - 1, rect.w, layer) -
                       shadowc_summedCorner(rect.z, rect.y - 1, layer) +
                       shadowc_summedCorner(rect.x - 1, rect.y - 1, layer);
  return shadowc_satMeanOfSum(sum, area);
#endif
}

#if SHADOWC_SAT_FRACTIONAL
// Fractional corners: the mean over the continuous box (x0, y0, x1, y1) in
// texel units (texel i covers [i, i+1)), i.e. the exact integral of the piecewise-constant
// moments under the box, which is the bilinear interpolation of the SAT at the four corners.
// It is evaluated without interpolating large sums (int32 sums wrap): per axis the box covers a
// partly covered first texel (weight 1 - f0), whole texels (weight 1) and a partly covered last
// texel (weight f1), or a single texel with weight x1 - x0. The 3 x 3 regions are exact box sums
// (uint, mod 2^32, from 16 corners) of at most the int32 limit each, weighted in float.
void shadowc_boxSegments(float a, float b, out ivec4 k, out vec3 w) {
  int n0 = int(floor(a));
  int n1 = int(floor(b));
  if (n1 <= n0) {
    k = ivec4(n0, n0 + 1, n0 + 1, n0 + 1);
    w = vec3(b - a, 0.0, 0.0);
  } else {
    k = ivec4(n0, n0 + 1, n1, n1 + 1);
    w = vec3(1.0 - (a - float(n0)), 1.0, b - float(n1));
  }
}

#if SHADOWC_SAT_WIDE
// The same integral for boxes wider than a piece: per axis the segments are the partly covered
// first texel, the whole texels in pieces of at most 255 (sat.glsl's wide sums), and the partly
// covered last texel. Segment s runs from boundary s to s + 1 (texel boundaries, I(k) = S(k - 1)).
int shadowc_segmentCount(float a, float b) {
  int n0 = int(floor(a));
  int n1 = int(floor(b));
  return n1 <= n0 ? 1 : 2 + (n1 - n0 - 1 + shadowc_satPiece - 1) / shadowc_satPiece;
}
int shadowc_segmentBound(float a, float b, int s, int count) {
  int n0 = int(floor(a));
  if (s == 0) return n0;
  if (s == count) return (count == 1 ? n0 : int(floor(b))) + 1;
  return min(n0 + 1 + (s - 1) * shadowc_satPiece, int(floor(b)));
}
float shadowc_segmentWeight(float a, float b, int s, int count) {
  if (count == 1) return b - a;
  if (s == 0) return 1.0 - (a - floor(a));
  return s == count - 1 ? b - floor(b) : 1.0;
}

vec4 shadowc_summedMeanBox(vec4 box, int layer) {
  int cx = shadowc_segmentCount(box.x, box.z);
  int cy = shadowc_segmentCount(box.y, box.w);
  ivec2 last = textureSize(shadowc_summedArea, 0).xy;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < SHADOWC_SAT_PIECES + 2 && j < cy; ++j) {
    float wy = shadowc_segmentWeight(box.y, box.w, j, cy);
    if (!(wy > 0.0)) continue;
    int y0 = min(shadowc_segmentBound(box.y, box.w, j, cy), last.y) - 1;
    int y1 = min(shadowc_segmentBound(box.y, box.w, j + 1, cy), last.y) - 1;
    int x0 = min(shadowc_segmentBound(box.x, box.z, 0, cx), last.x) - 1;
    uvec4 lo0 = shadowc_summedCorner(x0, y0, layer);
    uvec4 hi0 = shadowc_summedCorner(x0, y1, layer);
    for (int i = 0; i < SHADOWC_SAT_PIECES + 2 && i < cx; ++i) {
      int x1 = min(shadowc_segmentBound(box.x, box.z, i + 1, cx), last.x) - 1;
      uvec4 lo1 = shadowc_summedCorner(x1, y0, layer);
      uvec4 hi1 = shadowc_summedCorner(x1, y1, layer);
      float weight = shadowc_segmentWeight(box.x, box.z, i, cx) * wy;
      if (weight > 0.0) sum += weight * vec4(hi1 - hi0 - lo1 + lo0);
      lo0 = lo1;
      hi0 = hi1;
    }
  }
  float area = max((box.z - box.x) * (box.w - box.y), 1e-12);
  return sum / (65536.0 * area);
}
#else
vec4 shadowc_summedMeanBox(vec4 box, int layer) {
  ivec4 kx, ky;
  vec3 wx, wy;
  shadowc_boxSegments(box.x, box.z, kx, wx);
  shadowc_boxSegments(box.y, box.w, ky, wy);
  // I(k) = S(k - 1): the integral up to the texel boundary k; boundaries past the map add nothing.
  ivec2 last = textureSize(shadowc_summedArea, 0).xy;
  kx = min(kx, ivec4(last.x)) - 1;
  ky = min(ky, ivec4(last.y)) - 1;
#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
  uvec4 c[4][4];
#else
  vec4 c[4][4];
#endif
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) c[i][j] = shadowc_summedCorner(kx[i], ky[j], layer);
  vec4 sum = vec4(0.0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      float weight = wx[i] * wy[j];
      if (weight > 0.0) sum += weight * vec4(c[i + 1][j + 1] - c[i][j + 1] - c[i + 1][j] + c[i][j]);
    }
  float area = max((box.z - box.x) * (box.w - box.y), 1e-12);
#if SHADOWC_SAT_KIND == SHADOWC_SAT_INT32
  return sum / (65536.0 * area);
#elif SHADOWC_SAT_KIND == SHADOWC_SAT_FP32_CENTERED
  return sum / area + 0.5;
#else
  return sum / area;
#endif
}
#endif
#endif

#endif

// minmax.glsl — min-max hierarchical shadow map (vssm-yang2010 sec. 6.1, Algorithm 1 L8-L10):
// a mip pyramid whose level L texel (i, j) holds (min, max) of the depths of level-0 texels
// [i 2^L, (i+1) 2^L) x [j 2^L, (j+1) 2^L). For a kernel rectangle we pick the smallest level L
// with 2^L >= the rectangle's width, where it covers at most 2 x 2 cells. The pyramid stops at
// level ceil(log2 max) (planner.cpp pyramidLevels), and the influence rectangle is wider than
// `max` (bilinear taps, the blur footprint): clamped to the top level it can span 3 or more
// cells per axis, so every cell from its first to its last is read (reading
// only the 4 corner cells missed occluders in the middle ones; stability case
// minmax_three_top_cells). The result bounds the kernel's depths conservatively (it may include
// a few texels around the kernel), so the early out is exact whenever it fires:
//   min >= d  -> no texel occludes            -> lit (1)
//   max <  d  -> every texel occludes          -> umbra (0)   (d is the biased receiver depth)
// No division: no NaN possible.
#ifndef SHADOWC_MINMAX_GLSL
#define SHADOWC_MINMAX_GLSL

vec2 shadowc_minMaxOfRect(ivec4 rect) {
  int w = max(rect.z - rect.x, rect.w - rect.y) + 1;
  int level = w > 1 ? findMSB(w - 1) + 1 : 0;  // 2^level >= w
  level = min(level, textureQueryLevels(shadowc_minMaxPyramid) - 1);
  ivec2 last = max(textureSize(shadowc_minMaxPyramid, level) - 1, ivec2(0));
  ivec2 lo = clamp(rect.xy >> level, ivec2(0), last);
  ivec2 hi = clamp(rect.zw >> level, ivec2(0), last);
  vec2 mm = texelFetch(shadowc_minMaxPyramid, lo, level).rg; SHADOWC_COUNT(SHADOWC_WORK_MINMAX_FETCHES, 1)
  // 2 x 2 cells below the top level; at the top level (max + 2) / 2^L + 1 <= 3 per axis for the
  // kernels the pyramid was sized for, at most the whole top level in any case.
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      vec2 c = texelFetch(shadowc_minMaxPyramid, ivec2(x, y), level).rg; SHADOWC_COUNT(SHADOWC_WORK_MINMAX_FETCHES, 1)
      mm = vec2(min(mm.x, c.x), max(mm.y, c.y));
    }
  return mm;
}

// 1 = lit, 0 = umbra, -1 = undecided (penumbra candidate: run the filter).
// dLo / dHi: the lowest and highest receiver depth any tap in the rectangle compares against
// (equal but for the receiver-plane bias, bias.glsl).
float shadowc_earlyOut(ivec4 rect, float dLo, float dHi) {
  vec2 mm = shadowc_minMaxOfRect(rect);
  if (mm.x >= dHi) return 1.0;
  if (mm.y < dLo) return 0.0;
  return -1.0;
}

#endif

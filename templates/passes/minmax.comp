#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// minmax.comp — min-max hierarchical shadow map built as a mip chain (vssm-yang2010 sec. 6.1:
// mip-maps rather than N-buffers, 1 ms vs 3 ms at 1024^2). r = min depth, g = max depth.
// A level-k texel p is the min/max of level k-1's texels [2p, last(p)] (2x2, plus the last odd
// row/column at the far edge), through storage views.
// Fused, so that a pyramid of L levels takes about L/2 dispatches and each level
// is read at most once: one invocation per texel of the dispatch's last level, which
//   SHADOWC_MINMAX_LEVEL0 = 1: reads the light depth itself and also stores it as level 0
//                              (min = max = d), so the full-size level 0 is never read back;
//   SHADOWC_MINMAX_TWO = 1:    computes two levels, the middle one (binding 3) on the way.
// The footprints [2p, last(p)] tile the level below exactly, so every texel of every level the
// dispatch writes is written by exactly one invocation.
#ifndef SHADOWC_MINMAX_LEVEL0
#define SHADOWC_MINMAX_LEVEL0 0
#endif
#ifndef SHADOWC_MINMAX_TWO
#define SHADOWC_MINMAX_TWO 0
#endif

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
#if SHADOWC_MINMAX_LEVEL0
layout(set = 0, binding = 0) uniform sampler2D shadowDepth;
layout(set = 0, binding = 2, rg32f) writeonly uniform image2D level0;
#else
layout(set = 0, binding = 0, rg32f) readonly uniform image2D src;  // the level below the first written
#endif
layout(set = 0, binding = 1, rg32f) writeonly uniform image2D dst;  // the last level written
#if SHADOWC_MINMAX_TWO
layout(set = 0, binding = 3, rg32f) writeonly uniform image2D mid;  // the level between src and dst
#endif

ivec2 shadowc_sourceSize() {
#if SHADOWC_MINMAX_LEVEL0
  return textureSize(shadowDepth, 0);
#else
  return imageSize(src);
#endif
}

// The last texel of the footprint of texel p of a level of `size` texels over one of `below`.
ivec2 shadowc_footprintLast(ivec2 p, ivec2 size, ivec2 below) {
  return min(2 * p + 1 + ivec2(equal(p, size - 1)) * (below & 1), below - 1);
}

// Min/max of texel p of the first level above the source (`size` texels), read from the source.
vec2 shadowc_reduceSource(ivec2 p, ivec2 size, ivec2 srcSize) {
  const ivec2 last = shadowc_footprintLast(p, size, srcSize);
  vec2 mm = vec2(1e30, -1e30);
  for (int y = 2 * p.y; y <= last.y; ++y)
    for (int x = 2 * p.x; x <= last.x; ++x) {
#if SHADOWC_MINMAX_LEVEL0
      const float d = texelFetch(shadowDepth, ivec2(x, y), 0).r;
      imageStore(level0, ivec2(x, y), vec4(d, d, 0.0, 0.0));
      const vec2 v = vec2(d);
#else
      const vec2 v = imageLoad(src, ivec2(x, y)).rg;
#endif
      mm = vec2(min(mm.x, v.x), max(mm.y, v.y));
    }
  return mm;
}

void main() {
  const ivec2 dstSize = imageSize(dst);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, dstSize))) return;
  const ivec2 srcSize = shadowc_sourceSize();
#if SHADOWC_MINMAX_TWO
  const ivec2 midSize = imageSize(mid);
  const ivec2 last = shadowc_footprintLast(p, dstSize, midSize);
  vec2 mm = vec2(1e30, -1e30);
  for (int y = 2 * p.y; y <= last.y; ++y)
    for (int x = 2 * p.x; x <= last.x; ++x) {
      const vec2 v = shadowc_reduceSource(ivec2(x, y), midSize, srcSize);
      imageStore(mid, ivec2(x, y), vec4(v, 0.0, 0.0));
      mm = vec2(min(mm.x, v.x), max(mm.y, v.y));
    }
#else
  const vec2 mm = shadowc_reduceSource(p, dstSize, srcSize);
#endif
  imageStore(dst, p, vec4(mm, 0.0, 0.0));
}

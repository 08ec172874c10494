#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// minmax.comp — min-max hierarchical shadow map built as a mip chain (vssm-yang2010 sec. 6.1:
// mip-maps rather than N-buffers, 1 ms vs 3 ms at 1024^2). r = min depth, g = max depth.
// SHADOWC_MINMAX_LEVEL0 = 1: level 0 from shadow_depth (min = max = d). Otherwise level k
// from level k-1 by a 2x2 min/max (plus the last odd row/column), through storage views.
#ifndef SHADOWC_MINMAX_LEVEL0
#define SHADOWC_MINMAX_LEVEL0 0
#endif

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
#if SHADOWC_MINMAX_LEVEL0
layout(set = 0, binding = 0) uniform sampler2D shadowDepth;
#else
layout(set = 0, binding = 0, rg32f) readonly uniform image2D src;  // level k-1
#endif
layout(set = 0, binding = 1, rg32f) writeonly uniform image2D dst;  // level k

void main() {
  const ivec2 dstSize = imageSize(dst);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, dstSize))) return;
#if SHADOWC_MINMAX_LEVEL0
  const float d = texelFetch(shadowDepth, p, 0).r;
  imageStore(dst, p, vec4(d, d, 0.0, 0.0));
#else
  const ivec2 srcSize = imageSize(src);
  const ivec2 first = 2 * p;
  const ivec2 last = min(2 * p + 1 + ivec2(equal(p, dstSize - 1)) * (srcSize & 1), srcSize - 1);
  vec2 mm = vec2(1e30, -1e30);
  for (int y = first.y; y <= last.y; ++y)
    for (int x = first.x; x <= last.x; ++x) {
      const vec2 v = imageLoad(src, ivec2(x, y)).rg;
      mm = vec2(min(mm.x, v.x), max(mm.y, v.y));
    }
  imageStore(dst, p, vec4(mm, 0.0, 0.0));
#endif
}

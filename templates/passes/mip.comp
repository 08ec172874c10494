#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// mip.comp — one level of the moments mip chain: level k from level k-1 (2x2 box, plus the
// last odd row/column so no source texel is dropped). Moments are linear, so their box
// mean is the mean of the moments (vsm-tutorial, "mipmapping"); power-CDF keeps min/max in
// r/g and averages only the mean in b. The runtime binds storage views of the two levels.
#ifndef SHADOWC_LAYERS
#define SHADOWC_LAYERS 1
#endif
#ifndef SHADOWC_MOMENTS_FORMAT
#define SHADOWC_MOMENTS_FORMAT rg32f
#endif
#ifndef SHADOWC_WARP
#define SHADOWC_WARP 0
#endif

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(set = 0, binding = 0, SHADOWC_MOMENTS_FORMAT) readonly uniform image2DArray src;   // level k-1
layout(set = 0, binding = 1, SHADOWC_MOMENTS_FORMAT) writeonly uniform image2DArray dst;  // level k

void main() {
  const ivec2 srcSize = imageSize(src).xy;
  const ivec2 dstSize = imageSize(dst).xy;
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, dstSize))) return;
  // Source footprint [2p, 2p+1], widened by one when this is the last texel of an odd level.
  const ivec2 first = 2 * p;
  const ivec2 last = min(2 * p + 1 + ivec2(equal(p, dstSize - 1)) * (srcSize & 1), srcSize - 1);
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
    vec4 sum = vec4(0.0);
    float lo = 1e30, hi = -1e30;
    for (int y = first.y; y <= last.y; ++y)
      for (int x = first.x; x <= last.x; ++x) {
        vec4 v = imageLoad(src, ivec3(x, y, layer));
        sum += v;
        lo = min(lo, v.r);
        hi = max(hi, v.g);
      }
    const ivec2 n = last - first + 1;
    vec4 mean = sum / float(n.x * n.y);
#if SHADOWC_WARP == 4
    mean.r = lo;
    mean.g = hi;
#endif
    imageStore(dst, ivec3(p, layer), mean);
  }
}

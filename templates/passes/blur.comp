#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// blur.comp — one axis of the separable moments prefilter (vsm-tutorial: "filtering the
// variance shadow map"; moments are linear, so blurring them is filtering the visibility
// estimate's inputs). blur_h: moments -> moments_tmp, blur_v: moments_tmp -> moments.
// Weights are folded by the emitter: box 1/(2r+1), gaussian sigma = r/2, normalized.
// Power-CDF keeps (min, max, mean): r = min over the window, g = max, b = weighted mean.
// Texels outside the map clamp to the edge.
#ifndef SHADOWC_BLUR_AXIS
#define SHADOWC_BLUR_AXIS 0  // 0 = horizontal (x), 1 = vertical (y)
#endif
#ifndef SHADOWC_BLUR_RADIUS
#define SHADOWC_BLUR_RADIUS 1
#endif
#ifndef SHADOWC_BLUR_WEIGHTS
#define SHADOWC_BLUR_WEIGHTS float[](0.333333343, 0.333333343)  // w[0] centre, w[k] = w[-k]
#endif
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
layout(set = 0, binding = 0, SHADOWC_MOMENTS_FORMAT) readonly uniform image2DArray src;
layout(set = 0, binding = 1, SHADOWC_MOMENTS_FORMAT) writeonly uniform image2DArray dst;

void main() {
  const ivec2 size = imageSize(src).xy;
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  const float w[SHADOWC_BLUR_RADIUS + 1] = SHADOWC_BLUR_WEIGHTS;
  const ivec2 axis = SHADOWC_BLUR_AXIS == 0 ? ivec2(1, 0) : ivec2(0, 1);
  for (int layer = 0; layer < SHADOWC_LAYERS; ++layer) {
    vec4 centre = imageLoad(src, ivec3(p, layer));
    vec4 sum = w[0] * centre;
#if SHADOWC_WARP == 4
    vec2 lo = centre.rr, hi = centre.gg;
#endif
    for (int k = 1; k <= SHADOWC_BLUR_RADIUS; ++k) {
      vec4 a = imageLoad(src, ivec3(clamp(p - k * axis, ivec2(0), size - 1), layer));
      vec4 b = imageLoad(src, ivec3(clamp(p + k * axis, ivec2(0), size - 1), layer));
      sum += w[k] * (a + b);
#if SHADOWC_WARP == 4
      lo = min(lo, vec2(a.r, b.r));
      hi = max(hi, vec2(a.g, b.g));
#endif
    }
#if SHADOWC_WARP == 4
    sum.r = min(lo.x, lo.y);
    sum.g = max(hi.x, hi.y);
#endif
    imageStore(dst, ivec3(p, layer), sum);
  }
}

#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// depth_convert.comp — the engine's hardware light depth -> the normalized linear depth
// L = (z - near) / (far - near) every other pass and the lookup read (frame.glsl). Planned first,
// only for a filter with `depth_input d32|d24` (docs/dsl.md "depth_input"). One invocation per
// texel; the depth-aspect view gives d in [0, 1] for D32 and D24 alike.
//
// With r = near / far, Vulkan's zero-to-one perspective depth is d = (1 - near / z) / (1 - r),
// so L = d near / (d near + (1 - d) far); reverse Z (d' = 1 - d) swaps d and 1 - d. An
// orthographic map (a sun, SHADOWC_DEPTH_ORTHO) stores L itself, reversed 1 - L. Written without
// near / far as a quotient: each product and the sum round once, the one division once, so L is
// within 2 ulp of the exact value of the stored d on hardware that rounds + * / correctly (and
// 1 - d is exact for d >= 1/2, Sterbenz). "Nothing hit" (d = 1, reversed 0) stays exactly 1.
#ifndef SHADOWC_DEPTH_REVERSED
#define SHADOWC_DEPTH_REVERSED 0
#endif
#ifndef SHADOWC_DEPTH_ORTHO
#define SHADOWC_DEPTH_ORTHO 0
#endif

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
#include "frame.glsl"
layout(set = 0, binding = 1) uniform sampler2D hardwareDepth;
layout(set = 0, binding = 2, r32f) writeonly uniform image2D shadowDepthOut;

void main() {
  const ivec2 size = textureSize(hardwareDepth, 0);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  precise float d = texelFetch(hardwareDepth, p, 0).r;
#if SHADOWC_DEPTH_REVERSED
  precise float nearWeight = 1.0 - d, farWeight = d;  // d' = 1 - d
#else
  precise float nearWeight = d, farWeight = 1.0 - d;
#endif
#if SHADOWC_DEPTH_ORTHO
  precise float linear = nearWeight;
#else
  const vec4 params = shadowc_frame().lightParams;  // y near, z far
  precise float a = nearWeight * params.y;
  precise float linear = a / (a + farWeight * params.z);
#endif
  imageStore(shadowDepthOut, p, vec4(linear, 0.0, 0.0, 0.0));
}

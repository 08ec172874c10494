#version 460
#extension GL_GOOGLE_include_directive : require
// @shadowc:specialize
// shade.comp — the camera shade pass: per G-buffer pixel, the soft-shadow visibility of the
// area light (1 = fully lit) from the specialized lookup in lookup/shadowc_lookup.glsl.
// Bindings (set 0) are fixed by the briefing table: 0 frame, 1 gbuffer_position,
// 2 gbuffer_normal, 3 visibility, 4..8 the lookup's resources (declared by the lookup).
// The emitter replaces the marker line above with the filter's #defines and generated tables.

#include "frame.glsl"
#include "lookup/shadowc_lookup.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 1, rgba32f) readonly uniform image2D gbuffer_position;
layout(set = 0, binding = 2, rgba32f) readonly uniform image2D gbuffer_normal;
layout(set = 0, binding = 3, r32f) writeonly uniform image2D visibility;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(visibility);
  if (any(greaterThanEqual(pixel, size))) return;
  vec4 position = imageLoad(gbuffer_position, pixel); SHADOWC_WORK_BEGIN(position.w != 0.0)
  float v = 1.0;  // background (w == 0) is lit
  if (position.w != 0.0) {
    vec3 normal = imageLoad(gbuffer_normal, pixel).xyz;
    v = shadowc_visibility(position.xyz, normal);
  } SHADOWC_NAIVE_STORE_RAW(v)
  // shadowc_visibility already maps NaN to 0 and clamps; kept here so the pass contract
  // (visibility in [0, 1], never NaN) does not depend on the lookup.
  v = (v >= 0.0) ? min(v, 1.0) : 0.0;
  imageStore(visibility, pixel, vec4(v, 0.0, 0.0, 0.0)); SHADOWC_WORK_END
}

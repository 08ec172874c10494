#version 450
#extension GL_GOOGLE_include_directive : require
// lighting.comp — the sample engine's own deferred lighting pass: Lambert N·L from the area
// light's centre times the shadow term of the shadowc filter, read through the includable lookup.
// The engine keeps its own frame block at set 0, binding 0 and hands the lookup the light
// values from it (SHADOWC_FRAME_EXTERNAL); the lookup's images live in set 1 (the filter is
// compiled with --lookup-set 1, see CMakeLists.txt).

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(set = 0, binding = 0, std140) uniform EngineFrame {
  mat4 lightView;     // world -> light view (what the shadow map was rendered with)
  vec4 lightParams;   // x tanHalfFov, y near, z far, w light width
  vec4 lightCentre;   // xyz world position of the area light's centre
  vec4 albedo;        // rgb surface colour
} frame;
layout(set = 0, binding = 1, rgba32f) readonly uniform image2D gPosition;
layout(set = 0, binding = 2, rgba32f) readonly uniform image2D gNormal;
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D shaded;
layout(set = 0, binding = 4, r32f) writeonly uniform image2D shadowTerm;

#define SHADOWC_FRAME_EXTERNAL
#include "vssm_pcf_fallback_lookup.glsl"  // the filter named in CMakeLists.txt

shadowc_Frame shadowc_frame() { return shadowc_Frame(frame.lightView, frame.lightParams); }

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(shaded)))) return;
  vec4 p = imageLoad(gPosition, pixel);
  vec3 colour = vec3(0.0);
  float v = 1.0;
  if (p.w != 0.0) {
    vec3 n = normalize(imageLoad(gNormal, pixel).xyz);
    v = shadowc_visibility(p.xyz, n);
    float nDotL = max(dot(n, normalize(frame.lightCentre.xyz - p.xyz)), 0.0);
    colour = frame.albedo.rgb * nDotL * v;
  }
  imageStore(shaded, pixel, vec4(colour, 1.0));
  imageStore(shadowTerm, pixel, vec4(v, 0.0, 0.0, 0.0));
}

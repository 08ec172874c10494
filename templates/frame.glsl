// frame.glsl — the per-frame interface between the runtime harness and every shadowc pass.
// Its block is mirrored byte for byte by include/shadowc/frame.h (std140). Conventions:
//  * Light view space: origin at the light's centre, +z along the light axis (distance in
//    front of the light), the area light lies in the plane z = 0 with width `lightWidth`
//    (rectangle side or disk diameter; 0 = point light).
//  * The shadow map is a perspective projection from the light centre:
//        uv = 0.5 + 0.5 * p.xy / (p.z * tanHalfFov)
//  * The input depth image stores normalized linear depth d = (z - near) / (far - near).
//  * Kernel widths below are in uv units of the shadow map (PCSS, pcss-blog; vssm-yang2010
//    sec. 3, L7 and L16): the cone from a receiver to the light, cut by the plane of the
//    (assumed planar, light-parallel) occluders.
//  * Everything declared here is prefixed shadowc_ so the lookup fits into an engine's shader.
#ifndef SHADOWC_FRAME_GLSL
#define SHADOWC_FRAME_GLSL

// What the lookup reads of the frame. shadowc_frame() is defined by frame_block.glsl (our
// uniform block, set SHADOWC_SET, binding SHADOWC_BINDING_FRAME) unless the including shader
// defines SHADOWC_FRAME_EXTERNAL: then the engine defines shadowc_frame() from its own data
// (docs/integration.md "The lookup's interface").
struct shadowc_Frame {
  mat4 lightView;    // world -> light view
  vec4 lightParams;  // x tanHalfFov, y near, z far, w lightWidth (world units)
};
shadowc_Frame shadowc_frame();
#ifndef SHADOWC_FRAME_EXTERNAL
#include "frame_block.glsl"
#endif
#if !defined(SHADOWC_LIGHT_ORTHO) && !defined(SHADOWC_LIGHT_CUBE)  // spot; sun, point below
#ifdef SHADOWC_LIGHT_SAMPLES
#include "frame_light_samples.glsl"
#endif
// World position -> (uv, normalized depth d, view z).
vec4 shadowc_lightSpace(vec3 worldPos) {
  vec3 p = (shadowc_frame().lightView * vec4(worldPos, 1.0)).xyz;
  vec2 uv = 0.5 + 0.5 * p.xy / (p.z * shadowc_frame().lightParams.x);
  float d = (p.z - shadowc_frame().lightParams.y) / (shadowc_frame().lightParams.z - shadowc_frame().lightParams.y);
  return vec4(uv, d, p.z);
}

float shadowc_viewZ(float d) { return shadowc_frame().lightParams.y + d * (shadowc_frame().lightParams.z - shadowc_frame().lightParams.y); }

// Light width projected onto the near plane, in uv units.
float shadowc_lightSizeUV(float lightWidth) {
  return lightWidth / (2.0 * shadowc_frame().lightParams.y * shadowc_frame().lightParams.x);
}

// Blocker search width (uv) for a receiver at view depth zr: the cone to the light cut at the
// near plane, the widest cut of any occluder plane.
float shadowc_searchWidthUV(float lightWidth, float zr) {
  return shadowc_lightSizeUV(lightWidth) * (zr - shadowc_frame().lightParams.y) / zr;
}

// Filter width (uv) for a receiver at zr behind a blocker at zb: exact for a planar occluder
// parallel to the light (PCSS penumbra estimate, w = W (zr - zb) / zb at the receiver).
float shadowc_penumbraWidthUV(float lightWidth, float zr, float zb) {
  return shadowc_lightSizeUV(lightWidth) * shadowc_frame().lightParams.y * (zr - zb) / (zb * zr);
}
#elif defined(SHADOWC_LIGHT_CUBE)
#include "frame_cube.glsl"
#else
#include "frame_ortho.glsl"
#endif

#endif

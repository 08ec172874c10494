// frame_ortho.glsl — frame.glsl's light-space functions for a directional light (a sun), under
// SHADOWC_LIGHT_ORTHO (the planner defines it for `light sun(...)`). Conventions:
//  * Light view space: +z along the sun's direction of travel, the origin on a plane in front
//    of the scene; the map is an orthographic projection fitted to the scene's bounds:
//        uv = 0.5 + 0.5 * p.xy / halfExtent        (lightParams.x = halfExtent, world units)
//  * Depth is linear in the orthographic z, d = (z - near) / (far - near), as for a spot.
//  * lightParams.w ("lightWidth") is the slope of the penumbra, 2 tan(angle / 2) for a sun of
//    angular diameter `angle`: a receiver dz behind a planar blocker sees the sun's cone cut
//    the blocker's plane in a disk of diameter dz * 2 tan(angle / 2), so
//        penumbra (world) = (d_r - d_b) * 2 tan(angle / 2)
//    against the perspective form (d_r - d_b) / d_b * lightWidth of a spot.
#ifndef SHADOWC_FRAME_ORTHO_GLSL
#define SHADOWC_FRAME_ORTHO_GLSL
#ifdef SHADOWC_CASCADES  // every function below then reads the frame of the cascade being looked up
#include "frame_cascades.glsl"
#endif

// World position -> (uv, normalized depth d, view z).
vec4 shadowc_lightSpace(vec3 worldPos) {
  vec3 p = (shadowc_frame().lightView * vec4(worldPos, 1.0)).xyz;
  vec2 uv = 0.5 + 0.5 * p.xy / shadowc_frame().lightParams.x;
  float d = (p.z - shadowc_frame().lightParams.y) / (shadowc_frame().lightParams.z - shadowc_frame().lightParams.y);
  return vec4(uv, d, p.z);
}

float shadowc_viewZ(float d) { return shadowc_frame().lightParams.y + d * (shadowc_frame().lightParams.z - shadowc_frame().lightParams.y); }

// A world length across the light's direction, in uv units.
float shadowc_worldToUV(float w) { return w / (2.0 * shadowc_frame().lightParams.x); }

// Blocker search width (uv) for a receiver at view depth zr: the sun's cone from the receiver
// cut at the near plane, the widest cut of any occluder plane.
float shadowc_searchWidthUV(float slope, float zr) {
  return shadowc_worldToUV(slope * max(zr - shadowc_frame().lightParams.y, 0.0));
}

// Filter width (uv) for a receiver at zr behind a blocker at zb: the cone cut at the blocker's
// plane, a disk of diameter D = slope (zr - zb), exact for a planar occluder across the light's
// direction. A box kernel (a SAT box, a grid of taps) stands for that round disk with the box of
// the same second moment, side D sqrt(3) / 2 (a uniform disk of diameter D has variance D^2 / 16
// along any axis, a box of side b has b^2 / 12): across a straight edge its linear ramp is then
// 0.013 RMSE from the disk's profile instead of 0.042 (docs/accuracy.md "Light types"). Poisson
// taps fill a disk and keep D (SHADOWC_SUN_BOX_SCALE 1, the planner's choice).
#ifndef SHADOWC_SUN_BOX_SCALE
#define SHADOWC_SUN_BOX_SCALE 1.0
#endif
float shadowc_penumbraWidthUV(float slope, float zr, float zb) {
  return shadowc_worldToUV(SHADOWC_SUN_BOX_SCALE * slope * max(zr - zb, 0.0));
}

// bias.glsl's two light-dependent functions take their orthographic form (end of bias.glsl);
// the perspective ones it defines first are renamed out of the way, and unused.
#define shadowc_biasedLightPosition shadowc_biasedLightPositionSpot
#define shadowc_bias shadowc_biasSpot

#endif

// frame_cube.glsl — frame.glsl's light-space functions for an omnidirectional point light (a
// sphere of radius R), under SHADOWC_LIGHT_CUBE (the planner defines it for `light point(...)`).
// Design: the six cube faces are perspective maps from the light's centre packed into a 3x3 atlas
// of the one 2D shadow map (cells of N = floor(mapSize / 3) texels; face f = 2 axis + (negative),
// cell (f % 3, f / 3); the third row stays empty), as HDRP packs point-light faces into its atlas.
// Every prefilter and lookup template then runs unchanged on the atlas. Seams: each face is
// rendered with tan(half fov) = lightParams.x (the runtime uses 1.5) instead of 1, so a cell holds
// its face's 90 degrees plus a guard band of the neighbouring faces' directions, seen through this
// face's own projection. A receiver picks the face of its direction's major axis; every kernel is
// clamped to SHADOWC_CUBE_KERNEL_MAX (face uv) so that all its fetches stay in the band: filtering
// across a seam then reads real depths of the right projection, never another cell.
// Conventions:
//  * Light view space: lightView = translation to the light's centre (world axes). For face
//    (axis a, sign s): z_f = s p[a] > 0, x_f = p[(a + 1) % 3], y_f = p[(a + 2) % 3],
//        uv_face = 0.5 + 0.5 (x_f, y_f) / (z_f tanHalf)
//  * Depth is linear in the face's z: d = (z_f - near) / (far - near).
//  * lightParams.w ("lightWidth") is the sphere's diameter 2R; the search and penumbra widths are
//    the spot's (frame.glsl) in the face's perspective form, scaled from face uv to atlas uv.
#ifndef SHADOWC_FRAME_CUBE_GLSL
#define SHADOWC_FRAME_CUBE_GLSL

#ifndef SHADOWC_CUBE_KERNEL_MAX
#define SHADOWC_CUBE_KERNEL_MAX 0.25
#endif

ivec2 shadowc_mapSize();  // kernel.glsl

// Atlas uv of one face's uv: the cell's origin plus uv_face times the cell (N / mapSize).
float shadowc_cubeCell() {
  int s = shadowc_mapSize().x;
  return float(s / 3) / float(s);
}

// World position -> (atlas uv, normalized depth d, face z).
vec4 shadowc_lightSpace(vec3 worldPos) {
  vec3 p = (shadowc_frame().lightView * vec4(worldPos, 1.0)).xyz;
  vec3 q = abs(p);
  int a = (q.x >= q.y && q.x >= q.z) ? 0 : (q.y >= q.z ? 1 : 2);
  float s = p[a] < 0.0 ? -1.0 : 1.0;
  float z = max(s * p[a], 1e-20);
  vec2 xy = vec2(p[(a + 1) % 3], p[(a + 2) % 3]);
  vec2 uvFace = 0.5 + 0.5 * xy / (z * shadowc_frame().lightParams.x);
  int f = 2 * a + (s < 0.0 ? 1 : 0);
  vec2 uv = (vec2(float(f % 3), float(f / 3)) + uvFace) * shadowc_cubeCell();
  float d = (z - shadowc_frame().lightParams.y) / (shadowc_frame().lightParams.z - shadowc_frame().lightParams.y);
  return vec4(uv, d, z);
}

float shadowc_viewZ(float d) { return shadowc_frame().lightParams.y + d * (shadowc_frame().lightParams.z - shadowc_frame().lightParams.y); }

// A width in face uv -> atlas uv, clamped to what the guard band holds.
float shadowc_cubeWidthUV(float faceUV) { return min(faceUV, SHADOWC_CUBE_KERNEL_MAX) * shadowc_cubeCell(); }

// The sphere seen from a receiver is a disk of diameter 2R facing it; in the face's perspective
// form that is the spot's light width projected onto the near plane (face uv).
float shadowc_lightSizeUV(float lightWidth) {
  return lightWidth / (2.0 * shadowc_frame().lightParams.y * shadowc_frame().lightParams.x);
}

// Blocker search width: the cone to the light cut at the near plane (frame.glsl), clamped.
float shadowc_searchWidthUV(float lightWidth, float zr) {
  return shadowc_cubeWidthUV(shadowc_lightSizeUV(lightWidth) * (zr - shadowc_frame().lightParams.y) / zr);
}

// Filter width for a receiver at zr behind a blocker at zb (PCSS, w = W (zr - zb) / zb), clamped.
float shadowc_penumbraWidthUV(float lightWidth, float zr, float zb) {
  return shadowc_cubeWidthUV(shadowc_lightSizeUV(lightWidth) * shadowc_frame().lightParams.y * (zr - zb) / (zb * zr));
}

// bias.glsl's receiver offset takes its cube form (end of bias.glsl); its slope-scaled bias is the
// spot's (L towards the light's centre) unchanged.
#define shadowc_biasedLightPosition shadowc_biasedLightPositionSpot

#endif

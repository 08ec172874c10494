// bias.glsl — receiver depth bias (self-shadowing "acne"). Four policies:
//  constant:      d - b
//  slope-scaled:  d - max(a * (1 - N.L), b)      (pcss-blog: bias grows as the surface
//                                                  turns away from the light)
//  normal offset: move the receiver along N by SHADOWC_NORMAL_OFFSET shadow-map texels (world
//                 size of a texel at the receiver: 2 z tanHalfFov / mapSize), then d - b.
//  receiver plane: every depth tap at texel t compares against the receiver's tangent plane at
//                 t's centre, d + dot(g, t + 0.5 - c) - b, with g = dd/dtexel of that plane
//                 (Isidoro 2006, "Shadow Mapping: GPU-based Tips and Techniques", GDC, the
//                 "receiver plane depth bias"; there g comes from screen-space derivatives,
//                 here from the receiver's normal: the same plane, docs/integration.md).
// The receiver test everywhere is `z < d_biased` (briefing convention).
#ifndef SHADOWC_BIAS_GLSL
#define SHADOWC_BIAS_GLSL

// Light-space position of the (possibly offset) receiver; .w = 0 when it lies behind the light.
vec4 shadowc_biasedLightPosition(vec3 worldPos, vec3 worldNormal) {
  vec3 p = worldPos;
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_NORMAL_OFFSET_KIND || SHADOWC_BIAS_KIND == SHADOWC_BIAS_RECEIVER_PLANE_KIND
  float z0 = (shadowc_frame().lightView * vec4(worldPos, 1.0)).z;
  float texelWorld = 2.0 * max(z0, 0.0) * shadowc_frame().lightParams.x / float(shadowc_mapSize().x);
  p += worldNormal * (SHADOWC_NORMAL_OFFSET * texelWorld);
#endif
  vec3 pl = (shadowc_frame().lightView * vec4(p, 1.0)).xyz;
  return vec4(p, pl.z > 0.0 ? 1.0 : 0.0);
}

float shadowc_bias(vec3 worldPos, vec3 worldNormal) {
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_SLOPE_SCALED_KIND
  vec3 pl = (shadowc_frame().lightView * vec4(worldPos, 1.0)).xyz;
  vec3 nl = mat3(shadowc_frame().lightView) * worldNormal;
  // N.L with L towards the light centre; a zero-length vector gives N.L = 0 (max bias), not NaN.
  float len = length(nl) * length(pl);
  float ndotl = len > 0.0 ? clamp(dot(nl, -pl) / len, 0.0, 1.0) : 0.0;
  return max(SHADOWC_BIAS_SLOPE * (1.0 - ndotl), SHADOWC_BIAS_CONSTANT);
#else
  return SHADOWC_BIAS_CONSTANT;
#endif
}

#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_RECEIVER_PLANE_KIND
vec2 shadowc_rpGradient;  // dd/dtexel of the receiver's tangent plane (normalized depth per texel)
vec2 shadowc_rpCentre;    // the receiver's continuous texel coordinates

// The plane through the receiver with light-view normal n meets the light ray of direction
// s = (x/z, y/z, 1) at view depth z(s) = (n.p) / (n.s), so dz/ds_xy = -z n_xy / (n.s); one texel
// is 2 tanHalfFov / mapSize in s, i.e. 2 z tanHalfFov / mapSize world units at the receiver. For
// an orthographic map (a sun) the rays are all (0, 0, 1) and a texel is 2 halfExtent / mapSize.
// The depth slope |n_xy / (n.s)| is clamped to SHADOWC_BIAS_MAX_SLOPE: a plane seen edge-on by
// the light (n.s -> 0) has an unbounded gradient. The normal's sign does not matter.
void shadowc_receiverPlaneBegin(vec3 worldPos, vec3 worldNormal, vec2 texel) {
  vec3 pl = (shadowc_frame().lightView * vec4(worldPos, 1.0)).xyz;
  vec3 nl = mat3(shadowc_frame().lightView) * worldNormal;
#ifdef SHADOWC_LIGHT_ORTHO
  vec3 ray = vec3(0.0, 0.0, 1.0);
  float texelWorld = 2.0 * shadowc_frame().lightParams.x / float(shadowc_mapSize().x);
#elif defined(SHADOWC_LIGHT_CUBE)
  // A point light: the plane in the receiver's cube face (frame_cube.glsl picks the face by the
  // major axis a of pl, face coordinates (p[a+1], p[a+2], s p[a])), a texel of its atlas cell
  // (N = mapSize / 3 texels per face) 2 z tanHalf / N wide. Taps in the cell's guard band are
  // the same face's projection, so the one plane serves them too.
  vec3 q = abs(pl);
  int a = (q.x >= q.y && q.x >= q.z) ? 0 : (q.y >= q.z ? 1 : 2);
  float sgn = pl[a] < 0.0 ? -1.0 : 1.0;
  pl = vec3(pl[(a + 1) % 3], pl[(a + 2) % 3], max(sgn * pl[a], 1e-20));
  nl = vec3(nl[(a + 1) % 3], nl[(a + 2) % 3], sgn * nl[a]);
  vec3 ray = vec3(pl.xy / pl.z, 1.0);
  float texelWorld = 2.0 * pl.z * shadowc_frame().lightParams.x / float(shadowc_mapSize().x / 3);
#else
  vec3 ray = vec3(pl.xy / pl.z, 1.0);  // pl.z > 0: shadowc_receiver returned before otherwise
  float texelWorld = 2.0 * pl.z * shadowc_frame().lightParams.x / float(shadowc_mapSize().x);
#endif
  float den = dot(nl, ray);
  float lim = max(length(nl.xy) / SHADOWC_BIAS_MAX_SLOPE, 1e-20);  // > 0: no 0/0 for a zero normal
  den = (den < 0.0 ? -1.0 : 1.0) * max(abs(den), lim);
  float range = shadowc_frame().lightParams.z - shadowc_frame().lightParams.y;
  shadowc_rpGradient = -nl.xy / den * (texelWorld / range);
  shadowc_rpCentre = texel;
}

// The depth a tap reading texel t compares against (z < that occludes): the plane at t's centre,
// where the light-depth pass rasterized the texel's depth.
float shadowc_tapDepth(ivec2 t, float d) { return d + dot(shadowc_rpGradient, vec2(t) + 0.5 - shadowc_rpCentre); }
#define SHADOWC_TAP_DEPTH(t, d) shadowc_tapDepth(t, d)

// Lowest and highest offset of the plane over the texel centres of an inclusive rectangle (the
// min-max early out must hold for every tap in it).
vec2 shadowc_receiverPlaneRange(ivec4 rect) {
  vec2 a = shadowc_rpGradient * (vec2(rect.xy) + 0.5 - shadowc_rpCentre);
  vec2 b = shadowc_rpGradient * (vec2(rect.zw) + 0.5 - shadowc_rpCentre);
  vec2 lo = min(a, b);
  vec2 hi = max(a, b);
  return vec2(lo.x + lo.y, hi.x + hi.y);
}
#else
#define SHADOWC_TAP_DEPTH(t, d) d
#endif

#ifdef SHADOWC_LIGHT_ORTHO
// A sun (frame_ortho.glsl): every receiver sees the light along -z of the light view, and a texel
// is 2 halfExtent / mapSize wide at any depth.
#undef shadowc_biasedLightPosition
#undef shadowc_bias
vec4 shadowc_biasedLightPosition(vec3 worldPos, vec3 worldNormal) {
  vec3 p = worldPos;
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_NORMAL_OFFSET_KIND || SHADOWC_BIAS_KIND == SHADOWC_BIAS_RECEIVER_PLANE_KIND
  float texelWorld = 2.0 * shadowc_frame().lightParams.x / float(shadowc_mapSize().x);
  p += worldNormal * (SHADOWC_NORMAL_OFFSET * texelWorld);
#endif
  vec3 pl = (shadowc_frame().lightView * vec4(p, 1.0)).xyz;
  return vec4(p, pl.z > 0.0 ? 1.0 : 0.0);
}

float shadowc_bias(vec3 worldPos, vec3 worldNormal) {
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_SLOPE_SCALED_KIND
  vec3 nl = mat3(shadowc_frame().lightView) * worldNormal;
  float len = length(nl);
  float ndotl = len > 0.0 ? clamp(-nl.z / len, 0.0, 1.0) : 0.0;
  return max(SHADOWC_BIAS_SLOPE * (1.0 - ndotl), SHADOWC_BIAS_CONSTANT);
#else
  return SHADOWC_BIAS_CONSTANT;
#endif
}
#endif


#ifdef SHADOWC_LIGHT_CUBE
// A point light (frame_cube.glsl): L towards the light's centre as for a spot, a texel of the
// receiver's face 2 z_f tanHalf / N wide (N = the atlas cell), and every direction is in front.
#undef shadowc_biasedLightPosition
vec4 shadowc_biasedLightPosition(vec3 worldPos, vec3 worldNormal) {
  vec3 p = worldPos;
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_NORMAL_OFFSET_KIND || SHADOWC_BIAS_KIND == SHADOWC_BIAS_RECEIVER_PLANE_KIND
  float zf = shadowc_lightSpace(worldPos).w;
  float texelWorld = 2.0 * zf * shadowc_frame().lightParams.x / float(shadowc_mapSize().x / 3);
  p += worldNormal * (SHADOWC_NORMAL_OFFSET * texelWorld);
#endif
  return vec4(p, 1.0);
}
#endif

#endif

// bias.glsl — receiver depth bias (self-shadowing "acne"). Three policies:
//  constant:      d - b
//  slope-scaled:  d - max(a * (1 - N.L), b)      (pcss-blog.txt: bias grows as the surface
//                                                  turns away from the light)
//  normal offset: move the receiver along N by SHADOWC_NORMAL_OFFSET shadow-map texels (world
//                 size of a texel at the receiver: 2 z tanHalfFov / mapSize), then d - b.
// The receiver test everywhere is `z < d_biased` (briefing convention).
#ifndef SHADOWC_BIAS_GLSL
#define SHADOWC_BIAS_GLSL

// Light-space position of the (possibly offset) receiver; .w = 0 when it lies behind the light.
vec4 shadowc_biasedLightPosition(vec3 worldPos, vec3 worldNormal) {
  vec3 p = worldPos;
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_NORMAL_OFFSET_KIND
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


#ifdef SHADOWC_LIGHT_ORTHO
// A sun (frame_ortho.glsl): every receiver sees the light along -z of the light view, and a texel
// is 2 halfExtent / mapSize wide at any depth.
#undef shadowc_biasedLightPosition
#undef shadowc_bias
vec4 shadowc_biasedLightPosition(vec3 worldPos, vec3 worldNormal) {
  vec3 p = worldPos;
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_NORMAL_OFFSET_KIND
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
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_NORMAL_OFFSET_KIND
  float zf = shadowc_lightSpace(worldPos).w;
  float texelWorld = 2.0 * zf * shadowc_frame().lightParams.x / float(shadowc_mapSize().x / 3);
  p += worldNormal * (SHADOWC_NORMAL_OFFSET * texelWorld);
#endif
  return vec4(p, 1.0);
}
#endif

#endif

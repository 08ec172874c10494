// cascades.glsl — a cascaded sun's visibility (frame_cascades.glsl): pick the cascade of the
// receiver's camera depth, evaluate the filter in it, and inside the blend band before its far
// split mix linearly with the next cascade, so the change of resolution at a border is a ramp
// over SHADOWC_CASCADE_BLEND of the cascade's depth range instead of a step. Included at the end
// of shadowc_lookup.glsl, after shadowc_visibilityInCascade (the renamed one-map lookup).
#ifndef SHADOWC_CASCADES_GLSL
#define SHADOWC_CASCADES_GLSL

#undef shadowc_visibility

float shadowc_visibility(vec3 worldPos, vec3 worldNormal) {
  vec4 row = shadowc_cameraDepthRow();
  float depth = dot(row.xyz, worldPos) + row.w;
  // Far splits increase with the index: the cascade is the number of splits the depth is past.
  int c = 0;
  for (int i = 0; i < SHADOWC_CASCADES - 1; ++i) c += depth > shadowc_cascadeData(i).w ? 1 : 0;
  shadowc_cascade = c;
  float v = shadowc_visibilityInCascade(worldPos, worldNormal);
  if (c + 1 < SHADOWC_CASCADES && SHADOWC_CASCADE_BLEND > 0.0) {
    float far = shadowc_cascadeData(c).w;
    float near = c == 0 ? shadowc_cascadeInfo().y : shadowc_cascadeData(max(c - 1, 0)).w;
    float band = SHADOWC_CASCADE_BLEND * (far - near);
    float t = band > 0.0 ? (depth - (far - band)) / band : 0.0;
    if (t > 0.0) {  // the runtime fits cascade c + 1 to cover this band too (cascade_setup.cpp)
      shadowc_cascade = c + 1;
      v = mix(v, shadowc_visibilityInCascade(worldPos, worldNormal), min(t, 1.0));
    }
  }
  shadowc_cascade = 0;
  return v;
}

#undef shadowc_frame

#endif

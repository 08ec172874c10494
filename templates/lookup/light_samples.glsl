// light_samples.glsl — `light_samples N`: the shadowing term as the reference estimates it
// (docs/scenes.md "Ground truth"), from N hard views of the light instead of N rays. Each view i
// (frame_light_samples.glsl) stands for an equal patch of the light around s_i; its visibility
// v_i is the filter's PCF of that view's map, and
//     V = sum_i k_i v_i / sum_i k_i  over the views in front of the receiver's tangent plane,
//     k_i = (n . (s_i - p))+ cos_light / r^4 = (n . (s_i - p))+ q_z / |q|^4,  q = p - s_i,
// the form factor cos_receiver cos_light / r^2 of the patch (`weights form_factor`), or k_i = 1
// (`weights uniform`: the visible fraction of the light). A midpoint rule over the light: it
// converges to the reference as N grows. Included at the end of shadowc_lookup.glsl, after
// shadowc_visibilityFromSample (the renamed one-view lookup).
#ifndef SHADOWC_LIGHT_SAMPLES_GLSL
#define SHADOWC_LIGHT_SAMPLES_GLSL

#undef shadowc_visibility
#undef shadowc_frame

float shadowc_visibility(vec3 worldPos, vec3 worldNormal) {
  vec3 p = (shadowc_frame().lightView * vec4(worldPos, 1.0)).xyz;
  vec3 n = mat3(shadowc_frame().lightView) * worldNormal;
  float width = shadowc_lightWidth();  // the same in every view's frame
  float lit = 0.0, total = 0.0;
  for (int i = 0; i < SHADOWC_LIGHT_SAMPLES; ++i) {
    vec2 point = shadowc_lightSampleOffsets[i] * width;
    vec3 q = p - vec3(point, 0.0);
    float facing = -dot(n, q);
    // Written so that NaN counts as behind: the patch is not part of the shadowing term.
    if (!(facing > 0.0) || !(q.z > 0.0)) continue;
#if SHADOWC_LIGHT_SAMPLES_WEIGHTED
    float r2 = dot(q, q);
    float k = facing * q.z / (r2 * r2);
#else
    float k = 1.0;
#endif
    shadowc_lightSample = i;
    shadowc_lightSamplePoint = point;
    lit += k * shadowc_visibilityFromSample(worldPos, worldNormal);
    total += k;
  }
  shadowc_lightSample = 0;
  shadowc_lightSamplePoint = vec2(0.0);
  // No patch in front: the shadowing term is 0 there (`backface shadowed`), or lit (`filtered`).
  float v = total > 0.0 ? lit / total : (SHADOWC_BACKFACE_SHADOWED != 0 ? 0.0 : 1.0);
  return SHADOWC_NAIVE_SANITIZE(v);
}

#endif

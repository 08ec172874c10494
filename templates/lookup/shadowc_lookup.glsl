// shadowc_lookup.glsl — the visibility lookup of a shadowc filter:
//   float shadowc_visibility(vec3 worldPos, vec3 worldNormal)   // 1 = fully lit, in [0, 1]
// Specialized by the #defines of defaults.glsl (set by compiler/emit/lookup_specialization.cpp
// at the `@shadowc:specialize` marker of the including shader). The emitter ships the
// preprocessed text as <filter>_lookup.glsl so an engine can #include it into its own shader;
// it needs frame.glsl (shadowc_frame(): our block at set SHADOWC_SET, binding
// SHADOWC_BINDING_FRAME, or the engine's own data with SHADOWC_FRAME_EXTERNAL) and the
// resources of resources.glsl (set SHADOWC_SET, bindings SHADOWC_BINDING_*). Every global is
// prefixed shadowc_ (compiler/emit/lookup_interface.h places and checks them).
#ifndef SHADOWC_LOOKUP_GLSL
#define SHADOWC_LOOKUP_GLSL

#include "lookup/defaults.glsl"
#include "frame.glsl"
#include "lookup/resources.glsl"
#include "lookup/kernel.glsl"
#include "lookup/bias.glsl"
#if SHADOWC_HAS_POISSON_PCF || SHADOWC_HAS_POISSON_BLOCKER
#include "lookup/rotation.glsl"
#endif
#if SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_PCF || SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_PCSS || SHADOWC_CONTACT
#include "lookup/pcf.glsl"
#endif
#if SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_PCSS || SHADOWC_BLOCKER_KIND == SHADOWC_BLOCKER_SEARCH
#include "lookup/pcss.glsl"
#endif
#if SHADOWC_HAS_MINMAX
#include "lookup/minmax.glsl"
#endif
#if SHADOWC_HAS_MOMENTS
#include "lookup/chebyshev.glsl"
#if SHADOWC_WARP == SHADOWC_WARP_EXP
#include "lookup/esm.glsl"
#elif SHADOWC_WARP == SHADOWC_WARP_EVSM2 || SHADOWC_WARP == SHADOWC_WARP_EVSM4
#include "lookup/evsm.glsl"
#elif SHADOWC_WARP == SHADOWC_WARP_POWER_CDF
#include "lookup/power_cdf.glsl"
#elif SHADOWC_WARP == SHADOWC_WARP_MSM
#include "lookup/msm.glsl"
#endif
#if SHADOWC_HAS_SAT
#include "lookup/sat.glsl"
#endif
#include "lookup/layered.glsl"
#include "lookup/moments_filter.glsl"
#endif
#if SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_VSSM
#include "lookup/vssm.glsl"
#endif

// The receiver for a world position, with the bias applied. Returns false when the point is
// behind the light or outside the shadow map's frustum (then it is lit: nothing was rendered
// that could shadow it).
bool shadowc_receiver(vec3 worldPos, vec3 worldNormal, out shadowc_Receiver r) {
  vec4 p = shadowc_biasedLightPosition(worldPos, worldNormal);
  r.worldPos = worldPos;
  r.lightWidth = shadowc_lightWidth();
#if SHADOWC_WEIGHTED
  shadowc_weightsReceiver(worldPos, worldNormal);  // the light patches' weights (kernel.glsl)
#endif
  if (p.w == 0.0) return false;
  vec4 ls = shadowc_lightSpace(p.xyz);
  r.uv = ls.xy;
  r.texel = ls.xy * vec2(shadowc_mapSize());
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_RECEIVER_PLANE_KIND
  shadowc_receiverPlaneBegin(p.xyz, worldNormal, r.texel);
#endif
  r.d = ls.z - shadowc_bias(worldPos, worldNormal);
  r.zr = max(ls.w, shadowc_frame().lightParams.y);
  // Written so that NaN coordinates also count as outside.
  return all(greaterThanEqual(ls.xy, vec2(0.0))) && all(lessThanEqual(ls.xy, vec2(1.0)));
}

#if SHADOWC_EARLY_OUT && SHADOWC_HAS_MINMAX
// Texel rectangle whose texels can influence the result: the early out must cover all of it to
// be exact (the widest kernel, grown by one texel for bilinear taps and rounding, and by the
// prefilter's blur radius, SHADOWC_EARLY_OUT_GROW: a blurred moment holds texels that far
// away; stability case minmax_blur_footprint).
ivec4 shadowc_influenceRect(shadowc_Receiver r) {
#if SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_PCSS || SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_VSSM || SHADOWC_KERNEL_PENUMBRA
  ivec4 rect = shadowc_kernelRect(r.texel, shadowc_searchTexels(r));
#else
  ivec4 rect = shadowc_kernelRect(r.texel, SHADOWC_KERNEL_FIXED_TEXELS);
#endif
  ivec2 last = shadowc_mapSize() - 1;
  const int grow = 1 + SHADOWC_EARLY_OUT_GROW;
  return ivec4(max(rect.xy - grow, ivec2(0)), min(rect.zw + grow, last));
}
#endif

#if SHADOWC_BACKFACE_SHADOWED
// True when no point of the light lies in front of the receiver's tangent plane: there the
// shadowing term is 0 by definition (docs/scenes.md "Ground truth"; the N.L term
// already darkens it in a renderer), while a shadow map sees the receiver's own surface, or,
// after a bias or normal offset, nothing at all (lit back faces). One test, no fetch:
//   spot:  the light's rectangle (or the disk inside it) of width w in the light view's z = 0
//          plane, centred at the origin: max over it of n.(q - p) = -n.p + w/2 (|n_x| + |n_y|)
//          (the rectangle's bound, so a disk light is never zeroed wrongly);
//   sun:   directions within the cap of half-angle a around -z (tan a = w / 2, frame_ortho.glsl):
//          some lies in front unless the angle between n and -z is >= 90 deg + a, n_z >= |n| sin a;
//   point: the sphere of radius w/2 at the origin: max = -n.p + |n| w/2.
bool shadowc_lightBehind(vec3 worldPos, vec3 worldNormal) {
  vec3 p = (shadowc_frame().lightView * vec4(worldPos, 1.0)).xyz;
  vec3 n = mat3(shadowc_frame().lightView) * worldNormal;
  float h = 0.5 * shadowc_lightWidth();
#ifdef SHADOWC_LIGHT_ORTHO
  float len = length(n);
  return len > 0.0 && n.z >= len * h / sqrt(1.0 + h * h);
#elif defined(SHADOWC_LIGHT_CUBE)
  return dot(n, -p) + h * length(n) <= 0.0;
#else
  return dot(n, -p) + h * (abs(n.x) + abs(n.y)) <= 0.0;
#endif
}
#endif

float shadowc_visibility(vec3 worldPos, vec3 worldNormal) {
#if SHADOWC_BACKFACE_SHADOWED
  if (shadowc_lightBehind(worldPos, worldNormal)) return 0.0;
#endif
  shadowc_Receiver r;
  if (!shadowc_receiver(worldPos, worldNormal, r)) return 1.0;
#if SHADOWC_EARLY_OUT && SHADOWC_HAS_MINMAX
  // vssm-yang2010 sec. 6.1 / Algorithm 1 L8-L10.
  ivec4 rect = shadowc_influenceRect(r);
#if SHADOWC_BIAS_KIND == SHADOWC_BIAS_RECEIVER_PLANE_KIND
  vec2 span = r.d + shadowc_receiverPlaneRange(rect);
#else
  vec2 span = vec2(r.d);
#endif
  float early = shadowc_earlyOut(rect, span.x, span.y); SHADOWC_COUNT(SHADOWC_WORK_EARLY_OUTS, early >= 0.0)
  if (early >= 0.0) return early;
#endif
#if SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_VSSM
  float v = shadowc_vssm(r);
#elif SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_MOMENTS
  float v = shadowc_momentsTechnique(r);
#elif SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_PCSS
  float v = shadowc_pcss(r);
#else
#if SHADOWC_KERNEL_PENUMBRA
  float v = shadowc_pcf(r, shadowc_searchTexels(r));  // no blocker estimate: the widest penumbra
#else
  float v = shadowc_pcf(r, SHADOWC_KERNEL_FIXED_TEXELS);
#endif
#endif
  return SHADOWC_NAIVE_SANITIZE(v);
}

#ifdef SHADOWC_CASCADES
#include "lookup/cascades.glsl"
#endif
#ifdef SHADOWC_LIGHT_SAMPLES
#include "lookup/light_samples.glsl"
#endif
#endif

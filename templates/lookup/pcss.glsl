// pcss.glsl — percentage-closer soft shadows (Fernando 2005; pcss-blog):
//  1. blocker search: average depth of the texels that occlude the receiver, over the search
//     region (the light cone cut at the near plane, frame.glsl), with SHADOWC_BLOCKER_TAPS taps
//     on a grid or a rotated Poisson disk;
//  2. penumbra estimate: w = W (zr - zb) / zb scaled to the map (frame.glsl);
//  3. PCF with that kernel (pcf.glsl).
// Guards: no blocker found -> lit (no division by a zero count); zb is kept >= near in
// shadowc_penumbraTexels so the width never divides by 0.
#ifndef SHADOWC_PCSS_GLSL
#define SHADOWC_PCSS_GLSL

// Average occluder depth over a search region `w` texels wide, or -1 when nothing occludes; with
// `weights form_factor` each occluding tap counts with its light patch's weight (kernel.glsl).
float shadowc_blockerSearch(shadowc_Receiver r, float w) {
  float sum = 0.0;
  float count = 0.0;
#if SHADOWC_BLOCKER_PATTERN == 1
#if !SHADOWC_HAS_POISSON_BLOCKER
#error "Poisson blocker search needs the generated shadowc_poissonBlocker taps"
#endif
  vec2 rot = shadowc_rotation(r.worldPos);
  for (int i = 0; i < SHADOWC_BLOCKER_TAPS; ++i) {
    vec2 o = shadowc_rotate(shadowc_poissonBlocker[i], rot) * 0.5;  // the tap as a fraction of the region
    ivec2 t = ivec2(floor(r.texel + o * w));
    float z = shadowc_depthAt(t);
#if SHADOWC_WEIGHTED
    float k = shadowc_lightWeight(o * shadowc_lightWidth());  // the tap's light patch (kernel.glsl)
    if (z < SHADOWC_TAP_DEPTH(t, r.d)) {
      sum += k * z;
      count += k;
    }
#else
    if (z < SHADOWC_TAP_DEPTH(t, r.d)) {
      sum += z;
      count += 1.0;
    }
#endif
  }
#else
  const int n = SHADOWC_BLOCKER_GRID_N;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      vec2 pos = r.texel + (vec2(i, j) + 0.5 - 0.5 * float(n)) * (w / float(n));
      ivec2 t = ivec2(floor(pos));
      float z = shadowc_depthAt(t);
#if SHADOWC_WEIGHTED
      float k = shadowc_tapWeight(pos, r.texel, w);
      if (z < SHADOWC_TAP_DEPTH(t, r.d)) {
        sum += k * z;
        count += k;
      }
#else
      if (z < SHADOWC_TAP_DEPTH(t, r.d)) {
        sum += z;
        count += 1.0;
      }
#endif
    }
#endif
  return count > 0.0 ? sum / count : -1.0;
}

#if SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_PCSS
float shadowc_pcss(shadowc_Receiver r) {
  float zb = shadowc_blockerSearch(r, shadowc_searchTexels(r)); SHADOWC_COUNT(SHADOWC_WORK_BLOCKERS_FOUND, zb >= 0.0)
  if (zb < 0.0) return 1.0;
  return shadowc_pcf(r, shadowc_penumbraTexels(r, zb));
}
#endif

#endif

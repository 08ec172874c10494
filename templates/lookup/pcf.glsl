// pcf.glsl — percentage-closer filtering on the depth map (Reeves et al. 1987; pcss-blog).
// The average of depth-test results over a kernel `w` texels wide centred at `c`:
//  grid:     n x n texelFetch at the centres of an n x n partition of the kernel
//  bilinear: the same n x n positions, each the bilinear weight of its 4 neighbouring tests
//            (smooth in c, no texel-grid stepping)
//  poisson:  k taps of a Poisson disk of radius w/2, rotated per world position (rotation.glsl)
// No division by anything but the (constant, >= 1) tap count, or with `weights form_factor` the
// sum of the taps' weights (each > 0, kernel.glsl): no NaN possible.
#ifndef SHADOWC_PCF_GLSL
#define SHADOWC_PCF_GLSL

// 1 when the texel does not occlude a receiver at biased depth d (with the receiver-plane bias,
// the plane's depth at t: bias.glsl).
float shadowc_litTexel(ivec2 t, float d) { return shadowc_depthAt(t) < SHADOWC_TAP_DEPTH(t, d) ? 0.0 : 1.0; }

#if SHADOWC_PCF_PATTERN == SHADOWC_PATTERN_BILINEAR || SHADOWC_CONTACT
float shadowc_litBilinear(vec2 pos, float d) {
  vec2 p = pos - 0.5;
  vec2 f = fract(p);
  ivec2 i = ivec2(floor(p));
  float a = shadowc_litTexel(i, d);
  float b = shadowc_litTexel(i + ivec2(1, 0), d);
  float e = shadowc_litTexel(i + ivec2(0, 1), d);
  float g = shadowc_litTexel(i + ivec2(1, 1), d);
  return mix(mix(a, b, f.x), mix(e, g, f.x), f.y);
}
#endif

// With `weights form_factor` each tap counts with the weight of its light patch (kernel.glsl) and
// the sum divides by the weights' total; without, by the tap count (the same loop either way).
#if SHADOWC_PCF_PATTERN == SHADOWC_PATTERN_GRID
float shadowc_pcfGrid(vec2 c, float w, float d, int n) {
  float lit = 0.0;
#if SHADOWC_WEIGHTED
  float total = 0.0;
#endif
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      vec2 pos = c + (vec2(i, j) + 0.5 - 0.5 * float(n)) * (w / float(n));
#if SHADOWC_WEIGHTED
      float k = shadowc_tapWeight(pos, c, w);
      lit += k * shadowc_litTexel(ivec2(floor(pos)), d);
      total += k;
#else
      lit += shadowc_litTexel(ivec2(floor(pos)), d);
#endif
    }
#if SHADOWC_WEIGHTED
  return lit / total;
#else
  return lit / float(n * n);
#endif
}
#endif

#if SHADOWC_PCF_PATTERN == SHADOWC_PATTERN_BILINEAR || SHADOWC_CONTACT
float shadowc_pcfBilinearGrid(vec2 c, float w, float d, int n) {
  float lit = 0.0;
#if SHADOWC_WEIGHTED
  float total = 0.0;
#endif
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      vec2 pos = c + (vec2(i, j) + 0.5 - 0.5 * float(n)) * (w / float(n));
#if SHADOWC_WEIGHTED
      float k = shadowc_tapWeight(pos, c, w);
      lit += k * shadowc_litBilinear(pos, d);
      total += k;
#else
      lit += shadowc_litBilinear(pos, d);
#endif
    }
#if SHADOWC_WEIGHTED
  return lit / total;
#else
  return lit / float(n * n);
#endif
}
#endif

#if SHADOWC_HAS_POISSON_PCF
float shadowc_pcfPoisson(vec2 c, float w, float d, vec2 rot) {
  float lit = 0.0;
#if SHADOWC_WEIGHTED
  float total = 0.0;
#endif
  for (int i = 0; i < SHADOWC_PCF_TAPS; ++i) {
    vec2 o = shadowc_rotate(shadowc_poissonPcf[i], rot) * 0.5;  // the tap as a fraction of the kernel
#if SHADOWC_WEIGHTED
    float k = shadowc_lightWeight(o * shadowc_lightWidth());
    lit += k * shadowc_litTexel(ivec2(floor(c + o * w)), d);
    total += k;
#else
    lit += shadowc_litTexel(ivec2(floor(c + o * w)), d);
#endif
  }
#if SHADOWC_WEIGHTED
  return lit / total;
#else
  return lit / float(SHADOWC_PCF_TAPS);
#endif
}
#endif

#if SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_PCF || SHADOWC_TECHNIQUE == SHADOWC_TECHNIQUE_PCSS
// The filter's PCF: pattern and size chosen by the specialization.
float shadowc_pcf(shadowc_Receiver r, float w) {
#if SHADOWC_PCF_PATTERN == SHADOWC_PATTERN_POISSON
#if !SHADOWC_HAS_POISSON_PCF
#error "Poisson PCF needs the generated shadowc_poissonPcf taps"
#endif
  return shadowc_pcfPoisson(r.texel, w, r.d, shadowc_rotation(r.worldPos));
#elif SHADOWC_PCF_PATTERN == SHADOWC_PATTERN_BILINEAR
  return shadowc_pcfBilinearGrid(r.texel, w, r.d, SHADOWC_PCF_N);
#else
  return shadowc_pcfGrid(r.texel, w, r.d, SHADOWC_PCF_N);
#endif
}
#endif

#endif

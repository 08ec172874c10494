// esm.glsl — exponential shadow maps (Salvi 2008; lauritzen2008 sec. 7). The moments image holds
// E[exp(c (z - 1))] (kept <= 1 for precision, briefing table); the visibility is
//   v = E[exp(c (z - 1))] / exp(c (d - 1)) = exp(log E - c (d - 1)), clamped to <= 1.
// Guards: evaluated in log space with the exponent clamped to <= 0, so exp never overflows
// whatever d is; log of a zero (underflowed) moment is floored at log(1e-30).
#ifndef SHADOWC_ESM_GLSL
#define SHADOWC_ESM_GLSL

float shadowc_esm(float expMoment, float d) {
  float e = log(max(expMoment, 1e-30)) - SHADOWC_EXP_POSITIVE * (d - 1.0);
  return (e >= 0.0) ? 1.0 : exp(max(e, -87.0));
}

#endif

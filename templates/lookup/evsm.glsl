// evsm.glsl — exponential variance shadow maps (lauritzen2008 sec. 7). Moments per texel
// (briefing table), with depths d in [0, 1]:
//   evsm2: (e+, e+^2)                e+ = exp(c+ (d - 1))    in (0, 1]
//   evsm4: (e+, e+^2, -e-, e-^2)     e- = exp(-c- (d - 1))   in [1, exp(c-)]
// Each warp is monotonic in d, so Chebyshev (chebyshev.glsl) on the warped receiver gives an
// upper bound of the lit fraction; evsm4 takes the min of the positive and negative bounds.
// The minimum variance is scaled by the warp's slope squared (d warp/d d)^2 = (c e)^2, so one
// depth-space floor means the same everywhere.
// Guards: the receiver depth is clamped to [0, 1] before warping, so the receiver warp is
// bounded by exp(c) which the compiler keeps finite (c <= 42 fp32, docs/dsl.md "Exponent limits").
#ifndef SHADOWC_EVSM_GLSL
#define SHADOWC_EVSM_GLSL

float shadowc_evsm(vec4 m, float d, float minVariance) {
  float dc = clamp(d, 0.0, 1.0);
  float ep = exp(SHADOWC_EXP_POSITIVE * (dc - 1.0));
  float sp = SHADOWC_EXP_POSITIVE * ep;
  float v = shadowc_reduceBleeding(shadowc_chebyshev(m.x, m.y, ep, minVariance * sp * sp));
#if SHADOWC_WARP == SHADOWC_WARP_EVSM4
  float en = exp(-SHADOWC_EXP_NEGATIVE * (dc - 1.0));
  float sn = SHADOWC_EXP_NEGATIVE * en;
  v = min(v, shadowc_reduceBleeding(shadowc_chebyshev(m.z, m.w, -en, minVariance * sn * sn)));
#endif
  return v;
}

#endif

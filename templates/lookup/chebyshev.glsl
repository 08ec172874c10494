// chebyshev.glsl — the variance shadow map estimate (vssm-yang2010 eq. 1; vsm-tutorial;
// lauritzen2008 eq. 3): for moments (mu, E[x^2]) of the occluder depths over a kernel and a
// receiver at t,
//   p(t) = 1                                 if t <= mu
//   p(t) = s^2 / (s^2 + (t - mu)^2)          otherwise, s^2 = max(E[x^2] - mu^2, minVariance)
// an upper bound of the lit fraction P(x >= t). Light bleeding reduction (vsm-tutorial,
// Lauritzen): linstep(a, 1, p) = clamp((p - a) / (1 - a), 0, 1) with a < 1 (clamped by the
// compiler).
// Guards: the variance floor keeps the denominator > 0 when t > mu; a NaN or infinite input
// (e.g. an overflowed EVSM moment) fails every comparison and ends in shadowc_unit -> 0.
#ifndef SHADOWC_CHEBYSHEV_GLSL
#define SHADOWC_CHEBYSHEV_GLSL

float shadowc_chebyshev(float mean, float meanSq, float t, float minVariance) { SHADOWC_COUNT(SHADOWC_WORK_MOMENT_BOUNDS, 1)
  float variance = max(meanSq - mean * mean, minVariance);
  float dt = t - mean;
  float denom = variance + dt * dt;
  float p = denom > 0.0 ? shadowc_unit(variance / denom) : 0.0;
  return t <= mean ? 1.0 : p;
}

float shadowc_reduceBleeding(float p) {
#if SHADOWC_BLEEDING_ON
  return clamp((p - SHADOWC_BLEEDING) / (1.0 - SHADOWC_BLEEDING), 0.0, 1.0);
#else
  return p;
#endif
}

#endif

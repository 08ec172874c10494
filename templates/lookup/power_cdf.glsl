// power_cdf.glsl — power-CDF shadow maps (power-cdf sec. 3). From the filtered
// (min, max, mean) of the occluder depths the CDF is approximated by F(t) = t^beta with
//   t = (z - zmin) / (zmax - zmin),  beta = (mean - zmin) / (zmax - mean)        (eq. 3)
// and the visibility, normalized so that a planar receiver at the mean depth is lit, is
//   v = (1 - t^beta) / (1 - (beta / (beta + 1))^beta)  if t > beta / (beta + 1), else 1  (eq. 4)
// Guards: zmax - zmin ~ 0 (a single depth) is a plain depth test; beta is clamped to
// [1e-4, 1e4] so zmax - mean -> 0 does not divide by zero; the denominator of eq. 4 tends to 0
// only as beta -> 0, where the numerator vanishes faster, so it is floored at 1e-7 and the
// result clamped to [0, 1].
#ifndef SHADOWC_POWER_CDF_GLSL
#define SHADOWC_POWER_CDF_GLSL

float shadowc_powerCdf(vec3 m, float d) {
  float zmin = min(m.x, m.y);
  float zmax = max(m.x, m.y);
  float mean = clamp(m.z, zmin, zmax);
  if (d <= mean) return 1.0;
  float dz = zmax - zmin;
  if (dz <= 1e-7 || d >= zmax) return 0.0;  // d > mean and, then, d beyond every occluder
  float t = clamp((d - zmin) / dz, 0.0, 1.0);
  float beta = clamp((mean - zmin) / max(zmax - mean, 1e-7), 1e-4, 1e4);
  float tMean = beta / (beta + 1.0);
  float denom = max(1.0 - pow(tMean, beta), 1e-7);
  return shadowc_unit((1.0 - pow(t, beta)) / denom);
}

#endif

// msm.glsl — Hamburger 4MSM (Peters & Klein 2015, "Moment Shadow Mapping", I3D, Algorithm 3):
// from the filtered power moments b = E[(z, z^2, z^3, z^4)] of the kernel and a receiver at zf,
// the sharp lower bound G of the occluded fraction P(z < zf) over every depth distribution
// with those moments; the visibility is 1 - G. Four moments reproduce any two depths exactly
// (sec. 3), so two stacked occluders do not bleed light as VSM's Chebyshev bound does.
//   1. b' = (1 - alpha) b + alpha b*                                 the moment bias
//   2. B c = (1, zf, zf^2), B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]] by B = L D L^T
//   3. z2 <= z3: the roots of c3 z^2 + c2 z + c1 = 0
//   4-6. G = 0 if zf <= z2; the weight of z2 if zf <= z3; else 1 - the weight of zf
// b* = moments of 0.315 d(0) + 0.37 d(1/2) + 0.315 d(1): Peters et al.'s (0, 0.63, 0, 0.63) for
// depths in [-1, 1], mapped to [0, 1] (the bound is invariant under that affine map). It has
// three support points, so B(b') >= alpha B(b*) is positive definite for every valid b, even a
// single depth (zero variance) or depths exactly 0 and 1; alpha (SHADOWC_MSM_BIAS, from the
// checker: 3e-5 for 16-bit storage as in the paper) must also cover the storage rounding.
// Guards: D22 and D33 are floored at 1e-20 (moments made invalid by rounding beyond what the bias
// covers give a finite, clamped answer, not NaN); the roots come from the cancellation-free
// quadratic formula and are clamped to +-1e4, which also covers c3 -> 0 (a root at infinity:
// the ratios below tend to their limits); G goes through shadowc_unit (NaN -> 0).
#ifndef SHADOWC_MSM_GLSL
#define SHADOWC_MSM_GLSL

#include "passes/msm_moments.glsl"

#ifndef SHADOWC_MSM_BIAS
#define SHADOWC_MSM_BIAS 3e-5
#endif

const vec4 shadowc_msmBiasTarget = vec4(0.5, 0.4075, 0.36125, 0.338125);

// G of Algorithm 3 for power moments m and receiver depth zf, in [0, 1].
float shadowc_msmShadow(vec4 m, float zf) { SHADOWC_COUNT(SHADOWC_WORK_MOMENT_BOUNDS, 1)
  vec4 b = mix(m, shadowc_msmBiasTarget, SHADOWC_MSM_BIAS);  // step 1
  // Step 2: L21 = b1, L31 = b2, D22 = b2 - b1^2, L32 = (b3 - b1 b2) / D22,
  // D33 = b4 - b2^2 - L32^2 D22; forward substitution, scaling by D^-1, back substitution.
  float d22 = max(b.y - b.x * b.x, 1e-20);
  float l32 = (b.z - b.x * b.y) / d22;
  float d33 = max(b.w - b.y * b.y - l32 * l32 * d22, 1e-20);
  float c2 = zf - b.x;
  float c3 = zf * zf - b.y - l32 * c2;
  c2 /= d22;
  c3 /= d33;
  c2 -= l32 * c3;
  float c1 = 1.0 - b.x * c2 - b.y * c3;
  // Step 3: real roots for a positive definite B; q never vanishes unless c2 = c1 = 0.
  float disc = max(c2 * c2 - 4.0 * c3 * c1, 0.0);
  float q = -0.5 * (c2 + (c2 < 0.0 ? -sqrt(disc) : sqrt(disc)));
  float r0 = clamp(q / c3, -1e4, 1e4);
  float r1 = clamp(c1 / q, -1e4, 1e4);
  float z2 = min(r0, r1), z3 = max(r0, r1);
  // Steps 4-6.
  float g;
  if (zf <= z2) {
    g = 0.0;
  } else if (zf <= z3) {
    g = (zf * z3 - b.x * (zf + z3) + b.y) / ((z3 - z2) * (zf - z2));
  } else {
    g = 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((zf - z2) * (zf - z3));
  }
  return shadowc_unit(g);  // also maps a NaN (0 / 0 when roots coincide) to 0
}

// Visibility from the filtered stored moments (quantized or not, msm_moments.glsl).
float shadowc_msm(vec4 stored, float zf) {
  float v = 1.0 - shadowc_msmShadow(shadowc_msmDecode(stored), zf);
  return shadowc_unit(v);
}

#endif

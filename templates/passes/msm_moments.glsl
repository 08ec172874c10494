// msm_moments.glsl — the four power moments of Moment Shadow Mapping (Peters & Klein 2015,
// "Moment Shadow Mapping", I3D) and their optimized 16-bit quantization (sec. 4.3). Shared by
// the moments pass (moments_warp.glsl, SHADOWC_WARP 5) and the lookup (lookup/msm.glsl), so
// the encoding and its inverse cannot drift apart.
//   b = (z, z^2, z^3, z^4)                                         sec. 3, z in [0, 1]
//   SHADOWC_MSM_QUANTIZED 1: stored q = Theta b + (0.035955884801, 0, 0, 0)   sec. 4.3
// Theta maps the power moments of every depth in [0, 1] into [0, 1]^4 and decorrelates the
// channels, so unorm16 (and the 16.16 int32 SAT) keeps what the reconstruction needs; raw
// power moments in 16 bits do not. Linear (affine) in b, so blur, mips and SAT box means
// commute with it: the lookup filters q and inverts once. The planner sets the flag for
// 16-bit storage (unorm16, sat(int32)); fp32 stores b itself.
#ifndef SHADOWC_MSM_MOMENTS_GLSL
#define SHADOWC_MSM_MOMENTS_GLSL

#ifndef SHADOWC_MSM_QUANTIZED
#define SHADOWC_MSM_QUANTIZED 0
#endif

// GLSL matrices are column-major: column j holds the coefficients of b_j (sec. 4.3 as printed,
// rows of the paper's matrix are the quantized components).
const mat4 shadowc_msmTheta = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,     // b1 = z
                                   32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,  // b2 = z^2
                                   -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,   // b3 = z^3
                                   39.3703274134, -35.364903257, -6.6543490743, -23.9728048165  // b4 = z^4
);
const mat4 shadowc_msmThetaInverse = mat4(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,   // q1
                                          0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,  // q2
                                          0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,  // q3
                                          0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734  // q4
);
const vec4 shadowc_msmOffset = vec4(0.035955884801, 0.0, 0.0, 0.0);

vec4 shadowc_msmPowerMoments(float z) {
  float z2 = z * z;
  return vec4(z, z2, z2 * z, z2 * z2);
}

// What the moments pass stores for a texel of depth z.
vec4 shadowc_msmEncode(float z) {
#if SHADOWC_MSM_QUANTIZED
  return shadowc_msmTheta * shadowc_msmPowerMoments(z) + shadowc_msmOffset;
#else
  return shadowc_msmPowerMoments(z);
#endif
}

// Filtered stored moments -> filtered power moments b.
vec4 shadowc_msmDecode(vec4 stored) {
#if SHADOWC_MSM_QUANTIZED
  return shadowc_msmThetaInverse * (stored - shadowc_msmOffset);
#else
  return stored;
#endif
}

#endif

// Exact CPU references, in double precision, of what each shadow filter intends to compute
// on a shadow map. The GPU tests compare the compiled passes against these. Conventions are
// the briefing's: a texel of depth z occludes a receiver at normalized depth d when
// z < d - bias; texel (x, y) covers uv [x, x+1] / size; lookups clamp to the edge.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace shadowc::rt::cpu {

// A plain float image (interleaved channels, row 0 first). Does not own the data.
struct ImageView {
  const float* data = nullptr;
  uint32_t width = 0, height = 0, channels = 1;
  // Clamp-to-edge fetch.
  double at(int x, int y, uint32_t c = 0) const;
};

// --- PCF ---------------------------------------------------------------------------------
// Fraction of the n x n texels [x0, x0+n) x [y0, y0+n) (clamped to the edge) that are lit,
// i.e. not (z < d - bias).
double pcfGrid(const ImageView& depth, int x0, int y0, int n, double d, double bias);
// The grid placed for a lookup at uv: x0 = floor(u * size - n/2 + 0.5): for odd n centred on
// the texel holding uv, for even n the block whose central 2x2 surrounds uv.
double pcfGridAt(const ImageView& depth, double u, double v, int n, double d, double bias);
// One bilinearly weighted comparison (what a sampler2DShadow with linear filtering returns):
// the four texels around uv*size - 0.5, each compare result weighted by its bilinear weight.
double pcfBilinear(const ImageView& depth, double u, double v, double d, double bias);
// Mean of n x n bilinear comparisons at uv + (i - (n-1)/2, j - (n-1)/2) / size.
double pcfBilinearGrid(const ImageView& depth, double u, double v, int n, double d, double bias);

// --- Box statistics -----------------------------------------------------------------------
// Texel rectangles are inclusive: [x0, x1] x [y0, y1], intersected with the image (no edge
// replication: that is what a summed-area table can answer).
struct Rect {
  int x0, y0, x1, y1;
};
// Per-channel means over the rectangle (double sums). Empty intersection: all zero.
std::array<double, 4> boxMean(const ImageView& img, Rect r);
// Mean and variance of channel 0 treated as depth (sums of z and z^2 in double).
struct DepthStats {
  double mean = 0, variance = 0;
  uint64_t count = 0;
};
DepthStats boxDepthStats(const ImageView& depth, Rect r);

// --- Summed-area tables (vssm-yang2010 sec. 4; precision: docs/stability.md) --------------
// Inclusive tables: S(x, y) = sum over x' <= x, y' <= y. Box sums use the four corners
// S(x1,y1) - S(x0-1,y1) - S(x1,y0-1) + S(x0-1,y0-1), a corner with index -1 reading 0.
struct SatU32 {  // int32 16.16 fixed point: uint(roundEven(clamp(v, 0, 1) * 65536)), sums mod 2^32
  uint32_t width = 0, height = 0, channels = 1;
  std::vector<uint32_t> data;
};
struct SatF32 {  // fp32 sums; centered: of (v - 0.5)
  uint32_t width = 0, height = 0, channels = 1;
  bool centered = false;
  std::vector<float> data;
};
SatU32 buildSatU32(const ImageView& img);
// Row prefix pass then column prefix pass, sequential fp32 adds (one GPU schedule; parallel
// scans round differently, so compare with a tolerance).
SatF32 buildSatF32(const ImageView& img, bool centered);
// Box means from the tables (the inverse of each storage convention).
double satBoxMean(const SatU32& sat, Rect r, uint32_t channel = 0);
double satBoxMean(const SatF32& sat, Rect r, uint32_t channel = 0);

// --- Moment-based bounds (vsm-tutorial; lauritzen2008 sec. 3) -------------------------------
// One-tailed Chebyshev upper bound P(z >= t) with the variance clamped to minVariance and
// light-bleeding reduction linstep(amount, 1, p) (amount 0 = off). t <= m1 gives 1.
double chebyshevUpperBound(double m1, double m2, double t, double minVariance, double bleedReduction);
// ESM: mean of exp(c (z - 1)) against the receiver: clamp(E[exp(c (z - 1))] * exp(-c (d - 1)), 0, 1).
double esmVisibility(double meanExp, double d, double c);
// EVSM warps (briefing's moment layout): e+ = exp(c+ (d - 1)), e- = -exp(-c- (d - 1)).
double evsmPositiveWarp(double d, double cPos);
double evsmNegativeWarp(double d, double cNeg);
// EVSM2: Chebyshev on (E[e+], E[e+^2]) at t = e+(d).
double evsm2Visibility(double m1, double m2, double d, double cPos, double minVariance, double bleedReduction);
// EVSM4: min of the positive and negative bounds; moments = (E[e+], E[e+^2], E[e-], E[e-^2]).
double evsm4Visibility(const std::array<double, 4>& m, double d, double cPos, double cNeg, double minVariance,
                       double bleedReduction);

// lauritzen2008 eq. (4): plain VSM visibility on receiver C (depth c) when the filter region
// holds equal parts of occluder A (depth a) and occluder B (depth b), a < b < c:
// p = (dx^2 / 4) / (dx^2 / 2 + dx dy + dy^2), dx = b - a, dy = c - b. The truth is 0.
double vsmStackedPlanesBleeding(double a, double b, double c);

// --- Moment shadow mapping (Peters & Klein 2015, "Moment Shadow Mapping", I3D) --------------
// Four power moments b = (z, z^2, z^3, z^4) per texel (sec. 3), filtered like any moments.
using Moments4 = std::array<double, 4>;
Moments4 msmPowerMoments(double z);
// The moment bias (Algorithm 3 step 1): b' = (1 - alpha) b + alpha b*, with b* the moments of a
// fixed distribution with three support points (kMsmBiasTarget). b' is then the moment vector
// of a mixture with at least three support points, so its Hankel matrix is positive definite
// for every valid b (also for a single depth, zero variance, or depths exactly 0 and 1).
extern const Moments4 kMsmBiasTarget;
Moments4 msmBiasMoments(const Moments4& b, double alpha);
// The optimized quantization of sec. 4.3: q = Theta b + (0.035955884801, 0, 0, 0) maps the
// power moments of every depth in [0, 1] into [0, 1]^4 with the four channels decorrelated, so
// 16-bit storage keeps the information the reconstruction needs; msmDequantize inverts it.
Moments4 msmQuantize(const Moments4& b);
Moments4 msmDequantize(const Moments4& q);
// The Hamburger 4MSM reconstruction (Algorithm 3) on the biased moments: the sharp lower bound
// G of P(z < zf) over all distributions with moments b' (Cholesky of the 3x3 Hankel matrix,
// the quadratic's two roots z2 <= z3, the three-point solution). Returns G unclamped.
double msmHamburgerShadow(const Moments4& b, double zf, double alpha);
// Visibility 1 - clamp(G, 0, 1) (the lit fraction's upper bound), with light-bleeding
// reduction linstep(amount, 1, v) as for Chebyshev (amount 0 = off).
double msmVisibility(const Moments4& b, double zf, double alpha, double bleedReduction);
// Closed form of the unbiased bound on a two-depth map (a fraction w of the kernel at depth a,
// the rest at b > a): four moments determine a two-point distribution exactly, so the bound is
// the truth: 1 for zf <= a, 1 - w for a < zf <= b, 0 for zf > b (sec. 3: "exact for two depths").
double msmTwoDepthVisibility(double a, double b, double w, double zf);

}  // namespace shadowc::rt::cpu

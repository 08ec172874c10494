#include "runtime/reference/cpu_filters.h"

#include <algorithm>
#include <cmath>

namespace shadowc::rt::cpu {
namespace {

bool lit(double z, double d, double bias) { return !(z < d - bias); }

Rect clip(Rect r, uint32_t w, uint32_t h) {
  return {std::max(r.x0, 0), std::max(r.y0, 0), std::min(r.x1, int(w) - 1), std::min(r.y1, int(h) - 1)};
}

double linstep(double lo, double hi, double v) { return std::clamp((v - lo) / (hi - lo), 0.0, 1.0); }

}  // namespace

double ImageView::at(int x, int y, uint32_t c) const {
  x = std::clamp(x, 0, int(width) - 1);
  y = std::clamp(y, 0, int(height) - 1);
  return data[(size_t(y) * width + x) * channels + c];
}

double pcfGrid(const ImageView& depth, int x0, int y0, int n, double d, double bias) {
  int litCount = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) litCount += lit(depth.at(x0 + i, y0 + j), d, bias) ? 1 : 0;
  }
  return double(litCount) / double(n * n);
}

double pcfGridAt(const ImageView& depth, double u, double v, int n, double d, double bias) {
  const int x0 = int(std::floor(u * depth.width - 0.5 * n + 0.5));
  const int y0 = int(std::floor(v * depth.height - 0.5 * n + 0.5));
  return pcfGrid(depth, x0, y0, n, d, bias);
}

double pcfBilinear(const ImageView& depth, double u, double v, double d, double bias) {
  const double tx = u * depth.width - 0.5, ty = v * depth.height - 0.5;
  const int x = int(std::floor(tx)), y = int(std::floor(ty));
  const double fx = tx - x, fy = ty - y;
  auto s = [&](int dx, int dy) { return lit(depth.at(x + dx, y + dy), d, bias) ? 1.0 : 0.0; };
  return (1 - fy) * ((1 - fx) * s(0, 0) + fx * s(1, 0)) + fy * ((1 - fx) * s(0, 1) + fx * s(1, 1));
}

double pcfBilinearGrid(const ImageView& depth, double u, double v, int n, double d, double bias) {
  double sum = 0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      sum += pcfBilinear(depth, u + (i - 0.5 * (n - 1)) / depth.width, v + (j - 0.5 * (n - 1)) / depth.height, d, bias);
    }
  }
  return sum / double(n * n);
}

std::array<double, 4> boxMean(const ImageView& img, Rect r) {
  r = clip(r, img.width, img.height);
  std::array<double, 4> sum{};
  if (r.x0 > r.x1 || r.y0 > r.y1) return sum;
  for (int y = r.y0; y <= r.y1; ++y) {
    for (int x = r.x0; x <= r.x1; ++x) {
      for (uint32_t c = 0; c < std::min<uint32_t>(img.channels, 4); ++c) sum[c] += img.at(x, y, c);
    }
  }
  const double count = double(r.x1 - r.x0 + 1) * double(r.y1 - r.y0 + 1);
  for (double& s : sum) s /= count;
  return sum;
}

DepthStats boxDepthStats(const ImageView& depth, Rect r) {
  r = clip(r, depth.width, depth.height);
  DepthStats s;
  if (r.x0 > r.x1 || r.y0 > r.y1) return s;
  double sum = 0, sum2 = 0;
  for (int y = r.y0; y <= r.y1; ++y) {
    for (int x = r.x0; x <= r.x1; ++x) {
      const double z = depth.at(x, y);
      sum += z;
      sum2 += z * z;
    }
  }
  s.count = uint64_t(r.x1 - r.x0 + 1) * uint64_t(r.y1 - r.y0 + 1);
  s.mean = sum / double(s.count);
  s.variance = std::max(0.0, sum2 / double(s.count) - s.mean * s.mean);
  return s;
}

SatU32 buildSatU32(const ImageView& img) {
  SatU32 sat{img.width, img.height, img.channels, std::vector<uint32_t>(size_t(img.width) * img.height * img.channels)};
  const uint32_t w = img.width, ch = img.channels;
  for (uint32_t y = 0; y < img.height; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      for (uint32_t c = 0; c < ch; ++c) {
        const double v = std::clamp(img.at(int(x), int(y), c), 0.0, 1.0);
        uint32_t s = uint32_t(std::nearbyint(v * 65536.0));  // ties to even, as roundEven in sat_common.glsl
        // Unsigned adds and subtracts wrap modulo 2^32: the box sums stay exact (Lauritzen 2007).
        if (x > 0) s += sat.data[(size_t(y) * w + x - 1) * ch + c];
        if (y > 0) s += sat.data[(size_t(y - 1) * w + x) * ch + c];
        if (x > 0 && y > 0) s -= sat.data[(size_t(y - 1) * w + x - 1) * ch + c];
        sat.data[(size_t(y) * w + x) * ch + c] = s;
      }
    }
  }
  return sat;
}

SatF32 buildSatF32(const ImageView& img, bool centered) {
  SatF32 sat{img.width, img.height, img.channels, centered,
             std::vector<float>(size_t(img.width) * img.height * img.channels)};
  const uint32_t w = img.width, ch = img.channels;
  const float offset = centered ? 0.5f : 0.0f;
  for (uint32_t y = 0; y < img.height; ++y) {  // rows
    float run[4] = {0, 0, 0, 0};
    for (uint32_t x = 0; x < w; ++x) {
      for (uint32_t c = 0; c < ch && c < 4; ++c) {
        run[c] += float(img.at(int(x), int(y), c)) - offset;
        sat.data[(size_t(y) * w + x) * ch + c] = run[c];
      }
    }
  }
  for (uint32_t y = 1; y < img.height; ++y) {  // columns
    for (size_t k = 0; k < size_t(w) * ch; ++k)
      sat.data[size_t(y) * w * ch + k] += sat.data[size_t(y - 1) * w * ch + k];
  }
  return sat;
}

namespace {
template <typename T>
T corner(const std::vector<T>& data, uint32_t w, uint32_t ch, int x, int y, uint32_t c) {
  return (x < 0 || y < 0) ? T(0) : data[(size_t(y) * w + uint32_t(x)) * ch + c];
}
}  // namespace

double satBoxMean(const SatU32& sat, Rect r, uint32_t channel) {
  r = clip(r, sat.width, sat.height);
  if (r.x0 > r.x1 || r.y0 > r.y1) return 0;
  auto S = [&](int x, int y) { return corner(sat.data, sat.width, sat.channels, x, y, channel); };
  const uint32_t sum = S(r.x1, r.y1) - S(r.x0 - 1, r.y1) - S(r.x1, r.y0 - 1) + S(r.x0 - 1, r.y0 - 1);
  const double count = double(r.x1 - r.x0 + 1) * double(r.y1 - r.y0 + 1);
  return double(sum) / 65536.0 / count;
}

double satBoxMean(const SatF32& sat, Rect r, uint32_t channel) {
  r = clip(r, sat.width, sat.height);
  if (r.x0 > r.x1 || r.y0 > r.y1) return 0;
  auto S = [&](int x, int y) { return corner(sat.data, sat.width, sat.channels, x, y, channel); };
  // fp32 corner arithmetic, as the shader does it.
  const float sum = S(r.x1, r.y1) - S(r.x0 - 1, r.y1) - S(r.x1, r.y0 - 1) + S(r.x0 - 1, r.y0 - 1);
  const double count = double(r.x1 - r.x0 + 1) * double(r.y1 - r.y0 + 1);
  return double(sum) / count + (sat.centered ? 0.5 : 0.0);
}

double chebyshevUpperBound(double m1, double m2, double t, double minVariance, double bleedReduction) {
  if (t <= m1) return 1.0;
  const double variance = std::max(m2 - m1 * m1, minVariance);
  const double delta = t - m1;
  const double p = variance / (variance + delta * delta);
  return bleedReduction > 0 ? linstep(bleedReduction, 1.0, p) : p;
}

double esmVisibility(double meanExp, double d, double c) {
  return std::clamp(meanExp * std::exp(-c * (d - 1.0)), 0.0, 1.0);
}

double evsmPositiveWarp(double d, double cPos) { return std::exp(cPos * (d - 1.0)); }
double evsmNegativeWarp(double d, double cNeg) { return -std::exp(-cNeg * (d - 1.0)); }

double evsm2Visibility(double m1, double m2, double d, double cPos, double minVariance, double bleedReduction) {
  return chebyshevUpperBound(m1, m2, evsmPositiveWarp(d, cPos), minVariance, bleedReduction);
}

double evsm4Visibility(const std::array<double, 4>& m, double d, double cPos, double cNeg, double minVariance,
                       double bleedReduction) {
  const double pos = chebyshevUpperBound(m[0], m[1], evsmPositiveWarp(d, cPos), minVariance, bleedReduction);
  const double neg = chebyshevUpperBound(m[2], m[3], evsmNegativeWarp(d, cNeg), minVariance, bleedReduction);
  return std::min(pos, neg);
}

double vsmStackedPlanesBleeding(double a, double b, double c) {
  const double dx = b - a, dy = c - b;
  return (0.25 * dx * dx) / (0.5 * dx * dx + dx * dy + dy * dy);
}

// ---- Moment shadow mapping (Peters & Klein 2015) -------------------------------------------

// The moments of 0.315 d(0) + 0.37 d(1/2) + 0.315 d(1): Peters et al.'s bias vector
// (0, 0.63, 0, 0.63) for depths in [-1, 1] taken to depths in [0, 1] by z = (u + 1) / 2.
// Mixing distributions commutes with that affine map, and the bound is invariant under it,
// so this is their bias. The (0.5, 0.5, 0.5, 0.5) of the two points 0 and 1 is not used: its
// Hankel matrix is singular, and b' of a map whose depths are all 0 or 1 would be too.
const Moments4 kMsmBiasTarget = {0.5, 0.4075, 0.36125, 0.338125};

Moments4 msmPowerMoments(double z) {
  const double z2 = z * z;
  return {z, z2, z2 * z, z2 * z2};
}

Moments4 msmBiasMoments(const Moments4& b, double alpha) {
  Moments4 out;
  for (int i = 0; i < 4; ++i) out[i] = (1.0 - alpha) * b[i] + alpha * kMsmBiasTarget[i];
  return out;
}

namespace {
// Sec. 4.3, as printed (column-vector form: row i of Theta gives quantized moment i).
constexpr double kTheta[4][4] = {{-2.07224649, 32.23703778, -68.571074599, 39.3703274134},
                                 {13.7948857237, -59.4683975703, 82.0359750338, -35.364903257},
                                 {0.105877704, -1.9077466311, 9.3496555107, -6.6543490743},
                                 {9.7924062118, -33.7652110555, 47.9456096605, -23.9728048165}};
constexpr double kThetaInverse[4][4] = {{0.2227744146, 0.0771972861, 0.7926986636, 0.0319417555},
                                        {0.1549679261, 0.1394629426, 0.7963415838, -0.1722823173},
                                        {0.1451988946, 0.2120202157, 0.7258694464, -0.2758014811},
                                        {0.163127443, 0.2591432266, 0.6539092497, -0.3376131734}};
constexpr double kQuantizeOffset = 0.035955884801;
}  // namespace

Moments4 msmQuantize(const Moments4& b) {
  Moments4 q{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) q[i] += kTheta[i][j] * b[j];
  q[0] += kQuantizeOffset;
  return q;
}

Moments4 msmDequantize(const Moments4& q) {
  Moments4 c = q;
  c[0] -= kQuantizeOffset;
  Moments4 b{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) b[i] += kThetaInverse[i][j] * c[j];
  return b;
}

double msmHamburgerShadow(const Moments4& m, double zf, double alpha) {
  const Moments4 b = msmBiasMoments(m, alpha);  // step 1
  // Step 2: solve B c = (1, zf, zf^2) with B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]] by
  // B = L D L^T (L unit lower triangular): L21 = b1, L31 = b2, D22 = b2 - b1^2,
  // L32 = (b3 - b1 b2) / D22, D33 = b4 - b2^2 - L32^2 D22.
  const double d22 = b[1] - b[0] * b[0];
  const double l32 = (b[2] - b[0] * b[1]) / d22;
  const double d33 = b[3] - b[1] * b[1] - l32 * l32 * d22;
  double c1 = 1.0, c2 = zf - b[0], c3 = zf * zf - b[1] - l32 * c2;  // forward: L y = rhs
  c2 /= d22;                                                        // D^-1
  c3 /= d33;
  c2 -= l32 * c3;  // backward: L^T c = y
  c1 -= b[0] * c2 + b[1] * c3;
  // Step 3: the roots z2 <= z3 of c3 z^2 + c2 z + c1 = 0 (real and distinct for a positive
  // definite B), in the cancellation-free form.
  const double disc = std::max(c2 * c2 - 4.0 * c3 * c1, 0.0);
  const double q = -0.5 * (c2 + std::copysign(std::sqrt(disc), c2));
  double r0 = q / c3, r1 = c1 / q;
  const double z2 = std::min(r0, r1), z3 = std::max(r0, r1);
  // Steps 4-6: the weights of the three-point solution at z2, z3 and zf.
  if (zf <= z2) return 0.0;
  if (zf <= z3) return (zf * z3 - b[0] * (zf + z3) + b[1]) / ((z3 - z2) * (zf - z2));
  return 1.0 - (z2 * z3 - b[0] * (z2 + z3) + b[1]) / ((zf - z2) * (zf - z3));
}

double msmVisibility(const Moments4& b, double zf, double alpha, double bleedReduction) {
  const double v = 1.0 - std::clamp(msmHamburgerShadow(b, zf, alpha), 0.0, 1.0);
  return bleedReduction > 0 ? linstep(bleedReduction, 1.0, v) : v;
}

double msmTwoDepthVisibility(double a, double b, double w, double zf) {
  if (zf <= a) return 1.0;
  return zf <= b ? 1.0 - w : 0.0;
}

}  // namespace shadowc::rt::cpu

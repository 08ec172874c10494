// CPU filter references: each checked against an independent computation.
#include <gtest/gtest.h>

#include <random>

#include "runtime/reference/cpu_filters.h"

namespace shadowc::rt::cpu {
namespace {

std::vector<float> randomImage(uint32_t w, uint32_t h, uint32_t ch, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> v(size_t(w) * h * ch);
  for (float& x : v) x = u(rng);
  return v;
}

TEST(ReferenceCpuFilters, PcfGridCountsLitTexelsWithClampToEdge) {
  // 4x4 depth: left half 0.2 (occluder), right half 0.9.
  std::vector<float> d(16);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) d[y * 4 + x] = x < 2 ? 0.2f : 0.9f;
  const ImageView img{d.data(), 4, 4, 1};
  EXPECT_DOUBLE_EQ(pcfGrid(img, 1, 1, 2, 0.5, 0.0), 0.5);  // columns 1 (dark) and 2 (lit)
  EXPECT_DOUBLE_EQ(pcfGrid(img, 0, 0, 4, 0.5, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(pcfGrid(img, -3, 0, 3, 0.5, 0.0), 0.0);  // clamped: columns -3..-1 read column 0
  EXPECT_DOUBLE_EQ(pcfGrid(img, 3, 3, 3, 0.5, 0.0), 1.0);   // clamped to the lit edge
  // Bias: z < d - bias is the occlusion test; 0.2 < 0.25 - 0.1 is false -> lit.
  EXPECT_DOUBLE_EQ(pcfGrid(img, 0, 0, 2, 0.25, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(pcfGrid(img, 0, 0, 2, 0.35, 0.1), 0.0);
  // Placement at uv: 3x3 centred on the texel holding uv = texel (2, 1) -> columns 1..3.
  EXPECT_DOUBLE_EQ(pcfGridAt(img, 2.5 / 4, 1.5 / 4, 3, 0.5, 0), 2.0 / 3);
  // 2x2 at uv between texels 1 and 2 -> columns 1..2.
  EXPECT_DOUBLE_EQ(pcfGridAt(img, 2.0 / 4, 2.0 / 4, 2, 0.5, 0), 0.5);
  EXPECT_DOUBLE_EQ(pcfGridAt(img, 2.1 / 4, 2.0 / 4, 1, 0.5, 0), 1.0);
}

TEST(ReferenceCpuFilters, BilinearPcfInterpolatesCompareResults) {
  std::vector<float> d = {0.2f, 0.9f, 0.2f, 0.9f};  // 2x2: left dark, right lit
  const ImageView img{d.data(), 2, 2, 1};
  EXPECT_DOUBLE_EQ(pcfBilinear(img, 0.25, 0.5, 0.5, 0), 0.0);    // texel 0 centre
  EXPECT_DOUBLE_EQ(pcfBilinear(img, 0.75, 0.5, 0.5, 0), 1.0);    // texel 1 centre
  EXPECT_DOUBLE_EQ(pcfBilinear(img, 0.5, 0.5, 0.5, 0), 0.5);     // halfway
  EXPECT_DOUBLE_EQ(pcfBilinear(img, 0.375, 0.1, 0.5, 0), 0.25);  // a quarter of the way
  // Grid of bilinear taps = mean of its taps.
  const double expected =
      (pcfBilinear(img, 0.5 - 0.25, 0.5 - 0.25, 0.5, 0) + pcfBilinear(img, 0.5 + 0.25, 0.5 - 0.25, 0.5, 0) +
       pcfBilinear(img, 0.5 - 0.25, 0.5 + 0.25, 0.5, 0) + pcfBilinear(img, 0.5 + 0.25, 0.5 + 0.25, 0.5, 0)) /
      4;
  EXPECT_DOUBLE_EQ(pcfBilinearGrid(img, 0.5, 0.5, 2, 0.5, 0), expected);
}

TEST(ReferenceCpuFilters, BoxStatistics) {
  std::vector<float> d = {0, 1, 2, 3, 4, 5, 6, 7, 8};  // 3x3
  const ImageView img{d.data(), 3, 3, 1};
  const DepthStats s = boxDepthStats(img, {0, 0, 1, 1});  // 0 1 3 4
  EXPECT_DOUBLE_EQ(s.mean, 2.0);
  EXPECT_DOUBLE_EQ(s.variance, (4 + 1 + 1 + 4) / 4.0);
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(boxMean(img, {-5, -5, 10, 10})[0], 4.0);  // clipped to the image
  EXPECT_DOUBLE_EQ(boxMean(img, {2, 2, 2, 2})[0], 8.0);
}

TEST(ReferenceCpuFilters, SatBoxSumsEqualDirectSums) {
  const uint32_t w = 37, h = 23;
  const std::vector<float> v = randomImage(w, h, 2, 7);
  const ImageView img{v.data(), w, h, 2};
  const SatU32 u32 = buildSatU32(img);
  const SatF32 naive = buildSatF32(img, false), centered = buildSatF32(img, true);
  std::mt19937 rng(3);
  for (int k = 0; k < 200; ++k) {
    int x0 = int(rng() % w), x1 = int(rng() % w), y0 = int(rng() % h), y1 = int(rng() % h);
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    for (uint32_t c = 0; c < 2; ++c) {
      const double exact = boxMean(img, {x0, y0, x1, y1})[c];
      EXPECT_NEAR(satBoxMean(u32, {x0, y0, x1, y1}, c), exact, 0.5 / 65536 + 1e-12);  // rounding to 16.16
      EXPECT_NEAR(satBoxMean(naive, {x0, y0, x1, y1}, c), exact, 1e-4);
      EXPECT_NEAR(satBoxMean(centered, {x0, y0, x1, y1}, c), exact, 1e-4);
    }
  }
}

TEST(ReferenceCpuFilters, SatInt32WrapsAroundAndStaysExact) {
  // 300 x 300 texels of 1.0: total sum 9e4 * 65536 > 2^32 wraps, yet small boxes are exact.
  const uint32_t n = 300;
  const std::vector<float> ones(size_t(n) * n, 1.0f);
  const SatU32 sat = buildSatU32({ones.data(), n, n, 1});
  EXPECT_LT(sat.data.back(), uint32_t(n) * n * 65536ull);  // it wrapped
  EXPECT_DOUBLE_EQ(satBoxMean(sat, {290, 290, 299, 299}), 1.0);
  EXPECT_DOUBLE_EQ(satBoxMean(sat, {0, 0, 200, 200}), 1.0);  // 201^2 * 65536 < 2^32
  // Sibling: a naive fp32 SAT of the same image loses precision in small boxes far from the origin.
  std::vector<float> ramp(size_t(n) * n);
  for (size_t i = 0; i < ramp.size(); ++i) ramp[i] = float((i * 37) % 101) / 100.0f;
  const ImageView img{ramp.data(), n, n, 1};
  const SatF32 naive = buildSatF32(img, false);
  double worst = 0;
  for (int y = 280; y < 299; ++y)
    worst = std::max(worst, std::abs(satBoxMean(naive, {290, y, 290, y}) - img.at(290, y)));
  EXPECT_GT(worst, 1e-4);
}

TEST(ReferenceCpuFilters, ChebyshevIsExactForTwoPlanes) {
  // Fraction f of the region at occluder depth z0, the rest at the receiver's own depth d:
  // mean = f z0 + (1-f) d, variance = f (1-f) (d - z0)^2 -> bound = 1 - f exactly.
  const double z0 = 0.3, d = 0.8;
  for (double f : {0.1, 0.25, 0.5, 0.9}) {
    const double m1 = f * z0 + (1 - f) * d, m2 = f * z0 * z0 + (1 - f) * d * d;
    EXPECT_NEAR(chebyshevUpperBound(m1, m2, d, 0, 0), 1 - f, 1e-12) << f;
  }
  EXPECT_EQ(chebyshevUpperBound(0.5, 0.25, 0.4, 0, 0), 1.0);  // in front of the mean: lit
  // Minimum variance keeps zero-variance regions from turning black at t slightly > mean.
  EXPECT_NEAR(chebyshevUpperBound(0.5, 0.25, 0.5 + 1e-3, 1e-4, 0), 1e-4 / (1e-4 + 1e-6), 1e-12);
  // Bleeding reduction: linstep(0.3, 1, p).
  EXPECT_NEAR(chebyshevUpperBound(0.5, 0.26, 0.6, 0, 0.3), (0.5 - 0.3) / 0.7, 1e-12);
  EXPECT_EQ(chebyshevUpperBound(0.5, 0.26, 0.7, 0, 0.3), 0.0);  // p = 0.2 < 0.3
}

TEST(ReferenceCpuFilters, StackedPlanesBleedingMatchesEquation4) {
  // Brute force: Chebyshev with the moments of a region half at a, half at b, at t = c.
  for (auto [a, b, c] : {std::tuple{0.1, 0.4, 0.9}, {0.2, 0.3, 0.35}, {0.5, 0.6, 0.99}}) {
    const double m1 = (a + b) / 2, m2 = (a * a + b * b) / 2;
    EXPECT_NEAR(vsmStackedPlanesBleeding(a, b, c), chebyshevUpperBound(m1, m2, c, 0, 0), 1e-12);
  }
  // It is a real leak (truth = 0) that grows as C approaches B: the O(1/dy^2) tail.
  EXPECT_GT(vsmStackedPlanesBleeding(0.1, 0.5, 0.55), vsmStackedPlanesBleeding(0.1, 0.5, 0.9));
  EXPECT_NEAR(vsmStackedPlanesBleeding(0.1, 0.5, 0.5), 0.5, 1e-12);  // dy = 0: 1/4 / 1/2
}

TEST(ReferenceCpuFilters, EsmAndEvsmBounds) {
  const double c = 40, z = 0.3, d = 0.5;
  // A single occluder at z: ESM gives exp(c (z - d)).
  EXPECT_NEAR(esmVisibility(std::exp(c * (z - 1)), d, c), std::exp(c * (z - d)), 1e-12);
  EXPECT_EQ(esmVisibility(std::exp(c * (0.7 - 1)), d, c), 1.0);  // behind the receiver: clamped
  // EVSM on the two-plane case: the warp is monotonic, so Chebyshev in warped space is exact too.
  const double f = 0.4, ez = evsmPositiveWarp(z, 5), ed = evsmPositiveWarp(d, 5);
  const double m1 = f * ez + (1 - f) * ed, m2 = f * ez * ez + (1 - f) * ed * ed;
  EXPECT_NEAR(evsm2Visibility(m1, m2, d, 5, 0, 0), 1 - f, 1e-12);
  const double nz = evsmNegativeWarp(z, 5), nd = evsmNegativeWarp(d, 5);
  EXPECT_LT(nz, nd);  // negative warp is increasing too
  const std::array<double, 4> m = {m1, m2, f * nz + (1 - f) * nd, f * nz * nz + (1 - f) * nd * nd};
  EXPECT_NEAR(evsm4Visibility(m, d, 5, 5, 0, 0), 1 - f, 1e-12);
  // On the stacked planes EVSM4 leaks less than plain VSM's eq. (4).
  const double a = 0.1, b = 0.5, cc = 0.6;
  auto moments = [&](double (*warp)(double, double), double k) {
    const double wa = warp(a, k), wb = warp(b, k);
    return std::pair{(wa + wb) / 2, (wa * wa + wb * wb) / 2};
  };
  const auto [p1, p2] = moments(evsmPositiveWarp, 10);
  const auto [n1, n2] = moments(evsmNegativeWarp, 10);
  EXPECT_LT(evsm4Visibility({p1, p2, n1, n2}, cc, 10, 10, 0, 0), vsmStackedPlanesBleeding(a, b, cc));
}

}  // namespace
}  // namespace shadowc::rt::cpu

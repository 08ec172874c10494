// The moment shadow mapping reference (Peters & Klein 2015) against independent facts: the
// quantization of sec. 4.3 and its printed inverse, the exactness of four moments for two
// depths, the bound's defining properties on a three-depth distribution, and the role of the
// bias on degenerate (zero-variance, depth 0 / 1) inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "runtime/reference/cpu_filters.h"

namespace shadowc::rt::cpu {
namespace {

Moments4 mixture(std::initializer_list<std::pair<double, double>> depthWeights) {
  Moments4 m{};
  for (auto [z, w] : depthWeights) {
    const Moments4 p = msmPowerMoments(z);
    for (int i = 0; i < 4; ++i) m[i] += w * p[i];
  }
  return m;
}

TEST(ReferenceMsm, QuantizationMapsEveryDepthIntoTheUnitCubeAndItsInverseUndoesIt) {
  double worst = 0;
  for (int k = 0; k <= 1000; ++k) {
    const Moments4 b = msmPowerMoments(k / 1000.0);
    const Moments4 q = msmQuantize(b);
    for (double x : q) {
      EXPECT_GE(x, -1e-9);
      EXPECT_LE(x, 1.0 + 1e-9);
    }
    const Moments4 back = msmDequantize(q);
    for (int i = 0; i < 4; ++i) worst = std::max(worst, std::fabs(back[i] - b[i]));
  }
  // The printed constants carry ~10 digits: the round trip is exact to far below 16-bit steps.
  EXPECT_LT(worst, 1e-9);
  // z = 0 maps to the offset alone.
  EXPECT_NEAR(msmQuantize(msmPowerMoments(0.0))[0], 0.035955884801, 1e-12);
}

TEST(ReferenceMsm, BiasTargetIsAThreePointDistribution) {
  const Moments4 t = mixture({{0.0, 0.315}, {0.5, 0.37}, {1.0, 0.315}});
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(kMsmBiasTarget[i], t[i], 1e-15);
  // Its Hankel determinant is positive (three support points): det = D22 * D33.
  const double d22 = t[1] - t[0] * t[0];
  const double l32 = (t[2] - t[0] * t[1]) / d22;
  const double d33 = t[3] - t[1] * t[1] - l32 * l32 * d22;
  EXPECT_GT(d22, 0.1);
  EXPECT_GT(d33, 1e-3);
  // Bias is a convex mix.
  const Moments4 b = msmBiasMoments(msmPowerMoments(0.3), 0.25);
  EXPECT_NEAR(b[0], 0.75 * 0.3 + 0.25 * 0.5, 1e-15);
}

TEST(ReferenceMsm, FourMomentsReproduceTwoDepthsExactly) {
  // Unbiased (alpha tiny) the bound is the truth: 1, 1 - w, 0 (sec. 3).
  for (double w : {0.1, 0.5, 0.8}) {
    const Moments4 m = mixture({{0.2, w}, {0.45, 1 - w}});
    for (double zf : {0.1, 0.19, 0.21, 0.3, 0.44, 0.46, 0.6, 0.95}) {
      const double v = msmVisibility(m, zf, 1e-12, 0);
      EXPECT_NEAR(v, msmTwoDepthVisibility(0.2, 0.45, w, zf), 1e-6) << "w " << w << " zf " << zf;
    }
  }
  // The closed form itself.
  EXPECT_EQ(msmTwoDepthVisibility(0.2, 0.45, 0.3, 0.2), 1.0);
  EXPECT_DOUBLE_EQ(msmTwoDepthVisibility(0.2, 0.45, 0.3, 0.45), 0.7);
  EXPECT_EQ(msmTwoDepthVisibility(0.2, 0.45, 0.3, 0.46), 0.0);
}

TEST(ReferenceMsm, PlainVsmBleedsWhereMsmDoesNot) {
  // lauritzen2008 eq. (4): half A (0.2), half B (0.45), receiver C behind both, truly dark.
  const Moments4 m = mixture({{0.2, 0.5}, {0.45, 0.5}});
  for (double c : {0.5, 0.6, 0.75, 0.9}) {
    const double vsm = chebyshevUpperBound(m[0], m[1], c, 0, 0);
    EXPECT_NEAR(vsm, vsmStackedPlanesBleeding(0.2, 0.45, c), 1e-12);
    EXPECT_GT(vsm, 0.04);
    EXPECT_LT(msmVisibility(m, c, 3e-5, 0), 0.2 * vsm);  // the default 16-bit bias keeps it small
  }
}

TEST(ReferenceMsm, BoundIsSharpAndBelowTheTruthForThreeDepths) {
  // Three depths: G is a lower bound of P(z < zf), so 1 - G is never below the true lit fraction.
  const Moments4 m = mixture({{0.1, 0.3}, {0.4, 0.3}, {0.8, 0.4}});
  for (double zf = 0.0; zf <= 1.0; zf += 0.01) {
    const double truth = zf <= 0.1 ? 1.0 : zf <= 0.4 ? 0.7 : zf <= 0.8 ? 0.4 : 0.0;
    const double v = msmVisibility(m, zf, 1e-9, 0);
    EXPECT_GE(v, truth - 1e-6) << "zf " << zf;
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
  // Monotone in the receiver depth: farther receivers are never more lit.
  double prev = 1.0;
  for (double zf = 0.0; zf <= 1.0; zf += 0.005) {
    const double v = msmVisibility(m, zf, 3e-5, 0);
    EXPECT_LE(v, prev + 1e-9) << "zf " << zf;
    prev = v;
  }
}

TEST(ReferenceMsm, BiasMakesZeroVarianceAndDepthsAtZeroAndOneFinite) {
  for (double z : {0.0, 0.5, 1.0}) {
    const Moments4 m = msmPowerMoments(z);  // one depth: Hankel matrix of rank 1
    // Without bias the Cholesky divides by D22 = 0: no meaningful value.
    EXPECT_FALSE(std::isfinite(msmHamburgerShadow(m, z + 0.01, 0.0))) << "z " << z;
    for (double alpha : {3e-6, 3e-5}) {
      EXPECT_TRUE(std::isfinite(msmHamburgerShadow(m, z + 0.01, alpha)));
      EXPECT_NEAR(msmVisibility(m, z - 0.001, alpha, 0), 1.0, 1e-4) << "in front, z " << z;
      EXPECT_LT(msmVisibility(m, z + 0.05, alpha, 0), 0.01) << "behind, z " << z;
    }
  }
  // Depths exactly 0 and 1 (the two-point set of the (0.5, ...) bias vector some samples use):
  // still a positive definite biased Hankel matrix with our three-point target.
  const Moments4 m = mixture({{0.0, 0.5}, {1.0, 0.5}});
  EXPECT_TRUE(std::isfinite(msmHamburgerShadow(m, 0.5, 3e-5)));
  EXPECT_NEAR(msmVisibility(m, 0.5, 3e-5, 0), 0.5, 1e-3);
}

TEST(ReferenceMsm, BleedingReductionIsLinstep) {
  const Moments4 m = mixture({{0.2, 0.5}, {0.6, 0.5}});
  const double v = msmVisibility(m, 0.4, 1e-9, 0);
  EXPECT_NEAR(v, 0.5, 1e-6);
  EXPECT_NEAR(msmVisibility(m, 0.4, 1e-9, 0.2), (v - 0.2) / 0.8, 1e-6);
}

}  // namespace
}  // namespace shadowc::rt::cpu

// Closed-form checks of the shade-pass lookups of real compiled samples on crafted shadow maps
// and receivers placed exactly (identity light view, accuracy_harness.h):
//  * Chebyshev (VSM) on a two-depth map equals the formula on the same filtered moments (1e-5);
//  * plain VSM light bleeding on the stacked-planes set-up equals lauritzen2008 eq. (4) (1e-3);
//  * n x n grid PCF equals rt::cpu::pcfGridAt (1e-5);
//  * MSM (fp32 and unorm16-quantized) on the stacked planes equals the two-depth closed form.
// Each has a sibling that compares with a deliberately wrong reference and must fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"
#include "runtime/reference/cpu_filters.h"

namespace shadowc::test {
namespace {

using ClosedFormLookupTest = VulkanTest;

constexpr uint32_t kMap = 256;
constexpr uint32_t kScreen = 16;  // up to 256 receivers

// The receiver depth the shade pass computes (fp32, frame.glsl shadowc_lightSpace), minus the
// bias, emulated in float so the references see the very same t.
double gpuReceiverDepth(double d, double bias) {
  const float z = float(kNear + d * (kFar - kNear));
  const float dn = (z - kNear) / (kFar - kNear);
  return double(dn - float(bias));
}

// Visibility of the crafted receivers after running every pass.
struct LookupRun {
  std::vector<float> visibility;
  std::vector<float> moments;  // interleaved rg (empty when the filter has none)
};
LookupRun runLookup(rt::VulkanContext& ctx, const CompiledFilter& cf, const std::vector<float>& depth,
                    const std::vector<Receiver>& receivers) {
  const CraftedGBuffer g = craftGBuffer(receivers, kScreen, kScreen);
  rt::RunOptions options;
  for (const auto& im : cf.passes.manifest.images)
    if (im.name == "moments") options.downloads.push_back("moments");
  rt::RunOutputs out = rt::runPasses(
      ctx, cf.passes, craftedInputs(kMap, kScreen, kScreen, identityFrame(kMap, kScreen, kScreen, 0.5f), depth, g),
      options);
  LookupRun r;
  r.visibility = std::move(out.visibility);
  r.visibility.resize(receivers.size());
  if (out.images.count("moments")) r.moments = out.images.at("moments").floats();
  return r;
}

// Compares per receiver; the message names the worst one.
::testing::AssertionResult visibilityMatches(const std::vector<float>& gpu, const std::vector<double>& expected,
                                             const std::vector<Receiver>& receivers, double tolerance) {
  std::vector<double> g(gpu.begin(), gpu.end());
  const MaxError m = maxAbsError(g, expected);
  if (m.error <= tolerance) return ::testing::AssertionSuccess() << "max error " << m.error;
  const Receiver& r = receivers[m.index];
  return ::testing::AssertionFailure() << fmt::format(
             "receiver {} (u {:.6f}, v {:.6f}, d {:.4f}): GPU {:.7f}, reference {:.7f}, error {:.3g} > {:.3g}", m.index,
             r.u, r.v, r.d, gpu[m.index], expected[m.index], m.error, tolerance);
}

// ---- VSM: Chebyshev on a two-depth map ---------------------------------------------------------
// Occluder plane at depth a left of a vertical edge, floor at depth c right of it. The edge sits
// at a different column in each band of 16 rows, and every receiver is at u = 0.5 exactly
// (x = 0 in light view, exact in fp32), so the bilinear fetch mixes texels 127 and 128 with weights
// 1/2 whatever the rounding, and the moments across each band's middle rows depend on x only.
constexpr double kOccluder = 0.3, kFloor = 0.7;
constexpr int kBands = kMap / 16;

std::vector<float> twoDepthMap() {
  std::vector<float> d(size_t(kMap) * kMap);
  for (uint32_t y = 0; y < kMap; ++y) {
    const int edge = int(kMap / 2) - 5 + int(y / 16) % 11;  // occluder covers x < edge
    for (uint32_t x = 0; x < kMap; ++x) d[size_t(y) * kMap + x] = float(int(x) < edge ? kOccluder : kFloor);
  }
  return d;
}

std::vector<Receiver> edgeReceivers(const std::vector<double>& depths) {
  std::vector<Receiver> rs;
  for (int band = 0; band < kBands; ++band)
    for (double d : depths) rs.push_back({0.5, (band * 16 + 8.0) / kMap, d});
  return rs;
}

// Mean moments at u = 0.5, v in the middle of a band: texels 127 and 128, weight 1/2 each (rows
// 16 band + 7 and + 8 hold the same values: the blur radius is 2 and the band 16 rows high).
std::array<double, 2> edgeMoments(const std::vector<float>& moments, double v) {
  const int y = int(v * kMap);  // row 16 band + 8
  const size_t a = (size_t(y) * kMap + kMap / 2 - 1) * 2, b = (size_t(y) * kMap + kMap / 2) * 2;
  return {0.5 * (double(moments[a]) + moments[b]), 0.5 * (double(moments[a + 1]) + moments[b + 1])};
}

struct VsmCase {
  const CompiledFilter* cf;
  std::vector<Receiver> receivers;
  LookupRun run;
};
VsmCase runVsmEdge(rt::VulkanContext& ctx) {
  VsmCase c;
  c.cf = compileFilterCached("vsm_chebyshev", sampleSource("vsm_chebyshev"));
  if (!c.cf) return c;
  c.receivers = edgeReceivers({0.25, 0.42, 0.55, 0.69, 0.8, 0.95});
  c.run = runLookup(ctx, *c.cf, twoDepthMap(), c.receivers);
  return c;
}

std::vector<double> chebyshevReference(const VsmCase& c, bool applyBias) {
  const FilterSpec& s = c.cf->spec;
  std::vector<double> expected;
  for (const Receiver& r : c.receivers) {
    const auto m = edgeMoments(c.run.moments, r.v);
    const double t = gpuReceiverDepth(r.d, applyBias ? s.bias.constant : 0.0);
    expected.push_back(rt::cpu::chebyshevUpperBound(m[0], m[1], t, s.moments.minVariance, s.moments.bleedingReduction));
  }
  return expected;
}

TEST_F(ClosedFormLookupTest, VsmChebyshevOnTwoDepthsEqualsFormula) {
  const VsmCase c = runVsmEdge(context());
  ASSERT_NE(c.cf, nullptr);
  ASSERT_EQ(c.cf->spec.bias.kind, BiasKind::Constant);
  ASSERT_FALSE(c.run.moments.empty());
  EXPECT_TRUE(visibilityMatches(c.run.visibility, chebyshevReference(c, true), c.receivers, 1e-5));
  // Not vacuous: the receivers span lit, penumbra and dark values.
  const auto [lo, hi] = std::minmax_element(c.run.visibility.begin(), c.run.visibility.end());
  EXPECT_LT(*lo, 0.05);
  EXPECT_EQ(*hi, 1.0f);
}

// Sibling: the formula without the receiver bias is a wrong reference and must be caught.
TEST_F(ClosedFormLookupTest, VsmChebyshevWrongReferenceFails) {
  const VsmCase c = runVsmEdge(context());
  ASSERT_NE(c.cf, nullptr);
  EXPECT_FALSE(visibilityMatches(c.run.visibility, chebyshevReference(c, false), c.receivers, 1e-5));
}

// ---- Plain VSM on the stacked-planes set-up (lauritzen2008 sec. 3.1, Fig. 2, eq. 4) -------------
// Occluder A (depth a) left of column 128, occluder B (depth b) right of it, receiver C (depth
// c) behind both: truly in umbra. At u = 0.5 the symmetric blur and the half-half bilinear fetch
// see exactly equal parts of A and B, the case of eq. (4).
constexpr double kA = 0.2, kB = 0.45;

std::vector<float> stackedMap() {
  std::vector<float> d(size_t(kMap) * kMap);
  for (uint32_t y = 0; y < kMap; ++y)
    for (uint32_t x = 0; x < kMap; ++x) d[size_t(y) * kMap + x] = float(x < kMap / 2 ? kA : kB);
  return d;
}

struct StackedCase {
  const CompiledFilter* cf;
  std::vector<Receiver> receivers;
  std::vector<double> depthsSeen;  // receiver t as the shader sees it
  LookupRun run;
};
StackedCase runStacked(rt::VulkanContext& ctx) {
  StackedCase c;
  c.cf = compileFilterCached("vsm_chebyshev", sampleSource("vsm_chebyshev"));
  if (!c.cf) return c;
  for (int i = 0; i < 8; ++i)
    for (double cd : {0.5, 0.6, 0.75, 0.9}) c.receivers.push_back({0.5, (32.0 * i + 16.5) / kMap, cd});
  for (const Receiver& r : c.receivers) c.depthsSeen.push_back(gpuReceiverDepth(r.d, c.cf->spec.bias.constant));
  c.run = runLookup(ctx, *c.cf, stackedMap(), c.receivers);
  return c;
}

TEST_F(ClosedFormLookupTest, PlainVsmBleedingOnStackedPlanesMatchesLauritzenEq4) {
  const StackedCase c = runStacked(context());
  ASSERT_NE(c.cf, nullptr);
  ASSERT_EQ(c.cf->spec.moments.layers, 1);
  ASSERT_EQ(c.cf->spec.moments.bleedingReduction, 0.0);
  std::vector<double> expected;
  for (double t : c.depthsSeen) expected.push_back(rt::cpu::vsmStackedPlanesBleeding(kA, kB, t));
  EXPECT_TRUE(visibilityMatches(c.run.visibility, expected, c.receivers, 1e-3));
}

// Sibling: the truth (0: C is in B's umbra) is not what plain VSM gives; the comparison with it
// fails by the size of eq. (4) (about 0.05-0.14 here).
TEST_F(ClosedFormLookupTest, PlainVsmBleedingIsNotTheTruth) {
  const StackedCase c = runStacked(context());
  ASSERT_NE(c.cf, nullptr);
  EXPECT_FALSE(visibilityMatches(c.run.visibility, std::vector<double>(c.receivers.size(), 0.0), c.receivers, 1e-3));
}

// ---- PCF n x n grid -----------------------------------------------------------------------------
// Depths quantized to k/32 and receivers at (k + 0.5)/32 + 0.004 (before a 1e-3 bias) keep every
// comparison at least 1/100 away from a tie; receiver uv at quarter-texel offsets keep the grid
// origin floor(u size - n/2 + 0.5) away from rounding boundaries. So the GPU and the double
// reference must agree to fp32 rounding of the average (1e-5).
std::vector<float> quantizedDepth() {
  std::vector<float> d(size_t(kMap) * kMap);
  uint64_t s = 77;
  for (auto& v : d) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    // Blocky (4x4 runs would need 2D; values correlated along x) so kernels see mixed results.
    v = float(double((s >> 40) % 33) / 32.0);
  }
  return d;
}

std::vector<Receiver> pcfReceivers() {
  std::vector<Receiver> rs;
  uint64_t s = 5;
  auto next = [&](uint32_t n) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return uint32_t((s >> 33) % n);
  };
  for (uint32_t i = 0; i < kScreen * kScreen; ++i) {
    // Include texels at the border (clamp-to-edge) for the first few.
    const uint32_t tx = i < 4 ? (i % 2 ? kMap - 1 : 0) : next(kMap), ty = i < 4 ? (i / 2 ? kMap - 1 : 0) : next(kMap);
    const double fx = next(2) ? 0.25 : 0.75, fy = next(2) ? 0.25 : 0.75;
    rs.push_back({(tx + fx) / kMap, (ty + fy) / kMap, (next(32) + 0.5) / 32.0 + 0.004});
  }
  return rs;
}

struct PcfCase {
  const CompiledFilter* cf;
  std::vector<Receiver> receivers;
  std::vector<float> depth;
  LookupRun run;
};
PcfCase runPcf(rt::VulkanContext& ctx) {
  PcfCase c;
  c.cf = compileFilterCached("pcf_grid5x5", sampleSource("pcf_grid5x5"));
  if (!c.cf) return c;
  c.receivers = pcfReceivers();
  c.depth = quantizedDepth();
  c.run = runLookup(ctx, *c.cf, c.depth, c.receivers);
  return c;
}

std::vector<double> pcfReference(const PcfCase& c, int n, double texelShift) {
  // The receivers face the light centre, so the slope-scaled bias is its constant.
  const double bias = c.cf->spec.bias.constant;
  const rt::cpu::ImageView depth{c.depth.data(), kMap, kMap, 1};
  std::vector<double> expected;
  for (const Receiver& r : c.receivers)
    expected.push_back(rt::cpu::pcfGridAt(depth, r.u + texelShift / kMap, r.v, n, r.d, bias));
  return expected;
}

TEST_F(ClosedFormLookupTest, PcfGrid5x5EqualsCpuPcf) {
  const PcfCase c = runPcf(context());
  ASSERT_NE(c.cf, nullptr);
  ASSERT_EQ(c.cf->spec.kernel.fixedTexels, 5);
  ASSERT_EQ(c.cf->spec.sampling.gridN, 5);
  EXPECT_TRUE(visibilityMatches(c.run.visibility, pcfReference(c, 5, 0.0), c.receivers, 1e-5));
  // Not vacuous: partial coverage happens.
  int partial = 0;
  for (float v : c.run.visibility) partial += (v > 0.01f && v < 0.99f) ? 1 : 0;
  EXPECT_GT(partial, int(c.receivers.size()) / 2);
}

// Siblings: the grid one texel off, or a 3x3 kernel, are wrong references and must be caught.
TEST_F(ClosedFormLookupTest, PcfWrongReferencesFail) {
  const PcfCase c = runPcf(context());
  ASSERT_NE(c.cf, nullptr);
  EXPECT_FALSE(visibilityMatches(c.run.visibility, pcfReference(c, 5, 1.0), c.receivers, 1e-5));
  EXPECT_FALSE(visibilityMatches(c.run.visibility, pcfReference(c, 3, 0.0), c.receivers, 1e-5));
}

// ---- MSM on the stacked-planes set-up (Peters & Klein 2015 sec. 3, Algorithm 3) -----------------
// The map of the plain-VSM check: at u = 0.5 the kernel holds equal parts of A (0.2) and B (0.45).
// Four moments determine two depths exactly, so the unbiased Hamburger bound is the truth in
// closed form (rt::cpu::msmTwoDepthVisibility): 1 in front of A, 1/2 between A and B, 0 behind B,
// where plain VSM leaks eq. (4). The moment bias moves the bound by O(alpha): in double, on these
// receivers, 8.9e-4 for fp32's alpha 3e-6 and 8.7e-3 for 16-bit's 3e-5 (each test asserts it is
// under half its tolerance); the rest of the tolerance is fp32 evaluation and 16-bit rounding.
constexpr double kMsmTolerance = 0.003;
constexpr double kMsm16Tolerance = 0.02;

struct MsmCase {
  const CompiledFilter* cf;
  std::vector<Receiver> receivers;
  std::vector<double> depthsSeen;
  LookupRun run;
};
MsmCase runMsmStacked(rt::VulkanContext& ctx, const std::string& label, const std::string& source) {
  MsmCase c;
  c.cf = compileFilterCached(label, source);
  if (!c.cf) return c;
  for (int i = 0; i < 8; ++i)
    for (double d : {0.1, 0.15, 0.3, 0.4, 0.5, 0.6, 0.75, 0.9})
      c.receivers.push_back({0.5, (32.0 * i + 16.5) / kMap, d});
  for (const Receiver& r : c.receivers) c.depthsSeen.push_back(gpuReceiverDepth(r.d, c.cf->spec.bias.constant));
  c.run = runLookup(ctx, *c.cf, stackedMap(), c.receivers);
  return c;
}

std::vector<double> msmClosedForm(const MsmCase& c, double weightOfA) {
  std::vector<double> expected;
  for (double t : c.depthsSeen) expected.push_back(rt::cpu::msmTwoDepthVisibility(kA, kB, weightOfA, t));
  return expected;
}

// Largest deviation of the biased double-precision bound from the closed form on these receivers.
double msmBiasEffect(const MsmCase& c) {
  rt::cpu::Moments4 m{};
  for (double z : {kA, kB}) {
    const auto p = rt::cpu::msmPowerMoments(z);
    for (int i = 0; i < 4; ++i) m[i] += 0.5 * p[i];
  }
  double worst = 0;
  for (double t : c.depthsSeen)
    worst = std::max(worst, std::fabs(rt::cpu::msmVisibility(m, t, c.cf->spec.moments.momentBias, 0) -
                                      rt::cpu::msmTwoDepthVisibility(kA, kB, 0.5, t)));
  return worst;
}

TEST_F(ClosedFormLookupTest, MsmOnStackedPlanesEqualsTwoDepthClosedForm) {
  const MsmCase c = runMsmStacked(context(), "msm_blur", sampleSource("msm_blur"));
  ASSERT_NE(c.cf, nullptr);
  ASSERT_EQ(c.cf->spec.moments.warp, Warp::Msm);
  ASSERT_EQ(c.cf->spec.storage.format, StorageFormat::Fp32);
  const double bias = msmBiasEffect(c);
  std::printf("msm fp32: alpha %g moves the double bound by %.3g\n", c.cf->spec.moments.momentBias, bias);
  EXPECT_LT(bias, kMsmTolerance / 2);
  const auto match = visibilityMatches(c.run.visibility, msmClosedForm(c, 0.5), c.receivers, kMsmTolerance);
  std::printf("msm fp32 GPU vs closed form: %s\n", match.message());
  EXPECT_TRUE(match);
}

TEST_F(ClosedFormLookupTest, MsmUnorm16QuantizedOnStackedPlanesEqualsTwoDepthClosedForm) {
  const MsmCase c = runMsmStacked(context(), "msm_unorm16", sampleSource("msm_unorm16"));
  ASSERT_NE(c.cf, nullptr);
  ASSERT_EQ(c.cf->spec.storage.format, StorageFormat::Unorm16);
  const double bias = msmBiasEffect(c);
  std::printf("msm unorm16: alpha %g moves the double bound by %.3g\n", c.cf->spec.moments.momentBias, bias);
  EXPECT_LT(bias, kMsm16Tolerance / 2);
  const auto match = visibilityMatches(c.run.visibility, msmClosedForm(c, 0.5), c.receivers, kMsm16Tolerance);
  std::printf("msm unorm16 GPU vs closed form: %s\n", match.message());
  EXPECT_TRUE(match);
}

// Siblings: (1) the largest bias the checker accepts (1e-2) pulls the bound toward b* by more
// than the tolerance — the check sees a mis-set reconstruction; (2) the closed form with the
// wrong weight (A covering 3/4) is a wrong reference and must be caught.
TEST_F(ClosedFormLookupTest, MsmPerturbedReconstructionExceedsTolerance) {
  std::string source = sampleSource("msm_blur");
  const std::string from = "msm(moment_bias: 0.000003)";
  ASSERT_NE(source.find(from), std::string::npos);
  source.replace(source.find(from), from.size(), "msm(moment_bias: 0.01)");
  const MsmCase big = runMsmStacked(context(), "msm_blur_bias_1e-2", source);
  ASSERT_NE(big.cf, nullptr);
  ASSERT_EQ(big.cf->spec.moments.momentBias, 0.01);
  EXPECT_FALSE(visibilityMatches(big.run.visibility, msmClosedForm(big, 0.5), big.receivers, kMsmTolerance));
  const MsmCase c = runMsmStacked(context(), "msm_blur", sampleSource("msm_blur"));
  ASSERT_NE(c.cf, nullptr);
  EXPECT_FALSE(visibilityMatches(c.run.visibility, msmClosedForm(c, 0.75), c.receivers, kMsmTolerance));
}

}  // namespace
}  // namespace shadowc::test

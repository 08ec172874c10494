// Form-factor weights (`weights form_factor`, docs/dsl.md "weights") against a closed form: a
// square light of width W in the light view's plane z = 0, an occluding half-plane x < 0 at depth
// zb parallel to it, receivers on the plane z = zr facing the light (identity light view,
// accuracy_harness.h). A receiver p sees light point q past the edge when the segment q -> p
// crosses z = zb at x >= 0, i.e. q_x >= X* = -p_x zb / (zr - zb). The shadowing term (docs/scenes.md
// "Ground truth") weighs q by cos cos / r^2 = zr^2 / |q - p|^4 on these parallel planes, so
//     V(p) = I(visible part) / I(light),   I(R) = integral over rectangle R of zr^2 / |q - p|^4 dq,
// and I of an axis-aligned rectangle is four corner terms of the point-to-parallel-rectangle form
// factor (Howell's catalogue, C-11; written out in cornerIntegral below).
// The compiled filter is VSSM with a 16 x 16 uniform kernel on an int32 SAT with fractional
// corners: on two depths the Chebyshev bound is exact and eq. 4 gives the blocker depth, so what
// is left is the midpoint rule of the weights over each sub-kernel (the one column the edge cuts
// errs by at most (dx / 8) |d omega / dx| of its weight); the test also computes that discrete
// sum in double to show the two parts apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

using ClosedFormWeightsTest = VulkanTest;

constexpr uint32_t kMap = 256;
constexpr uint32_t kScreen = 16;        // 256 receiver slots
constexpr double kW = 4.0;              // light width (world = light view units)
constexpr double kZb = 3.0, kZr = 6.0;  // occluder and receiver planes (light-view depth)
constexpr int kN = 16;                  // sub-kernels per axis
constexpr double kTolerance = 1e-3;

double normalized(double z) { return (z - kNear) / (kFar - kNear); }

// The filter: VSSM, uniform blocker and a 16 x 16 uniform kernel, exact box means, a tiny
// constant bias (with the receiver exactly on the floor's depth it only has to cover rounding).
std::string filterSource(bool weighted) {
  return std::string(
             "filter weights_closed_form {\n"
             "    light     area(size: scene)\n"
             "    moments   linear\n"
             "    storage   sat(int32, corners: bilinear)\n"
             "    blocker   moments(uniform(m: 5))\n"
             "    kernel    uniform(n: 16)\n"
             "    fallback  none\n"
             "    bias      constant(0.00001)\n") +
         (weighted ? "    weights   form_factor\n" : "") + "}\n";
}

// Occluder (depth zb) on texels x < kMap / 2 (light-view x < 0 at every depth), floor elsewhere.
std::vector<float> halfPlaneMap() {
  std::vector<float> d(size_t(kMap) * kMap);
  for (uint32_t y = 0; y < kMap; ++y)
    for (uint32_t x = 0; x < kMap; ++x)
      d[size_t(y) * kMap + x] = float(x < kMap / 2 ? normalized(kZb) : normalized(kZr));
  return d;
}

// Receivers on the floor plane, three rows of 64 across the penumbra (X* from beyond one side of
// the light to beyond the other); every kernel stays inside the map.
std::vector<std::array<double, 2>> receiverPositions() {
  std::vector<std::array<double, 2>> ps;
  for (double py : {0.0, 1.5, -2.5})
    for (int k = 0; k < 64; ++k) ps.push_back({-2.2 + 4.4 * k / 63.0, py});
  return ps;
}

// Integral over [0, a] x [0, b] of h^2 / (x^2 + y^2 + h^2)^2 (times a constant that cancels in V):
// odd in a and in b, so any rectangle is four signed corners.
double cornerIntegral(double a, double b, double h) {
  const double x = a / h, y = b / h, sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
  return x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy);
}
double rectIntegral(double x0, double x1, double y0, double y1, double h) {
  return cornerIntegral(x1, y1, h) - cornerIntegral(x0, y1, h) - cornerIntegral(x1, y0, h) + cornerIntegral(x0, y0, h);
}

// The closed form above.
double weightedVisibility(double px, double py) {
  const double xs = std::clamp(-px * kZb / (kZr - kZb), -kW / 2, kW / 2);
  return rectIntegral(xs - px, kW / 2 - px, -kW / 2 - py, kW / 2 - py, kZr) /
         rectIntegral(-kW / 2 - px, kW / 2 - px, -kW / 2 - py, kW / 2 - py, kZr);
}
// What a uniformly weighted filter estimates: the visible fraction of the light.
double unweightedVisibility(double px) { return (kW / 2 - std::clamp(-px * kZb / (kZr - kZb), -kW / 2, kW / 2)) / kW; }

// The filter's own sum in double: the kN x kN sub-kernels of the penumbra kernel (frame.glsl's
// width for the exact blocker depth), each its visible fraction times the weight at its centre.
double midpointVisibility(double px, double py) {
  const double c[2] = {(0.5 + 0.5 * px / kZr) * kMap, (0.5 + 0.5 * py / kZr) * kMap};
  const double w = kMap * (kW / 2) * (kZr - kZb) / (kZb * kZr);
  double num = 0, den = 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      const double x0 = c[0] - w / 2 + i * w / kN, x1 = x0 + w / kN;
      const double y0 = c[1] - w / 2 + j * w / kN, y1 = y0 + w / kN;
      const double lit = std::clamp((x1 - kMap / 2.0) / (x1 - x0), 0.0, 1.0);
      const double qx = ((x0 + x1) / 2 - c[0]) * kW / w, qy = ((y0 + y1) / 2 - c[1]) * kW / w;
      const double r2 = (qx - px) * (qx - px) + (qy - py) * (qy - py) + kZr * kZr;
      const double omega = kZr * kZr / (r2 * r2);
      num += omega * lit;
      den += omega;
    }
  return num / den;
}

std::vector<double> gpuVisibility(rt::VulkanContext& ctx, bool weighted) {
  const CompiledFilter* cf =
      compileFilterCached(weighted ? "weights_closed_form" : "weights_closed_form_uniform", filterSource(weighted));
  if (!cf) return {};
  EXPECT_EQ(cf->spec.formFactorWeights, weighted);
  const auto ps = receiverPositions();
  std::vector<float> pos(size_t(kScreen) * kScreen * 4, 0.0f), nrm(pos.size(), 0.0f);
  for (size_t i = 0; i < ps.size(); ++i) {
    pos[i * 4 + 0] = float(ps[i][0]);
    pos[i * 4 + 1] = float(ps[i][1]);
    pos[i * 4 + 2] = float(kZr);
    pos[i * 4 + 3] = 1.0f;
    nrm[i * 4 + 2] = -1.0f;  // facing the light plane
  }
  const CraftedGBuffer g{rt::HostImage::fromFloats(kScreen, kScreen, ImageFormat::RGBA32F, pos),
                         rt::HostImage::fromFloats(kScreen, kScreen, ImageFormat::RGBA32F, nrm)};
  const rt::RunOutputs out = rt::runPasses(
      ctx, cf->passes,
      craftedInputs(kMap, kScreen, kScreen, identityFrame(kMap, kScreen, kScreen, float(kW)), halfPlaneMap(), g),
      rt::RunOptions{});
  return std::vector<double>(out.visibility.begin(), out.visibility.begin() + long(ps.size()));
}

::testing::AssertionResult within(const std::vector<double>& got, const std::vector<double>& expected,
                                  double tolerance) {
  if (got.size() != expected.size() || got.empty()) return ::testing::AssertionFailure() << "nothing compared";
  const MaxError m = maxAbsError(got, expected);
  const auto p = receiverPositions()[m.index];
  if (m.error <= tolerance) return ::testing::AssertionSuccess() << "max error " << m.error;
  return ::testing::AssertionFailure() << fmt::format(
             "receiver ({:.3f}, {:.3f}): got {:.6f}, expected {:.6f}, error {:.3g} > {:.3g}", p[0], p[1], got[m.index],
             expected[m.index], m.error, tolerance);
}

std::vector<double> closedForm() {
  std::vector<double> v;
  for (const auto& p : receiverPositions()) v.push_back(weightedVisibility(p[0], p[1]));
  return v;
}

TEST_F(ClosedFormWeightsTest, WeightedVssmMatchesTheFormFactorIntegral) {
  const std::vector<double> gpu = gpuVisibility(context(), true);
  EXPECT_TRUE(within(gpu, closedForm(), kTolerance));
  // The parts apart: the filter's own discrete sum is within the midpoint rule's error of the
  // integral, and the GPU computes that sum up to the variance floor below.
  std::vector<double> midpoint;
  for (const auto& p : receiverPositions()) midpoint.push_back(midpointVisibility(p[0], p[1]));
  EXPECT_TRUE(within(midpoint, closedForm(), kTolerance));
  // The GPU's part: a sub-kernel wholly behind the occluder has variance 0, raised to the int32
  // SAT's variance floor v (sat.glsl, shadowc_satVarianceFloor), so Chebyshev leaves it
  // v / (v + (d_floor - d_occluder)^2) lit; fp32 and the bias add less than 1e-5.
  const double v = 2.4e-5, gap = normalized(kZr) - normalized(kZb);
  EXPECT_TRUE(within(gpu, midpoint, v / (gap * gap) + 1e-5));
  // Not vacuous: the receivers span the umbra-free penumbra from dark to lit.
  const auto [lo, hi] = std::minmax_element(gpu.begin(), gpu.end());
  EXPECT_LT(*lo, 0.02);
  EXPECT_GT(*hi, 0.98);
}

// Sibling: the same filter without weights estimates the visible fraction of the light, which
// misses the closed form by far more than the tolerance (0.046 at worst here)...
TEST_F(ClosedFormWeightsTest, UnweightedVssmFailsTheFormFactorIntegral) {
  const std::vector<double> gpu = gpuVisibility(context(), false);
  ASSERT_FALSE(gpu.empty());
  EXPECT_FALSE(within(gpu, closedForm(), kTolerance));
  // ...while it is the visible fraction, so the set-up itself is right.
  std::vector<double> fraction;
  for (const auto& p : receiverPositions()) fraction.push_back(unweightedVisibility(p[0]));
  EXPECT_TRUE(within(gpu, fraction, kTolerance));
}

}  // namespace
}  // namespace shadowc::test

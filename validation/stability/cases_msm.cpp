// Moment shadow mapping hard cases (Peters & Klein 2015): zero variance (a single depth makes the
// Hankel matrix of the unbiased moments singular), depths exactly 0 and 1 (the two-point set where
// a (0.5, 0.5, 0.5, 0.5) bias target would stay singular), and the 16-bit quantization of sec. 4.3
// (unorm16 and the int32 16.16 SAT) on a noisy map. The intent reference is Algorithm 3 in double
// on the exact power moments (rt::cpu::msmVisibility), with the filter's own moment bias.
#include "validation/stability/case_support.h"

namespace shadowc::validation {
namespace {

constexpr uint32_t kMap = 128;

const std::vector<FilterSpec>& msmFilters() {
  static const std::vector<FilterSpec> f = {
      libraryFilter("msm", "moments msm\nblur box(radius: 2)"),
      libraryFilter("msm_unorm16", "moments msm\nstorage unorm16\nblur box(radius: 2)"),
      libraryFilter("msm_sat", "moments msm\nstorage sat(int32)\nkernel fixed(5)"),
  };
  return f;
}

bool isMsm(const FilterSpec& s) { return isMoments(s) && s.moments.warp == Warp::Msm; }

std::vector<Receiver> gridReceivers(const std::vector<double>& depths) {
  std::vector<Receiver> rs;
  for (double d : depths)
    for (int i = 0; i < 6; ++i) rs.push_back(atTexel(kMap, 17 + 19 * i, 23 + 13 * i, d));
  return rs;
}

bool sixteenBits(const FilterSpec& s) {
  return s.storage.sat == SatKind::Int32 ||
         (s.storage.sat == SatKind::None && s.storage.format == StorageFormat::Unorm16);
}

// Bounds: about 2-10x the values measured on lavapipe, each with its cause (docs/stability.md).
CaseResult bounded(double bound, const std::string& reason) {
  CaseResult r;
  r.bound = bound;
  r.boundReason = reason;
  return r;
}

}  // namespace

void addMsmCases(std::vector<StabilityCase>& out) {
  const auto all = msmFilters();

  out.push_back(makeCase(
      "msm_zero_variance", "flat map at 0.4: receivers in front, on (after bias), 5e-3 .. 0.55 behind", all, isMsm,
      [](SuiteContext& ctx, const FilterSpec& s) {
        return evaluate(ctx,
                        bounded(5e-3,
                                "rank-1 Hankel matrix: only the bias keeps D22, D33 ~ alpha > 0, so fp32 rounding "
                                "(~1e-8) of b4 - b2^2 - L32^2 D22 moves the bound by ~1e-8 / alpha; measured 2.7e-3"),
                        s, constantMap(kMap, 0.4f),
                        gridReceivers({0.2, 0.4, 0.4 + s.bias.constant, 0.405, 0.41, 0.6, 0.95}), LightFrame{});
      }));

  out.push_back(makeCase(
      "msm_depths_0_and_1", "checkerboard of depths exactly 0 and 1: receivers 0.25 .. 0.999", all, isMsm,
      [](SuiteContext& ctx, const FilterSpec& s) {
        return evaluate(ctx,
                        bounded(sixteenBits(s) ? 1e-4 : 1e-5,
                                "two depths: the biased Hankel matrix is well conditioned (D33 ~ alpha), error is "
                                "storage rounding (2^-17 for 16 bits) x O(1); measured 1.1e-5 / 9e-7"),
                        s, checkerMap(kMap, 0.0f, 1.0f), gridReceivers({0.25, 0.5, 0.75, 0.999}), LightFrame{});
      }));

  out.push_back(makeCase("msm_quantization_noise", "noise 0.05..0.95, receivers 0.1 .. 0.99", all, isMsm,
                         [](SuiteContext& ctx, const FilterSpec& s) {
                           return evaluate(
                               ctx,
                               bounded(sixteenBits(s) ? 2e-4 : 2e-5,
                                       sixteenBits(s) ? "16-bit rounding (2^-17) of the quantized moments, x Theta^-1 "
                                                        "(<= 1), on well-conditioned 25-texel mixes; measured 2.7e-5"
                                                      : "fp32 moments and evaluation of Algorithm 3; measured 2.3e-6"),
                               s, noiseMap(kMap, 11, 0.05, 0.95), gridReceivers({0.1, 0.3, 0.5, 0.7, 0.9, 0.99}),
                               LightFrame{});
                         }));
}

}  // namespace shadowc::validation

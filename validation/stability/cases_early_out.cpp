// Min-max early out (vssm-yang2010 sec. 6.1, Algorithm 1 L8-L10; templates/lookup/minmax.glsl):
// the early out must be exact, so every texel that can influence the result has to be inside the
// min-max rectangle it reads. Two ways it was not:
//   * the rectangle clamps to the pyramid's top level, where it can span 3 cells per axis, and
//     only the 2 x 2 corner cells were fetched: an occluder in the middle cell was missed;
//   * the blur of plain moments spreads an occluder `radius` texels further than the kernel,
//     and the rectangle ignored it: receivers next to an occluder were declared lit.
// The intent reference (intent_reference.cpp) decides the early out over the exact rectangle.
#include <fmt/format.h>

#include "validation/stability/case_support.h"

namespace shadowc::validation {
namespace {

constexpr uint32_t kMap = 128;

// The top pyramid level of `max: 8` has 8-texel cells; the search rectangle is 8 texels wide and
// the influence rectangle 10, so a receiver at texel 16a + 11 reads cells 2a .. 2a + 2. The 4x4
// occluder blocks sit only in the middle cells (texels 16a + 10 .. 16a + 13).
DepthMap middleCellBlocks() {
  DepthMap m = constantMap(kMap, 0.8f);
  for (uint32_t y = 0; y < kMap; ++y)
    for (uint32_t x = 0; x < kMap; ++x)
      if (x % 16 >= 10 && x % 16 <= 13 && y % 16 >= 10 && y % 16 <= 13) m.depth[size_t(y) * kMap + x] = 0.3f;
  return m;
}

// A 4-texel occluder stripe (x in [60, 63]) at 0.3 on a floor at 0.8; receivers at 0.78, 2..6
// texels beside it: their blurred mean lies below 0.78 (Chebyshev < 1), the kernel holds only
// floor texels (min 0.8 >= d: the old early out said lit).
DepthMap stripe() {
  DepthMap m = constantMap(kMap, 0.8f);
  for (uint32_t y = 0; y < kMap; ++y)
    for (uint32_t x = 60; x < 64; ++x) m.depth[size_t(y) * kMap + x] = 0.3f;
  return m;
}

CaseResult satBound() {
  CaseResult r;
  r.bound = 5e-4;
  r.boundReason = "16.16 quantization of the mean moves Chebyshev by ~2e-3 p";
  return r;
}

}  // namespace

void addEarlyOutCases(std::vector<StabilityCase>& out) {
  const auto hasEarlyOut = [](const FilterSpec& s) { return s.earlyOutMinMax; };

  const std::vector<FilterSpec> vssm = {
      libraryFilter("vssm_minmax_max8",
                    "moments linear\nstorage sat(int32)\nblocker moments\nkernel uniform(4, max: "
                    "8)\nfallback pcf(2x2)\nearly_out minmax"),
  };
  out.push_back(makeCase("minmax_three_top_cells",
                         "occluders only in the middle one of the 3 top-level min-max cells an influence rectangle "
                         "spans (pyramid cell 2^ceil(log2 max) < max + 2)",
                         vssm, hasEarlyOut, [](SuiteContext& ctx, const FilterSpec& s) {
                           std::vector<Receiver> rs;
                           for (int a = 0; a < 7; ++a)
                             for (int b = 0; b < 7; ++b) rs.push_back(atTexel(kMap, 16 * a + 11, 16 * b + 11, 0.6));
                           return evaluate(ctx, satBound(), s, middleCellBlocks(), rs, LightFrame{});
                         }));

  const std::vector<FilterSpec> blurred = {
      libraryFilter("vsm_blur6_minmax", "moments linear\nblur box(radius: 6)\nearly_out minmax"),
      libraryFilter("vsm_gauss8_minmax", "moments linear\nblur gaussian(radius: 8)\nearly_out minmax"),
  };
  out.push_back(makeCase(
      "minmax_blur_footprint",
      "receivers 2..6 texels beside an occluder stripe, within the blur radius but outside the "
      "kernel: the early out must cover the blur footprint",
      blurred, [](const FilterSpec& s) { return s.earlyOutMinMax && !hasSat(s); },
      [](SuiteContext& ctx, const FilterSpec& s) {
        std::vector<Receiver> rs;
        for (int dx = 2; dx <= 6; ++dx)
          for (int y : {20, 64, 100}) {
            rs.push_back(atTexel(kMap, 63 + dx, y, 0.78));
            rs.push_back(atTexel(kMap, 60 - dx, y, 0.78));
          }
        CaseResult r;
        r.bound = 1e-4;
        r.boundReason = "same formula in fp32: ~1e-7 per moment x condition <= 1e3";
        return evaluate(ctx, r, s, stripe(), rs, LightFrame{});
      }));
}

}  // namespace shadowc::validation

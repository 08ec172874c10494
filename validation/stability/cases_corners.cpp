// SAT box corners: with whole-texel corners the box of a kernel snaps to the
// texel grid, so the visibility of a receiver moving across a texel does not change and jumps at
// the texel boundary (blocky penumbrae under magnification). Fractional corners (sat.glsl,
// `sat(int32, corners: bilinear)`) integrate the moments under the continuous box. Both forms
// are compared with the reference of the continuous box (intent_reference.cpp, boxMeanFrac) on
// receivers 1/8 texel apart across a straight occluder edge; the texel form is the naive row.
#include <fmt/format.h>

#include <cmath>

#include "validation/stability/case_support.h"

namespace shadowc::validation {
namespace {

constexpr uint32_t kSize = 128;

// Occluder at 0.3 left of x = 64 (texel boundary), empty receiver plane at 0.9 right of it.
DepthMap edgeMap() {
  DepthMap m = constantMap(kSize, 0.9f);
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < 64; ++x) m.depth[size_t(y) * kSize + x] = 0.3f;
  return m;
}

std::vector<Receiver> acrossTheEdge() {
  std::vector<Receiver> rs;
  for (int i = 0; i <= 96; ++i) rs.push_back({(58.0 + i / 8.0) / kSize, 64.5 / kSize, 0.6, std::nullopt});
  return rs;
}

FilterSpec withCorners(const std::string& name, const std::string& body, bool fractional) {
  return libraryFilter(name,
                       fmt::format("{}\nstorage sat(int32, corners: {})", body, fractional ? "bilinear" : "texel"));
}

// The pairs: moments (VSM) with a fixed 9-texel kernel, and VSSM with one penumbra box.
const char* const kVsm = "moments linear\nkernel fixed(9)";
const char* const kVssm = "light area(size: scene)\nmoments linear\nblocker moments(none)\nkernel penumbra(max: 64)";

CaseResult cornersCase(SuiteContext& ctx, const FilterSpec& s) {
  CaseResult r;
  r.filter = s.name;
  r.naive = !s.storage.fractionalCorners;
  // The continuous box's reference: the same filter with fractional corners.
  FilterSpec ideal = s;
  ideal.storage.fractionalCorners = true;
  // Bound: the 16.16 moments round by 2^-17 (box means within 7.7e-6, sat_box_mean_*) and the
  // fp32 corner weights by 2^-24 of the box; Chebyshev's slope on this edge (variance >= 0.02
  // wherever the box straddles it) keeps the visibility within 1e-4 of the double reference,
  // 1e-3 leaves room for fp32 kernel widths. A texel-corner box is off by up to half the
  // visibility change per texel (about 1/9 of the edge's contrast for the 9-texel kernel).
  r.bound = 1e-3;
  r.boundReason = "continuous-box reference: int32 box means within 7.7e-6, fp32 corner weights";
  const DepthMap map = edgeMap();
  const std::vector<Receiver> rs = acrossTheEdge();
  LightFrame light;
  light.lightWidth = 0.3;  // search box ~12 texels, penumbra ~6 texels on this map
  const CraftedResult run = runCrafted(ctx.vk, compileCached(s), map, rs, light);
  countValues(r, run.visibility);
  const IntentReference reference(ideal, map, light);
  r.worstError = 0;
  double step = 0;  // largest change between neighbouring receivers (1/8 texel apart)
  for (size_t i = 0; i < rs.size(); ++i) {
    const std::vector<double> ref = reference(rs[i]);
    if (ref.empty()) continue;
    double err = INFINITY;
    for (double v : ref) err = std::min(err, std::fabs(double(run.visibility[i]) - v));
    if (std::isnan(double(run.visibility[i]))) err = INFINITY;
    if (i > 0) step = std::max(step, std::fabs(double(run.visibility[i]) - double(run.visibility[i - 1])));
    if (err > r.worstError) {
      r.worstError = err;
      r.detail = fmt::format("worst: receiver x {:.3f} texels, GPU {:.6g} vs continuous box {:.6g}", rs[i].u * kSize,
                             run.visibility[i], ref[0]);
    }
  }
  r.detail += fmt::format("; largest step between receivers 1/8 texel apart {:.3g}", step);
  settle(r);
  return r;
}

}  // namespace

void addCornerCases(std::vector<StabilityCase>& out) {
  out.push_back(makeCase("sat_fractional_corners",
                         "receivers 1/8 texel apart across an occluder edge, int32 SAT with texel and fractional "
                         "corners, against the continuous box",
                         {withCorners("vsm_sat_fractional", kVsm, true), withCorners("vsm_sat_texel", kVsm, false),
                          withCorners("vssm_fractional", kVssm, true), withCorners("vssm_texel", kVssm, false)},
                         {}, cornersCase));
}

}  // namespace shadowc::validation

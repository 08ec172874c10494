// VSSM contact path (vssm-yang2010 sec. 6.4): where blocker and receiver nearly touch, a few
// bilinear PCF taps replace the SAT estimate. A defect this guards: the blocker walk returned "lit"
// when eq. 4 found no blocker mass (1 - P <= 1e-4, which is exactly what a receiver a hair behind
// a flat occluder gives) before the contact test ran, so touching receivers came out fully lit.
// The intent reference does not model the contact path; here the truth is known exactly: every
// texel of a flat occluder lies in front of the receiver, so the PCF taps give 0.
#include <fmt/format.h>

#include <cmath>

#include "validation/stability/case_support.h"

namespace shadowc::validation {

void addContactCases(std::vector<StabilityCase>& out) {
  const std::vector<FilterSpec> f = {
      libraryFilter("vssm_contact",
                    "moments linear\nstorage sat(int32)\nblocker moments\nkernel uniform(4)\n"
                    "fallback pcf(2x2)\ncontact pcf(3x3, epsilon: 0.005)"),
      libraryFilter("vssm_quadtree_contact",
                    "moments linear\nstorage sat(int32)\nblocker moments\n"
                    "kernel quadtree(height: 3)\nfallback pcf(2x2)\ncontact pcf(3x3)"),
  };
  out.push_back(makeCase(
      "contact_before_no_blocker_lit",
      "flat occluder 0.4, receivers 2e-5..1e-3 behind it (after bias): 1 - P < 1e-4, contact PCF must give 0", f,
      [](const FilterSpec& s) { return isVssm(s) && s.contact.enabled; },
      [](SuiteContext& ctx, const FilterSpec& s) {
        constexpr uint32_t kMap = 128;
        CaseResult r;
        r.filter = s.name;
        r.bound = 1e-6;
        r.boundReason = "every PCF tap is occluded: exactly 0";
        std::vector<Receiver> rs;
        for (double e : {2e-5, 1e-4, 1e-3})
          for (int i = 0; i < 6; ++i) rs.push_back(atTexel(kMap, 17 + 19 * i, 23 + 13 * i, 0.4 + s.bias.constant + e));
        const CraftedResult run = runCrafted(ctx.vk, compileCached(s), constantMap(kMap, 0.4f), rs, LightFrame{});
        countValues(r, run.visibility);
        r.worstError = 0;
        for (size_t i = 0; i < rs.size(); ++i) {
          const double err = std::isnan(run.visibility[i]) ? INFINITY : std::fabs(double(run.visibility[i]));
          if (err > r.worstError) {
            r.worstError = err;
            r.detail = fmt::format("worst: receiver {} (d {:.6g}) GPU {:.7g} vs 0", i, rs[i].d, run.visibility[i]);
          }
        }
        settle(r);
        return r;
      }));
}

}  // namespace shadowc::validation

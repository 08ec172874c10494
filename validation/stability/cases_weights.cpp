// Stability of form-factor weights (`weights form_factor`, templates/lookup/kernel.glsl): a large
// light close to the receivers, and receivers whose tangent plane grazes the light's edge or has
// the whole light behind it, where every tap's weight (n . v)+ p_z^3 / |v|^4 is 0 and the weighted
// mean would be 0 / 0 without the 1e-12 floor each weight carries. On an empty map (depth 1: every
// tap lit) the weighted mean of ones is 1 whatever the weights, so the reference is exact; the
// naive row drops the floor (SHADOWC_NAIVE_UNGUARDED) and gives NaN where the light is behind.
#include <fmt/format.h>

#include <cmath>

#include "validation/stability/case_support.h"

namespace shadowc::validation {
namespace {

constexpr uint32_t kMap = 128;
constexpr double kPi = 3.14159265358979;

const std::vector<FilterSpec>& weightedFilters() {
  static const std::vector<FilterSpec> f = [] {
    const std::string common = "\nbackface filtered\nweights form_factor";  // filter the back-facing too
    std::vector<FilterSpec> v = {
        libraryFilter("pcf_weighted", "depth\nsampling grid(3x3)" + common),
        libraryFilter("pcss_weighted", "depth\nblocker search(16)\nkernel penumbra" + common),
        libraryFilter("vssm_weighted",
                      "moments linear\nstorage sat(int32)\nblocker moments\nkernel uniform(4)" + common),
    };
    FilterSpec naive = libraryFilter("pcf_weighted_unfloored", "depth\nsampling grid(3x3)" + common);
    naive.naiveUnguarded = true;
    v.push_back(naive);
    return v;
  }();
  return f;
}

}  // namespace

void addWeightsCases(std::vector<StabilityCase>& out) {
  // Light width 8 at z = 0; receivers at x = 0 and depth d (z = near + d (far - near), as low as
  // 1.05, so the light is 8 times wider than its distance). Normals: facing the light, and
  // (sin a, 0, -cos a) 2 degrees short of and past a* = 90 deg + atan(4 / z), where the light's edge
  // x = +4 lies in the tangent plane (light_behind_tangent_plane's geometry): short of it a sliver
  // of the light weighs, past it none.
  out.push_back(makeCase(
      "weights_large_light_and_horizon", "empty map, light 8 wide at z 1.05..6, normals facing it, grazing, behind",
      weightedFilters(), {}, [](SuiteContext& ctx, const FilterSpec& s) {
        LightFrame light;
        light.lightWidth = 8;
        CaseResult r = bounded(s);
        r.naive = s.naiveUnguarded;
        std::vector<Receiver> rs;
        for (double d : {0.005, 0.1, 0.5}) {
          const double z = light.nearZ + d * (light.farZ - light.nearZ);
          const double edge = 0.5 * kPi + std::atan2(4.0, z);
          Receiver facing = atTexel(kMap, kMap / 2, 20 + 80 * d, d);
          facing.u = 0.5;  // x = 0 exactly
          rs.push_back(facing);
          for (double k : {-1.0, 1.0}) {
            Receiver rc = facing;
            const double a = edge + k * 2.0 * kPi / 180.0;
            rc.normal = std::array<double, 3>{std::sin(a), 0.0, -std::cos(a)};
            rs.push_back(rc);
          }
        }
        r.filter = s.name;
        const CraftedResult run = runCrafted(ctx.vk, compileCached(s), constantMap(kMap, 1.0f), rs, light);
        countValues(r, run.visibility);
        r.worstError = 0;
        for (size_t i = 0; i < rs.size(); ++i) {
          const double e = std::fabs(double(run.visibility[i]) - 1.0);
          if (!(e <= r.worstError)) {
            r.worstError = std::isnan(e) ? INFINITY : e;
            static const char* kinds[] = {"facing the light", "2 deg short of the edge", "2 deg past the edge"};
            r.detail = fmt::format("worst: receiver {} (d {:.3g}, {}) GPU {:.7g} vs 1", i, rs[i].d, kinds[i % 3],
                                   run.visibility[i]);
          }
        }
        settle(r);
        return r;
      }));
}

}  // namespace shadowc::validation

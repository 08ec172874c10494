// Randomized filters: valid descriptions within docs/dsl.md's ranges, generated as DSL text from
// (seed, index), compiled in process (the driver; spirv-val runs inside) and run on a random map
// with random receivers: never a checker error, invalid SPIR-V, NaN, Inf or a value outside [0, 1].
#include <fmt/format.h>

#include <cmath>

#include "validation/stability/case_support.h"

namespace shadowc::validation {
namespace {

struct Rng {
  uint64_t state;
  uint64_t next() { return state = mix64(state); }
  int range(int lo, int hi) { return lo + int(next() % uint64_t(hi - lo + 1)); }  // inclusive
  double uniform(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) / double(1ull << 53); }
  bool coin() { return next() & 1; }
};

std::string num(double v) { return fmt::format("{:.4g}", v); }

}  // namespace

std::string randomFilterSource(uint64_t seed, int index) {
  Rng g{mix64(seed) ^ mix64(uint64_t(index) + 0x51ab)};
  std::string body;
  auto line = [&](const std::string& s) { body += "    " + s + "\n"; };
  const int family = g.range(0, 2);
  if (g.coin()) line(fmt::format("light area(size: {})", num(g.uniform(0.01, 1.0))));
  switch (g.range(0, 2)) {
    case 0:
      line(fmt::format("bias constant({})", num(g.uniform(0, 0.01))));
      break;
    case 1:
      line(fmt::format("bias slope({}, constant: {})", num(g.uniform(0, 0.05)), num(g.uniform(0, 0.005))));
      break;
    default:
      line(fmt::format("bias normal_offset({})", num(g.uniform(0, 2))));
      break;
  }
  if (family == 0) {  // depth: hard / PCF / PCSS
    line("depth");
    const int s = g.range(0, 2);
    if (s == 0) line(fmt::format("sampling grid({0}x{0})", g.range(1, 7)));
    if (s == 1) line(fmt::format("sampling bilinear({0}x{0})", g.range(1, 5)));
    if (s == 2) line(fmt::format("sampling poisson(taps: {})", g.range(1, 32)));
    if (g.coin())
      line(fmt::format("blocker search(taps: {}, pattern: {})", g.range(1, 32), g.coin() ? "grid" : "poisson"));
  } else if (family == 1) {  // filtered moments
    const char* warps[] = {"linear", "exp", "evsm2", "evsm4", "power_cdf"};
    const std::string warp = warps[g.range(0, 4)];
    const bool fp16 = g.range(0, 3) == 0;
    std::string args;
    if (warp == "exp" || warp == "evsm2") args = num(fp16 ? g.uniform(0.5, 5.5) : g.uniform(1, 42));
    if (warp == "evsm4")
      args = num(fp16 ? g.uniform(0.5, 5.5) : g.uniform(1, 42)) + ", " +
             num(fp16 ? g.uniform(0.5, 5.5) : g.uniform(1, 42));
    const int layers = g.range(0, 2) == 0 ? g.range(2, 4) : 1;
    if (layers > 1)
      args += std::string(args.empty() ? "" : ", ") +
              fmt::format("layers: {}, overlap: {}", layers, num(g.uniform(0, 0.05)));
    line(fmt::format("moments {}({})", warp, args));
    if (fp16) line("storage fp16");
    if (g.coin()) line(fmt::format("blur {}(radius: {})", g.coin() ? "box" : "gaussian", g.range(1, 4)));
    if (g.coin()) line("mips on");
    if (warp != "exp" && warp != "power_cdf" && g.coin())
      line(fmt::format("bleeding reduce({})", num(g.uniform(0, 0.45))));
  } else {  // VSSM
    line("moments linear");
    line("storage sat(int32)");
    line(g.coin() ? fmt::format("blocker moments(uniform(m: {}))", g.range(1, 6))
                  : fmt::format("blocker moments(quadtree(height: {}))", g.range(1, 3)));
    line(g.coin() ? fmt::format("kernel uniform({}, max: {})", g.range(1, 6), g.range(8, 64))
                  : fmt::format("kernel quadtree(height: {}, max: {})", g.range(1, 3), g.range(8, 64)));
    if (g.coin()) line(fmt::format("fallback pcf({0}x{0})", g.range(1, 3)));
    if (g.coin()) line(fmt::format("contact pcf({0}x{0}, epsilon: {1})", g.range(1, 4), num(g.uniform(0.001, 0.05))));
    if (g.coin()) line("early_out minmax");
    if (g.coin()) line(fmt::format("bleeding reduce({})", num(g.uniform(0, 0.45))));
  }
  return fmt::format("filter random_{}_{} {{\n{}}}\n", seed, index, body);
}

CaseResult runRandomFilter(SuiteContext& ctx, uint64_t seed, int index) {
  CaseResult r;
  r.caseName = fmt::format("random_seed{}_{}", seed, index);
  r.filter = fmt::format("random_{}_{}", seed, index);
  // No reference models every random filter: the measured error is the distance outside [0, 1].
  r.bound = 0;
  r.boundReason = "no reference: validity, finiteness and the distance outside [0, 1]";
  const std::string text = randomFilterSource(seed, index);
  try {
    const FilterSpec spec = specFromSource(text, r.filter);
    const CompiledFilter& cf = compileCached(spec);  // spirv-val inside: invalid SPIR-V throws
    Rng g{mix64(seed * 31 + uint64_t(index))};
    const uint32_t size = 64;
    DepthMap map = noiseMap(size, g.next(), g.uniform(0, 0.5), g.uniform(0.5, 1));
    for (size_t i = 0; i < map.depth.size(); i += size_t(g.range(1, 7))) map.depth[i] = 1.0f;  // empty texels
    std::vector<Receiver> rs;
    for (int i = 0; i < 64; ++i)
      rs.push_back({g.uniform(-0.05, 1.05), g.uniform(-0.05, 1.05), g.uniform(-0.1, 1.1), std::nullopt});
    LightFrame light;
    light.lightWidth = g.uniform(0.01, 2);
    const CraftedResult run = runCrafted(ctx.vk, cf, map, rs, light);
    countValues(r, run.visibility);
    r.worstError = worstOutside(run.visibility);
  } catch (const std::exception& e) {
    r.detail = e.what();
    r.pass = false;
    return r;
  }
  settle(r);
  if (!r.pass) r.detail = fmt::format("{} non-finite, {} out of [0, 1] of {}", r.nonFinite, r.outOfRange, r.values);
  return r;
}

}  // namespace shadowc::validation

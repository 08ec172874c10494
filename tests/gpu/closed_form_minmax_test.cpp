// The min-max pyramid built by the real compiled passes of a sample (the fused dispatches of
// minmax.comp: depth -> levels 0, 1, 2, then two levels a pass) equals a CPU pyramid built by
// the footprint rule, texel for texel and exactly (min and max round nothing), on an odd map
// size so that every level's last odd row and column take the edge path. The sibling drops
// the odd row/column from the CPU rule and must be caught. Validation on (VulkanTest).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"
#include "runtime/executor/pass_executor.h"

namespace shadowc::test {
namespace {

using ClosedFormMinMaxTest = VulkanTest;

constexpr uint32_t kMap = 197;  // levels 197, 98, 49, 24, 12, 6, 3: odd at 0, 2 and 6

struct Level {
  uint32_t size = 0;
  std::vector<std::array<float, 2>> mm;  // (min, max) per texel
};

std::vector<float> craftedDepth(uint32_t n) {
  std::vector<float> d(size_t(n) * n);
  uint64_t s = 0x243F6A8885A308D3ull;
  for (float& v : d) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    v = float(double(s >> 11) / double(1ull << 53));
  }
  // The far row and column hold the extremes, so a rule that drops them gets other values.
  for (uint32_t i = 0; i < n; ++i) {
    d[size_t(n - 1) * n + i] = i % 2 ? 0.0f : 1.0f;
    d[size_t(i) * n + (n - 1)] = i % 2 ? 1.0f : 0.0f;
  }
  return d;
}

// Level k from k-1: texel p covers [2p, last] with the last odd row/column folded into the
// last texel (vssm-yang2010 sec. 6.1 mip chain; minmax.comp shadowc_footprintLast).
std::vector<Level> cpuPyramid(const std::vector<float>& depth, uint32_t n, int levels, bool foldOddEdge) {
  std::vector<Level> out(1);
  out[0].size = n;
  for (float d : depth) out[0].mm.push_back({d, d});
  for (int k = 1; k < levels; ++k) {
    const Level& src = out.back();
    Level dst;
    dst.size = std::max(1u, src.size >> 1);
    for (uint32_t y = 0; y < dst.size; ++y)
      for (uint32_t x = 0; x < dst.size; ++x) {
        auto last = [&](uint32_t p) {
          const uint32_t odd = foldOddEdge && p == dst.size - 1 ? (src.size & 1) : 0;
          return std::min(2 * p + 1 + odd, src.size - 1);
        };
        std::array<float, 2> mm{1e30f, -1e30f};
        for (uint32_t sy = 2 * y; sy <= last(y); ++sy)
          for (uint32_t sx = 2 * x; sx <= last(x); ++sx) {
            const auto& v = src.mm[size_t(sy) * src.size + sx];
            mm = {std::min(mm[0], v[0]), std::max(mm[1], v[1])};
          }
        dst.mm.push_back(mm);
      }
    out.push_back(std::move(dst));
  }
  return out;
}

// Every level of the GPU pyramid, downloaded after one run of all passes.
std::vector<Level> gpuPyramid(rt::VulkanContext& ctx, const CompiledFilter& cf, const std::vector<float>& depth) {
  const CraftedGBuffer g = craftGBuffer({}, 8, 8);
  rt::PassExecutor ex(ctx, cf.passes, kMap, 8, 8);
  ex.setFrame(identityFrame(kMap, 8, 8, 0.5f));
  ex.upload("shadow_depth", rt::HostImage::fromFloats(kMap, kMap, ImageFormat::R32F, depth));
  ex.upload("gbuffer_position", g.position);
  ex.upload("gbuffer_normal", g.normal);
  ex.run();
  uint32_t levels = 0;
  for (const ImageDesc& im : cf.passes.manifest.images)
    if (im.name == "minmax") levels = uint32_t(im.mipLevels);
  std::vector<Level> out;
  for (uint32_t k = 0; k < levels; ++k) {
    const rt::HostImage h = ex.download("minmax", k, 0);
    Level l;
    l.size = h.width;
    for (uint32_t y = 0; y < h.height; ++y)
      for (uint32_t x = 0; x < h.width; ++x) l.mm.push_back({h.texel(x, y, 0), h.texel(x, y, 1)});
    out.push_back(std::move(l));
  }
  return out;
}

// Number of texels (over all levels) that differ; `first` names one.
uint64_t differences(const std::vector<Level>& gpu, const std::vector<Level>& cpu, std::string& first) {
  uint64_t bad = 0;
  for (size_t k = 0; k < std::min(gpu.size(), cpu.size()); ++k) {
    if (gpu[k].size != cpu[k].size) {
      first = fmt::format("level {} is {} wide, expected {}", k, gpu[k].size, cpu[k].size);
      return ~0ull;
    }
    for (size_t i = 0; i < cpu[k].mm.size(); ++i)
      if (gpu[k].mm[i] != cpu[k].mm[i] && bad++ == 0)
        first = fmt::format("level {} texel ({}, {}): ({}, {}) != ({}, {})", k, i % cpu[k].size, i / cpu[k].size,
                            gpu[k].mm[i][0], gpu[k].mm[i][1], cpu[k].mm[i][0], cpu[k].mm[i][1]);
  }
  return bad;
}

// The vssm_minmax_early_out sample with its kernel max written as 64: a 7-level pyramid (the
// sample's own default max is the whole map, a 9-level pyramid that needs a map of 256^2 or more).
const char* const kMinMaxFilter = R"(filter minmax_max64 {
    moments   linear
    storage   sat(int32)
    blocker   moments
    kernel    uniform(4, max: 64)
    early_out minmax
    fallback  pcf(2x2)
})";

TEST_F(ClosedFormMinMaxTest, EveryLevelEqualsTheCpuPyramidExactly) {
  const CompiledFilter* cf = compileFilterCached("minmax_max64", kMinMaxFilter);
  ASSERT_NE(cf, nullptr);
  const std::vector<float> depth = craftedDepth(kMap);
  const std::vector<Level> gpu = gpuPyramid(context(), *cf, depth);
  ASSERT_EQ(gpu.size(), 7u);
  const std::vector<Level> cpu = cpuPyramid(depth, kMap, int(gpu.size()), true);
  std::string first;
  EXPECT_EQ(differences(gpu, cpu, first), 0u) << first;
  // Fewer dispatches than levels: 0-2, 3-4, 5-6.
  int dispatches = 0;
  for (const Pass& p : cf->passes.manifest.passes) dispatches += p.kind == "minmax";
  EXPECT_EQ(dispatches, 3);
}

TEST_F(ClosedFormMinMaxTest, ARuleWithoutTheOddEdgeIsCaught) {
  const CompiledFilter* cf = compileFilterCached("minmax_max64", kMinMaxFilter);
  ASSERT_NE(cf, nullptr);
  const std::vector<float> depth = craftedDepth(kMap);
  const std::vector<Level> gpu = gpuPyramid(context(), *cf, depth);
  std::string first;
  EXPECT_GT(differences(gpu, cpuPyramid(depth, kMap, int(gpu.size()), false), first), 0u);
}

}  // namespace
}  // namespace shadowc::test

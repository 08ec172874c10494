// light_bench: frame time at the largest light ÷ at the smallest, measured interleaved (a
// benchmark, never a test: it prints medians, nothing here can fail CI).
//
// The light-size study (`shadowc sweep bench/sweeps/light_size_study.json`) runs one light after
// another, minutes apart; on a shared 2-core VM a cell moves by ±30 % with the neighbours' load,
// and a ratio of two cells is only as good as the noisier one (docs/performance.md "Light-size
// study"). Here each variant of the same sweep description runs on the smallest and on the
// largest light of each map size through the run harness's interleaved timing
// (rt::timeInterleaved: both warmed up, then round after round one timed frame of each), so that
// both cells of the ratio see the same minute. Per variant and map it prints both medians, their
// ratio, the median and range of the per-round ratios, and the shade pass's ratio; then, at the
// largest light, every variant in turn against the first (the study's PCSS-16): the
// "VSSM shade ≤ 2× PCSS-16" ratio from the same minutes.
//
// Usage: light_bench [sweep.json] [rounds] [variant-substring]
//   defaults: bench/sweeps/light_size_study.json, 15 rounds after the sweep's warm-ups, every
//   variant. Run with MESA_SHADER_CACHE_DISABLE=true so that runs are comparable.
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "compiler/driver/driver.h"
#include "runtime/harness/run_harness.h"
#include "runtime/harness/scene_run.h"
#include "runtime/vulkan/vulkan_context.h"
#include "shadowc_source_dir.h"
#include "sweep/expand.h"
#include "sweep/sweep_scene.h"
#include "sweep/sweep_spec.h"

namespace fs = std::filesystem;
using namespace shadowc;

namespace {

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return one.empty() ? "?" : one;
}

std::string utcNow() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", std::gmtime(&t));
  return buf;
}

double shadeMs(const rt::TimingResult& t) {
  double ms = 0;
  for (const rt::PassTiming& p : t.passes)
    if (p.kind == "shade") ms += p.medianMs;
  return ms;
}

// Round k's frame of `num` ÷ round k's frame of `den` (both from one rt::timeInterleaved call).
std::vector<double> roundRatios(const rt::TimingResult& num, const rt::TimingResult& den) {
  std::vector<double> r;
  for (size_t k = 0; k < num.runTotalsMs.size(); ++k) r.push_back(num.runTotalsMs[k] / den.runTotalsMs[k]);
  return r;
}

}  // namespace

int main(int argc, char** argv) try {
  const fs::path file =
      argc > 1 ? fs::path(argv[1]) : fs::path(SHADOWC_SOURCE_DIR) / "bench" / "sweeps" / "light_size_study.json";
  const int rounds = argc > 2 ? std::max(1, std::atoi(argv[2])) : 15;
  const std::string only = argc > 3 ? argv[3] : "";
  const sweep::SweepSpec spec = sweep::loadSweepSpec(file);
  const sweep::Expansion e = sweep::expand(spec);

  // The smallest and the largest light of the description (derived scenes under a scratch folder).
  const fs::path scratch = fs::temp_directory_path() / "shadowc_light_bench";
  struct Light {
    sweep::SceneEntry entry;
    sweep::ResolvedScene resolved;
  };
  std::vector<Light> lights;
  for (const sweep::SceneEntry& s : spec.scenes) lights.push_back({s, sweep::resolveScene(s, scratch)});
  if (lights.size() < 2) throw std::invalid_argument(file.string() + ": needs at least two scenes (lights)");
  const auto [smallest, largest] =
      std::minmax_element(lights.begin(), lights.end(),
                          [](const Light& a, const Light& b) { return a.resolved.lightWidth < b.resolved.lightWidth; });

  struct Compiled {
    std::string label;
    CompiledPasses passes;
    int mapSize = 0;
  };
  std::vector<Compiled> variants;
  for (const sweep::Variant& v : e.variants) {
    if (v.shader != sweep::ShaderKind::Specialized || v.label.find(only) == std::string::npos) continue;
    const driver::Result r = driver::compileSource(v.text, v.label);
    if (!r.artifact || !r.spec) {
      fmt::print(stderr, "skipping {}:\n{}", v.label, r.log);
      continue;
    }
    variants.push_back({v.label, r.artifact->passes(), r.spec->mapSize});
  }

  rt::VulkanContext ctx;
  const uint32_t screen = spec.screens.front();
  fmt::print(
      "light_bench {} ({}), {} UTC, device {}, load average {} at the start; {}² screen, light {} against {}, {} "
      "warm-ups each, then {} rounds of one frame on each light (order reversed every other round); ms are "
      "medians over the rounds\n\n",
      file.filename().string(), spec.name, utcNow(), ctx.describe(), loadAverage(), screen, largest->entry.label,
      smallest->entry.label, spec.warmup, rounds);
  const auto start = std::chrono::steady_clock::now();
  for (uint32_t map : spec.maps) {
    auto prepare = [&](const Light& l) {
      rt::SceneSettings settings;
      settings.scene = l.resolved.nameOrPath;
      settings.screen = screen;
      settings.map = map;
      settings.traceReference = false;  // RMSE is the study's; this measures time only
      return rt::prepareScene(ctx, settings);
    };
    const auto small = prepare(*smallest), large = prepare(*largest);
    fmt::print("**{}² map**\n\n", map);
    fmt::print(
        "| variant | frame ms, light {} | frame ms, light {} | largest ÷ smallest (medians) | per-round ratio: median "
        "[min–max] | shade largest ÷ smallest |\n|---|---:|---:|---:|---|---:|\n",
        smallest->resolved.lightWidth, largest->resolved.lightWidth);
    for (const Compiled& v : variants) {
      if (int(map) > v.mapSize) {
        fmt::print("| {} | – | – | – | map {} exceeds its map_size {} | – |\n", v.label, map, v.mapSize);
        continue;
      }
      const rt::RunInputs inSmall = rt::sceneInputs(v.passes, *small), inLarge = rt::sceneInputs(v.passes, *large);
      const std::vector<rt::TimingResult> t =
          rt::timeInterleaved(ctx, {{&v.passes, &inSmall}, {&v.passes, &inLarge}}, spec.warmup, rounds);
      const std::vector<double> perRound = roundRatios(t[1], t[0]);
      const auto [lo, hi] = std::minmax_element(perRound.begin(), perRound.end());
      fmt::print("| {} | {:.1f} | {:.1f} | {:.2f} | {:.2f} [{:.2f}–{:.2f}] | {:.2f} |\n", v.label, t[0].totalMs,
                 t[1].totalMs, t[1].totalMs / t[0].totalMs, rt::median(perRound), *lo, *hi,
                 shadeMs(t[1]) / shadeMs(t[0]));
      std::fflush(stdout);
      fmt::print(stderr, "light_bench: {} map {}: {:.0f} s\n", v.label, map,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    fmt::print("\n");

    // At the largest light, every variant in turn, against the first (the study's PCSS-16): the
    // shade and frame ratios from the same minutes, as the light ratio above.
    std::vector<const Compiled*> fit;
    for (const Compiled& v : variants)
      if (int(map) <= v.mapSize) fit.push_back(&v);
    if (fit.size() < 2) continue;
    std::vector<rt::RunInputs> inputs;
    for (const Compiled* v : fit) inputs.push_back(rt::sceneInputs(v->passes, *large));
    std::vector<rt::TimedRun> runs;
    for (size_t i = 0; i < fit.size(); ++i) runs.push_back({&fit[i]->passes, &inputs[i]});
    const std::vector<rt::TimingResult> t = rt::timeInterleaved(ctx, runs, spec.warmup, rounds);
    fmt::print(
        "At light {}, all {} variants in turn ({} rounds), against {}:\n\n| variant | frame ms | shade ms | frame ÷ "
        "anchor (per-round median) | shade ÷ anchor (medians) |\n|---|---:|---:|---:|---:|\n",
        largest->resolved.lightWidth, fit.size(), rounds, fit[0]->label);
    for (size_t i = 0; i < fit.size(); ++i)
      fmt::print("| {} | {:.1f} | {:.1f} | {:.2f} | {:.2f} |\n", fit[i]->label, t[i].totalMs, shadeMs(t[i]),
                 rt::median(roundRatios(t[i], t[0])), shadeMs(t[i]) / shadeMs(t[0]));
    fmt::print("\n");
    std::fflush(stdout);
    fmt::print(stderr, "light_bench: every variant at light {} map {}: {:.0f} s\n", largest->resolved.lightWidth, map,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  fmt::print("{:.0f} s wall, load average {} at the end\n",
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), loadAverage());
  return 0;
} catch (const std::exception& ex) {
  fmt::print(stderr, "light_bench: error: {}\n", ex.what());
  return 1;
}

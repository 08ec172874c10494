// clock_bench: does a timed run report the time it took (a benchmark, never a test)? For each
// sample filter and screen size, N timed runs through the run harness; per run the reported total
// (on the clock the executor chose, or the one asked for) beside the host's submit-to-fence time
// of the same run (docs/runtime.md "Timing method"). Prints, per sample: the clock, the accepted
// and rejected runs, the reported and host medians, and min and median of reported ÷ host over the
// accepted runs, and the min over every reading including the rejected ones.
// Usage: clock_bench [--runs N=200] [--warmup N=3] [--clock auto|device|host] [--sizes 256,512]
//                    [--map N=1024] [--scene two_planes] [sample ...]
#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/driver/driver.h"
#include "runtime/harness/scene_run.h"
#include "runtime/vulkan/vulkan_context.h"
#include "shadowc_source_dir.h"

namespace fs = std::filesystem;
using namespace shadowc;

namespace {

struct Args {
  int runs = 200, warmup = 3;
  rt::ClockChoice clock = rt::ClockChoice::Auto;
  std::string clockName = "auto";
  std::vector<uint32_t> sizes{256, 512};
  uint32_t map = 1024;
  std::string scene = "two_planes";
  // A PCF grid, a Poisson PCF, a PCSS, a VSM and a VSSM with its PCF fallback.
  std::vector<std::string> samples{"pcf_grid5x5", "pcf_poisson16", "pcss_poisson", "vsm_chebyshev",
                                   "vssm_pcf_fallback"};
};

Args parse(int argc, char** argv) {
  Args a;
  std::vector<std::string> named;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(s + " needs a value");
      return argv[++i];
    };
    if (s == "--runs") {
      a.runs = std::max(1, std::atoi(next().c_str()));
    } else if (s == "--warmup") {
      a.warmup = std::max(0, std::atoi(next().c_str()));
    } else if (s == "--clock") {
      a.clockName = next();
      if (a.clockName == "auto") a.clock = rt::ClockChoice::Auto;
      else if (a.clockName == "device") a.clock = rt::ClockChoice::Device;
      else if (a.clockName == "host") a.clock = rt::ClockChoice::Host;
      else throw std::invalid_argument("--clock is auto, device or host, not '" + a.clockName + "'");
    } else if (s == "--sizes") {
      a.sizes.clear();
      std::stringstream in(next());
      for (std::string item; std::getline(in, item, ',');) a.sizes.push_back(uint32_t(std::atoi(item.c_str())));
    } else if (s == "--map") {
      a.map = uint32_t(std::atoi(next().c_str()));
    } else if (s == "--scene") {
      a.scene = next();
    } else {
      named.push_back(s);
    }
  }
  if (!named.empty()) a.samples = named;
  return a;
}

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

void row(const std::string& sample, uint32_t size, const rt::TimingResult& t) {
  std::vector<double> ratios;
  for (size_t k = 0; k < t.runTotalsMs.size(); ++k) ratios.push_back(t.runTotalsMs[k] / t.runHostMs[k]);
  double minAll = ratios.empty() ? 0 : *std::min_element(ratios.begin(), ratios.end());
  for (const rt::RejectedRun& r : t.rejected) minAll = std::min(minAll, r.hostMs > 0 ? r.totalMs / r.hostMs : 0.0);
  fmt::print("| {} | {}² | {} | {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n", sample, size,
             rt::toString(t.clock), t.runs, t.rejected.size(), t.totalMs, rt::median(t.runHostMs),
             rt::median(ratios), ratios.empty() ? 0 : *std::min_element(ratios.begin(), ratios.end()), minAll);
}

}  // namespace

int main(int argc, char** argv) try {
  const Args a = parse(argc, argv);
  rt::VulkanContext ctx;
  fmt::print(
      "clock_bench, {} UTC, device {}, load average {} at the start; scene {}, {}² map, {} warm-ups, then {} "
      "accepted runs wanted per row, --clock {}\n\n",
      utcNow(), ctx.describe(), loadAverage(), a.scene, a.map, a.warmup, a.runs, a.clockName);
  fmt::print(
      "| sample | screen | clock | runs | rejected | reported median ms | host median ms | median reported ÷ host | "
      "min reported ÷ host | min ÷ host, rejected too |\n|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (uint32_t size : a.sizes) {
    rt::SceneSettings settings;
    settings.scene = a.scene;
    settings.screen = size;
    settings.map = a.map;
    settings.traceReference = false;  // time only
    const auto scene = rt::prepareScene(ctx, settings);
    for (const std::string& sample : a.samples) {
      const fs::path file = fs::path(SHADOWC_SOURCE_DIR) / "samples" / "filters" / (sample + ".shadow");
      const driver::Result r = driver::compileFile(file.string());
      if (!r.artifact) {
        fmt::print(stderr, "clock_bench: {} did not compile:\n{}", sample, r.log);
        return 1;
      }
      const CompiledPasses passes = r.artifact->passes();
      rt::RunOptions options;
      options.warmup = a.warmup;
      options.runs = a.runs;
      options.clock = a.clock;
      const rt::RunOutputs out = rt::runPasses(ctx, passes, rt::sceneInputs(passes, *scene), options);
      row(sample, size, *out.timing);
    }
  }
  fmt::print("\nload average {} at the end\n", loadAverage());
  return 0;
} catch (const std::exception& e) {
  fmt::print(stderr, "clock_bench: {}\n", e.what());
  return 1;
}

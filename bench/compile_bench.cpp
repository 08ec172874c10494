// compile_bench: what in-process compilation buys. For each sample filter, the median of N
//   (a) in-process compiles of the emitted GLSL (glslang + -O recipe + spirv-val, linked in),
//   (b) a full in-process compile by the driver (load, check, plan, specialize, preprocess,
//       compile, lookup, manifest: driver::compileFile),
//   (c) the same work as (a) done by running the glslangValidator, spirv-opt and spirv-val
//       programs on the emitted GLSL files (std::system: allowed here, in the benchmark only).
// Prints a markdown table and the ratio (c)/(a). Usage: compile_bench [N] [sample-substring].
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "compiler/driver/driver.h"
#include "runtime/executor/pass_executor.h"  // rt::median
#include "shadowc_source_dir.h"

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

std::string recipeFlags() {
  std::string s;
  for (const auto& f : shadowc::driver::optimizationRecipe()) s += " " + f;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const std::string only = argc > 2 ? argv[2] : "";
  std::vector<fs::path> samples;
  for (const auto& e : fs::directory_iterator(fs::path(SHADOWC_SOURCE_DIR) / "samples" / "filters"))
    if (e.path().extension() == ".shadow" && e.path().stem().string().find(only) != std::string::npos)
      samples.push_back(e.path());
  std::sort(samples.begin(), samples.end());
  const fs::path tmp = fs::temp_directory_path() / ("shadowc-compile-bench-" + std::to_string(::getpid()));
  const std::string recipe = recipeFlags();

  fmt::print(
      "| filter | shaders | in-process compile (ms) | full driver compile (ms) | glslangValidator + spirv-opt + "
      "spirv-val "
      "(ms) | external / in-process |\n");
  fmt::print("|---|---:|---:|---:|---:|---:|\n");
  std::vector<double> ratios;
  double sumIn = 0, sumExt = 0, sumFull = 0;
  for (const fs::path& file : samples) {
    const shadowc::driver::Result r = shadowc::driver::compileFile(file.string());
    if (!r.artifact) {
      fmt::print(stderr, "skipping {}: does not compile\n{}", file.filename().string(), r.log);
      continue;
    }
    const std::string name = r.artifact->spec.name;
    const fs::path dir = tmp / name;
    // stem, glsl, and the calls the driver keeps (an unrolled quadtree's node callbacks: the
    // same -O compile as the driver's; the external spirv-opt of (c) has no such option).
    const std::vector<shadowc::driver::ShaderText> shaders = shadowc::driver::shaderTexts(*r.artifact);
    // The external programs of (c) read the GLSL from disk.
    if (!shadowc::driver::writeArtifact(dir, *r.artifact).empty()) return 1;

    std::vector<double> in, full, ext;
    for (int i = 0; i < n; ++i) {
      auto t0 = Clock::now();
      for (const shadowc::driver::ShaderText& s : shaders) {
        std::string log;
        if (!shadowc::driver::compileShaderText(s, log)) {
          fmt::print(stderr, "{}", log);
          return 1;
        }
      }
      auto t1 = Clock::now();
      const auto again = shadowc::driver::compileFile(file.string());
      auto t2 = Clock::now();
      if (!again.ok) return 1;
      for (const shadowc::driver::ShaderText& s : shaders) {
        const std::string base = (dir / s.stem).string();
        const std::string cmd = "glslangValidator -S comp -V --target-env vulkan1.2 -o " + base + ".ext.spv " + base +
                                ".glsl >/dev/null && spirv-opt --target-env=vulkan1.2" + recipe + " " + base +
                                ".ext.spv -o " + base + ".opt.spv && spirv-val --target-env vulkan1.2 " + base +
                                ".opt.spv";
        if (std::system(cmd.c_str()) != 0) {
          fmt::print(stderr, "external pipeline failed on {}\n", base);
          return 1;
        }
      }
      auto t3 = Clock::now();
      in.push_back(ms(t0, t1));
      full.push_back(ms(t1, t2));
      ext.push_back(ms(t2, t3));
    }
    const double a = shadowc::rt::median(in), b = shadowc::rt::median(full), c = shadowc::rt::median(ext);
    sumIn += a, sumFull += b, sumExt += c;
    ratios.push_back(c / a);
    fmt::print("| {} | {} | {:.1f} | {:.1f} | {:.1f} | {:.2f}× |\n", name, shaders.size(), a, b, c, c / a);
  }
  fs::remove_all(tmp);
  if (ratios.empty()) return 1;
  fmt::print(
      "\n{} filters, {} runs each (medians). Totals: in-process compile {:.0f} ms, full driver compile {:.0f} ms, "
      "external programs {:.0f} ms; external/in-process: median {:.2f}×, total {:.2f}×\n",
      ratios.size(), n, sumIn, sumFull, sumExt, shadowc::rt::median(ratios), sumExt / sumIn);
  return 0;
}

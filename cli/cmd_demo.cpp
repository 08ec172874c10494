// `shadowc demo [-o DIR]`: the README's first command. Compiles a VSSM sample (adaptive
// quadtree kernel with PCF fallback, vssm-yang2010 Algorithm 2; embedded in the binary) and
// validates it on a built-in scene: per-pass times, error against the Embree reference, images
// in out/demo/. The sample takes its light width from the scene (`area(size: scene)`), so the
// filter and the ray-traced reference see the same light; samples/filters/vssm_adaptive.shadow folds
// a 0.04-wide light and would be compared against a different light.
// It ends with a small trade-off table (cheap PCF to VSSM on the same scene, through the sweep
// library: docs/sweep.md), so the first thing a newcomer sees is what accuracy costs in time.
#include <fmt/core.h>

#include <cstdio>
#include <string>

#include "cli/commands.h"
#include "cli/validation_run.h"
#include "sweep/frontier_table.h"
#include "sweep/sweep_run.h"

namespace shadowc::samples {
std::string_view find(std::string_view path);  // samples/filters/* embedded (cli/CMakeLists.txt)
}

namespace shadowc::cli {
namespace {

// From cheap PCF to VSSM: four embedded samples, each taking its light from the scene.
constexpr const char* kTradeoff[] = {"pcf_poisson16", "pcss_poisson", "vsm_chebyshev", "vssm_pcf_fallback"};

// The trade-off table: the four samples swept on the demo's scene and sizes. Rows are cached
// in OUT/tradeoff (a second demo runs nothing again); the reference is the one validate traced.
int tradeoffTable(const ValidationOptions& o, const std::string& out) {
  sweep::SweepSpec spec;
  spec.name = "demo";
  for (const char* name : kTradeoff) {
    const std::string file = std::string(name) + ".shadow";
    spec.filters.push_back({name, "embedded:samples/filters/" + file, std::string(samples::find(file)), {}, {}});
  }
  spec.scenes.push_back({std::filesystem::path(o.scene).stem().string(), o.scene, std::nullopt});
  spec.screens = {o.size};
  spec.maps = {o.map};
  spec.referenceSamples = o.samples;
  spec.runs = o.runs;
  spec.warmup = o.warmup;
  sweep::SweepOptions so;
  so.outDir = std::filesystem::path(out) / "tradeoff";
  so.device = o.device;
  so.validation = o.validation;
  std::fflush(stdout);
  const sweep::SweepOutcome r = sweep::runSweep(spec, so, stderr);
  std::fflush(stderr);
  fmt::print("\n{}", sweep::formatFrontierTables(r.results, /*allRows=*/true));
  fmt::print(
      "rows     {}/tradeoff/cache; a full study with plots and an HTML report:\n"
      "         shadowc sweep samples/sweeps/default.json -o out/sweep   (docs/sweep.md)\n",
      out);
  if (r.validationMessages > 0) {
    std::fflush(stdout);
    fmt::print(stderr, "shadowc: error: the validation layer reported {} message(s)\n", r.validationMessages);
    return 1;
  }
  return r.results.skipped.empty() ? 0 : 1;
}

}  // namespace

CommandRunner registerDemo(CLI::App& app) {
  auto o = std::make_shared<ValidationOptions>();
  auto out = std::make_shared<std::string>("out/demo");
  o->filterPath = "vssm_pcf_fallback.shadow";
  o->scene = "two_planes";
  o->size = 256;
  o->map = 1024;
  o->samples = 16;
  o->runs = 5;
  o->warmup = 2;
  CLI::App* sub = app.add_subcommand("demo", "Compile the VSSM sample and validate it on a built-in scene");
  sub->add_option("-o,--out", *out, "Directory for images and report.json")->capture_default_str();
  addRenamedOption(sub, "--output", "-o/--out");
  sub->add_option("--filter", o->filterPath, "Embedded sample to run (samples/filters/NAME)")->capture_default_str();
  sub->add_option("--scene", o->scene, "Built-in scene name or scene .json file")->capture_default_str();
  sub->add_option("--screen", o->size, "Screen width and height in pixels")->capture_default_str();
  addRenamedOption(sub, "--size", "--screen");
  sub->add_option("--device", o->device, "Vulkan device: index or name substring (default: llvmpipe)");
  sub->add_flag("--validate", o->validation, "Enable the Khronos validation layer; any message fails the run");
  return [o, out] {
    const std::string_view text = samples::find(o->filterPath);
    if (text.empty()) throw std::invalid_argument("no embedded sample '" + o->filterPath + "' (see samples/filters/)");
    ValidationOptions run = *o;
    run.filterSource = std::string(text);
    run.imagesDir = *out;
    run.jsonOut = *out + "/report.json";
    if (const int rc = runValidation(run); rc != 0) return rc;
    return tradeoffTable(*o, *out);
  };
}

}  // namespace shadowc::cli

// `shadowc validate FILTER.shadow --scene NAME|FILE`: compile, run on the Vulkan device with
// per-pass GPU timing, compare against the Embree ground truth. See docs/cli.md.
#include "cli/commands.h"
#include "cli/runs_option.h"
#include "cli/validation_run.h"

namespace shadowc::cli {

CommandRunner registerValidate(CLI::App& app) {
  auto o = std::make_shared<ValidationOptions>();
  CLI::App* sub =
      app.add_subcommand("validate", "Run a filter on a scene: per-pass GPU times and error vs. ray tracing");
  sub->add_option("filter", o->filterPath, "Filter description (.shadow), or a compiled manifest.json / its directory")
      ->required();
  sub->add_option("--scene", o->scene, "Built-in scene name or scene .json file")->required();
  sub->add_option("--screen", o->size, "Screen width and height in pixels")->capture_default_str();
  addRenamedOption(sub, "--size", "--screen");
  CLI::Option* map = sub->add_option("--map", o->map,
                                     "Shadow-map side in texels (default: the filter's `resolution` when it has one, "
                                     "else 1024)");
  sub->add_option("--samples", o->samples, "Reference light samples per axis (N x N)")->capture_default_str();
  sub->add_option("--json", o->jsonOut, "Write metrics and timings as JSON");
  sub->add_option("--images", o->imagesDir, "Write result/reference/error/comparison PNGs to this directory");
  sub->add_option("--device", o->device, "Vulkan device: index or name substring (default: llvmpipe)");
  sub->add_flag("--validate", o->validation, "Enable the Khronos validation layer; any message fails the run");
  addRunsOption(sub, o->runs, "Timed runs (the median and its interval are reported)");
  sub->add_option("--warmup", o->warmup, "Untimed warm-up runs (lavapipe JIT-compiles on first use)")
      ->capture_default_str();
  sub->add_option("--pass-form", o->passForm,
                  "Form of passes that have several: auto (by the device), serial, parallel (default: "
                  "env SHADOWC_PASS_FORM, else auto)");
  sub->add_flag("--counters", o->counters,
                "Also run the instrumented build once: texel fetches, moment bounds, walk steps per receiver "
                "(docs/manifest.md \"Work counters\"); the times are the plain build's");
  sub->add_flag(
      "--no-reference-cache", [o](int64_t) { o->useCache = false; },
      "Trace the Embree reference again (do not read or write the reference cache)");
  addRenamedOption(sub, "--no-cache", "--no-reference-cache", /*takesValue=*/false);
  return [o, map] {
    o->mapGiven = map->count() > 0;
    return runValidation(*o);
  };
}

}  // namespace shadowc::cli

// `shadowc demo [--out DIR]`: the README's first command. Compiles a VSSM sample (adaptive
// quadtree kernel with PCF fallback, vssm-yang2010 Algorithm 2; embedded in the binary) and
// validates it on a built-in scene: per-pass times, error against the Embree reference, images
// in out/demo/. The sample takes its light width from the scene (`area(size: scene)`), so the
// filter and the ray-traced reference see the same light; DESIGN.md's vssm_adaptive example folds
// a 0.04-wide light and would be compared against a different light.
#include <string>

#include "cli/commands.h"
#include "cli/validation_run.h"

namespace shadowc::samples {
std::string_view find(std::string_view path);  // samples/filters/* embedded (cli/CMakeLists.txt)
}

namespace shadowc::cli {

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
  sub->add_option("--out", *out, "Directory for images and report.json")->capture_default_str();
  sub->add_option("--filter", o->filterPath, "Embedded sample to run (samples/filters/NAME)")->capture_default_str();
  sub->add_option("--scene", o->scene, "Built-in scene name or scene .json file")->capture_default_str();
  sub->add_option("--size", o->size, "Screen width and height in pixels")->capture_default_str();
  sub->add_option("--device", o->device, "Vulkan device: index or name substring (default: llvmpipe)");
  sub->add_flag("--validate", o->validation, "Enable the Khronos validation layer; any message fails the run");
  return [o, out] {
    const std::string_view text = samples::find(o->filterPath);
    if (text.empty()) throw std::invalid_argument("no embedded sample '" + o->filterPath + "' (see samples/filters/)");
    ValidationOptions run = *o;
    run.filterSource = std::string(text);
    run.imagesDir = *out;
    run.jsonOut = *out + "/report.json";
    return runValidation(run);
  };
}

}  // namespace shadowc::cli

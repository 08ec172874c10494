// `shadowc analyze --scene S [--map N] [--screen N] [--json OUT]`: the scene statistics that
// decide which shadow features it needs (planning/scene_analysis.h, docs/planning.md). Rasterizes
// the light depth map and the G-buffer only: no reference is traced.
#include <fmt/core.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "cli/commands.h"
#include "planning/scene_analysis.h"
#include "runtime/images/atomic_file.h"
#include "runtime/vulkan/vulkan_context.h"

namespace shadowc::cli {

CommandRunner registerAnalyze(CLI::App& app) {
  struct Options {
    std::string scene, json, device;
    uint32_t map = 1024, screen = 256;
    double contactEpsilon = 0.01;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("analyze", "Scene statistics that decide shadow features (docs/planning.md)");
  sub->add_option("--scene", o->scene, "Built-in scene name or scene .json file")->required();
  sub->add_option("--map", o->map, "Shadow-map side in texels")->capture_default_str();
  sub->add_option("--screen", o->screen, "Screen width and height in pixels")->capture_default_str();
  addRenamedOption(sub, "--size", "--screen");
  sub->add_option("--contact-epsilon", o->contactEpsilon, "Contact distance, normalized depth")->capture_default_str();
  sub->add_option("--json", o->json, "Write the statistics as JSON here");
  sub->add_option("--device", o->device, "Vulkan device: index or name substring (default: llvmpipe)");
  return [o]() -> int {
    if (o->map == 0 || o->screen == 0 || !(o->contactEpsilon > 0))
      throw std::invalid_argument("--map, --screen and --contact-epsilon must be positive");
    rt::Scene scene = rt::loadScene(o->scene);  // scene errors before device errors
    rt::VulkanContext ctx(rt::VulkanOptions{o->device, false});
    rt::SceneSettings settings;
    settings.scene = o->scene;
    settings.map = o->map;
    settings.screen = o->screen;
    settings.traceReference = false;
    const auto prepared = rt::prepareScene(ctx, std::move(scene), settings);
    planning::AnalysisOptions options;
    options.contactEpsilon = o->contactEpsilon;
    const planning::SceneStats stats = planning::analyzeScene(*prepared, options);
    fmt::print("{}", planning::formatSummary(stats));
    if (!o->json.empty()) rt::writeFileAtomically(o->json, planning::toJson(stats).dump(2) + "\n");
    return 0;
  };
}

}  // namespace shadowc::cli

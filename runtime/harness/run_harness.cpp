#include "runtime/harness/run_harness.h"

#include <fmt/core.h>

#include <chrono>
#include <memory>

namespace shadowc::rt {
namespace {

// The harness input for a role, or nullptr for the filter's own images.
const HostImage* inputFor(ImageRole role, const RunInputs& inputs) {
  switch (role) {
    case ImageRole::InputDepth:
      return &inputs.lightDepth;
    case ImageRole::InputPosition:
      return &inputs.position;
    case ImageRole::InputNormal:
      return &inputs.normal;
    case ImageRole::Internal:
    case ImageRole::OutputVisibility:
      return nullptr;
  }
  return nullptr;
}

}  // namespace

RunOutputs runPasses(VulkanContext& ctx, const CompiledPasses& passes, const RunInputs& inputs,
                     const RunOptions& options) {
  if (options.warmup < 0 || options.runs < 0) throw ExecutorError("warm-up and timed run counts must be >= 0");
  RunOutputs out;
  const auto start = std::chrono::steady_clock::now();
  PassExecutor ex(ctx, passes, inputs.mapSize, inputs.width, inputs.height);
  out.pipelineCreateMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  ex.setFrame(inputs.frame);
  for (const ImageDesc& image : passes.manifest.images) {
    const HostImage* input = inputFor(image.role, inputs);
    if (!input) continue;
    if (input->width == 0 || input->height == 0)
      throw ExecutorError(
          fmt::format("image '{}' has role {}, but the run has no such input", image.name, toString(image.role)));
    ex.upload(image.name, *input);  // checks size, layers and format against the manifest
  }
  const std::string output = ex.imageWithRole(ImageRole::OutputVisibility);
  if (output.empty()) throw ExecutorError("the manifest has no output_visibility image");

  // The last run leaves the outputs in place for the downloads.
  if (options.runs > 0) {
    out.timing = ex.time(options.warmup, options.runs);
  } else {
    for (int i = 0; i <= options.warmup; ++i) ex.run();
  }
  out.visibility = ex.download(output).channel(0);
  for (const std::string& name : options.downloads) out.images.emplace(name, ex.download(name));
  return out;
}

}  // namespace shadowc::rt

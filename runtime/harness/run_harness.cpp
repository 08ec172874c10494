#include "runtime/harness/run_harness.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <memory>

#include "runtime/executor/busy_machine.h"

namespace shadowc::rt {
namespace {

// The harness input for a role, or nullptr for the filter's own images.
const HostImage* inputFor(ImageRole role, const RunInputs& inputs) {
  switch (role) {
    case ImageRole::InputDepth:
      return &inputs.lightDepth;
    case ImageRole::InputHardwareDepth:
      return &inputs.hardwareDepth;
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

// The frame and every input image by role; returns the output_visibility image's name.
std::string setInputs(PassExecutor& ex, const CompiledPasses& passes, const RunInputs& inputs) {
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
  return output;
}

}  // namespace

RunOutputs runPasses(VulkanContext& ctx, const CompiledPasses& passes, const RunInputs& inputs,
                     const RunOptions& options) {
  if (options.warmup < 0 || options.runs.runs < 0) throw ExecutorError("warm-up and timed run counts must be >= 0");
  RunOutputs out;
  const auto start = std::chrono::steady_clock::now();
  PassExecutor ex(ctx, passes, inputs.mapSize, inputs.width, inputs.height, options.passForm);
  out.forms = ex.formChoices();
  out.pipelineCreateMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  const std::string output = setInputs(ex, passes, inputs);

  // The last run leaves the outputs in place for the downloads, and an instrumented build's
  // counts of that one run (the counters start from the manifest's zeros before it).
  const bool counted = workCounterBuffer(passes.manifest) != nullptr;
  if (options.runs.any()) {
    const CpuWindow window = openCpuWindow();  // the machine's load while timing (busy_machine.h)
    out.timing = ex.time(options.warmup, options.runs, options.clock);
    out.timing->otherCpuShare = closeCpuWindow(window);
    if (counted) {
      ex.resetBuffers();
      ex.run();
    }
  } else {
    for (int i = 0; i <= options.warmup; ++i) {
      if (counted && i == options.warmup) ex.resetBuffers();
      ex.run();
    }
  }
  if (counted) {
    const BufferDesc& buffer = *workCounterBuffer(passes.manifest);
    out.work = workCountsFromWords(passes.manifest, ex.readBuffer(buffer.name));
  }
  out.visibility = ex.download(output).channel(0);
  for (const std::string& name : options.downloads) out.images.emplace(name, ex.download(name));
  return out;
}

std::vector<TimingResult> timeInterleaved(VulkanContext& ctx, const std::vector<TimedRun>& runs, int warmup, int rounds,
                                          ClockChoice clock) {
  if (warmup < 0 || rounds < 1) throw ExecutorError("interleaved timing needs warm-up >= 0 and rounds >= 1");
  std::vector<std::unique_ptr<PassExecutor>> ex;
  for (const TimedRun& r : runs) {
    if (!r.passes || !r.inputs) throw ExecutorError("interleaved timing: a run without passes or inputs");
    ex.push_back(std::make_unique<PassExecutor>(ctx, *r.passes, r.inputs->mapSize, r.inputs->width, r.inputs->height,
                                                r.passForm));
    setInputs(*ex.back(), *r.passes, *r.inputs);
  }
  for (auto& e : ex)
    for (int i = 0; i < warmup; ++i) e->run();
  // perRun[i][round] = that round's one-run timing of run i.
  std::vector<std::vector<TimingResult>> perRun(ex.size());
  const CpuWindow window = openCpuWindow();
  for (int round = 0; round < rounds; ++round)
    for (size_t k = 0; k < ex.size(); ++k) {
      const size_t i = round % 2 ? ex.size() - 1 - k : k;
      perRun[i].push_back(ex[i]->time(0, 1, clock));
    }
  const std::optional<double> otherShare = closeCpuWindow(window);
  std::vector<TimingResult> out(ex.size());
  for (size_t i = 0; i < ex.size(); ++i) {
    TimingResult& t = out[i];
    t.otherCpuShare = otherShare;
    t.warmup = warmup;
    t.runs = rounds;
    t.clock = perRun[i].front().clock;
    for (const TimingResult& one : perRun[i]) {
      t.runTotalsMs.push_back(one.totalMs);
      if (!one.runHostMs.empty()) t.runHostMs.push_back(one.runHostMs.front());
      t.rejected.insert(t.rejected.end(), one.rejected.begin(), one.rejected.end());
    }
    std::vector<double> overheads;
    for (const TimingResult& one : perRun[i]) overheads.push_back(one.submitOverheadMs);
    t.submitOverheadMs = median(overheads);
    t.totalMs = median(t.runTotalsMs);
    for (size_t p = 0; p < perRun[i].front().passes.size(); ++p) {
      std::vector<double> ms;
      for (const TimingResult& one : perRun[i]) ms.push_back(one.passes[p].medianMs);
      const PassTiming& first = perRun[i].front().passes[p];
      t.passes.push_back({first.name, first.kind, median(ms), *std::min_element(ms.begin(), ms.end())});
    }
    summarize(t);
  }
  return out;
}

}  // namespace shadowc::rt

// The run harness: the one way a compiled filter is run (`validate`, `demo`, `sweep`, the
// stability suite, the GPU tests, the benchmarks). Compiled passes + inputs in, outputs +
// per-pass timings out. It knows the manifest only (the runtime knows nothing about
// techniques): the caller gets `CompiledPasses` (manifest/compiled_passes.h) from the driver's
// artifact (driver::Artifact::passes()) or from a directory written by `shadowc compile`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "manifest/compiled_passes.h"
#include "manifest/frame_uniforms.h"
#include "manifest/manifest.h"
#include "runtime/executor/host_image.h"
#include "runtime/executor/pass_executor.h"  // TimingResult
#include "runtime/harness/work_counts.h"

namespace shadowc::rt {

class VulkanContext;

// The harness's inputs, by image role (manifest.h ImageRole). Missing roles the manifest does
// not use are fine; a role the manifest uses but the inputs lack is an error.
struct RunInputs {
  ShadowcFrame frame{};
  uint32_t mapSize = 0, width = 0, height = 0;  // shadow-map side, screen size
  HostImage lightDepth;                         // InputDepth, R32F map x map
  HostImage position, normal;                   // InputPosition / InputNormal, RGBA32F w x h
  HostImage hardwareDepth;  // InputHardwareDepth: the light pass's depth attachment (a depth_input filter)
};

struct RunOptions {
  int warmup = 0;                         // untimed runs first (lavapipe JIT-compiles on the first dispatch)
  RunCount runs;                          // timed runs (or auto); 0 = one untimed run, no timing
  ClockChoice clock = ClockChoice::Auto;  // Auto: the host clock on a CPU device (run_timing.h)
  std::vector<std::string> downloads;     // intermediate images to read back (level 0, layer 0)
  std::string passForm;  // the form of passes with several: "" = SHADOWC_PASS_FORM or auto (pass_forms.h)
};

struct RunOutputs {
  std::vector<float> visibility;            // OutputVisibility, channel 0, width x height
  std::optional<TimingResult> timing;       // when runs > 0
  std::map<std::string, HostImage> images;  // the requested downloads
  double pipelineCreateMs = 0;              // executor construction (pipelines, images, descriptors)
  std::vector<FormChoice> forms;            // the form each pass with several ran (pass_forms.h)
  // An instrumented build's counts (work_counts.h): of exactly one run, the last, whatever the
  // warm-up and timed runs before it added; nullopt for a plain build. A counted build's times
  // include the counting: time the plain build, count the instrumented one.
  std::optional<WorkCounts> work;
};

RunOutputs runPasses(VulkanContext& ctx, const CompiledPasses& passes, const RunInputs& inputs,
                     const RunOptions& options = {});

// Several filters or scenes timed in turn: every one warmed up first, then round after round one
// timed run of each (the order reversed every other round), so that a slow minute on a shared
// machine slows all of them alike. A ratio between two of them then holds far better than one
// between two runs made minutes apart (docs/performance.md "Light size, interleaved"). Each
// result's medians, minima and runTotalsMs are over the rounds, in round order.
struct TimedRun {
  const CompiledPasses* passes = nullptr;
  const RunInputs* inputs = nullptr;
  std::string passForm;  // as RunOptions::passForm
};
// A rejected reading is tried again within its round (PassExecutor::time) and counted.
std::vector<TimingResult> timeInterleaved(VulkanContext& ctx, const std::vector<TimedRun>& runs, int warmup, int rounds,
                                          ClockChoice clock = ClockChoice::Auto);

}  // namespace shadowc::rt

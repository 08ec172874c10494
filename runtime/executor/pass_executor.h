// Runs a compiled filter: every image, sampler, pipeline and descriptor set the manifest
// lists, the passes in manifest order, per-pass GPU timestamps. Driven by the manifest only;
// knows nothing about shadow techniques. Mapping and timing: docs/runtime.md.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "manifest/compiled_passes.h"
#include "manifest/frame_uniforms.h"
#include "manifest/manifest.h"
#include "runtime/executor/host_image.h"
#include "runtime/executor/pass_forms.h"
#include "runtime/executor/run_timing.h"  // TimingResult, median, the clocks

namespace shadowc::rt {

class VulkanContext;

// A manifest the device cannot run as written (unknown image, missing SPIR-V, unsupported
// format, shader/manifest mismatch): the message names the pass.
struct ExecutorError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Workgroup counts for a pass: Texels -> ceil(w/lx) x ceil(h/ly); Rows -> one invocation per
// row along x (gl_GlobalInvocationID.x = row), ceil(h/lx) groups; Columns -> one per column,
// ceil(w/lx) groups; RowGroups -> one workgroup per row (h groups, gl_WorkGroupID.x = row);
// ColumnGroups -> one per column (w groups). z is always 1 (layered passes loop over layers in
// the shader).
std::array<uint32_t, 3> dispatchGroups(const Pass& pass, uint32_t mapSize, uint32_t screenWidth, uint32_t screenHeight);
// Mip levels of an image: mipLevels, or the full chain when 0.
uint32_t mipLevelCount(const ImageDesc& image, uint32_t width, uint32_t height);

class PassExecutor {
 public:
  // The SPIR-V comes from memory: the driver's artifact (driver::Artifact::passes()) or a
  // directory read by CompiledPasses::fromDirectory. Most callers want the run harness
  // (runtime/harness/run_harness.h), which also uploads the inputs by role.
  // `passForm` picks among the forms of passes that have several (pass_forms.h): "auto", a form
  // name, or "" for the environment's SHADOWC_PASS_FORM (else auto).
  PassExecutor(VulkanContext& ctx, const CompiledPasses& compiled, uint32_t mapSize, uint32_t screenWidth,
               uint32_t screenHeight, const std::string& passForm = "");
  ~PassExecutor();
  PassExecutor(const PassExecutor&) = delete;
  PassExecutor& operator=(const PassExecutor&) = delete;

  void setFrame(const ShadowcFrame& frame);
  // Level 0, all layers; size, layers and format must match the manifest image.
  void upload(const std::string& image, const HostImage& data);
  void run();  // one execution of every pass, waits for completion
  // `warmup` untimed runs (lavapipe JIT-compiles on the first dispatch), then `runs` timed runs on
  // the chosen clock (Auto: the host clock on a CPU device), every reading checked against the
  // host's clock (run_timing.h). An ExecutorError when every run was rejected.
  TimingResult time(int warmup, const RunCount& runs, ClockChoice clock = ClockChoice::Auto);
  // The host clock timed runs read (default steadyHostClock()).
  void setHostClock(HostClock clock);
  HostImage download(const std::string& image, uint32_t level = 0, uint32_t layer = 0);
  // Every manifest buffer back to its manifest values (the work counters to zero), and one
  // buffer's words as the last run left them (host-visible memory, no copy on the device).
  void resetBuffers();
  std::vector<int32_t> readBuffer(const std::string& name) const;

  const Manifest& manifest() const;  // as run: each pass in its chosen form
  // The form each pass with several forms runs, manifest order (empty when none has forms).
  const std::vector<FormChoice>& formChoices() const;
  // Names of the images with a role (the harness's inputs/outputs); empty when absent.
  std::string imageWithRole(ImageRole role) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowc::rt

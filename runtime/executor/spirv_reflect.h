// Just enough SPIR-V reflection for the executor to check a pass against its manifest entry:
// the descriptor bindings a module declares (kind, arrayed, storage format) and its local size.
// A mismatch between manifest and shader becomes a clear error naming the pass instead of a
// validation-layer message or undefined behaviour.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "manifest/manifest.h"

namespace shadowc::rt {

enum class DescriptorKind { UniformBuffer, StorageBuffer, StorageImage, CombinedImageSampler, Other };

struct ReflectedBinding {
  uint32_t set = 0, binding = 0;
  DescriptorKind kind = DescriptorKind::Other;
  bool arrayed = false;                // image2DArray / sampler2DArray
  std::optional<ImageFormat> format;   // storage images with a format qualifier the manifest knows
  std::string variable;                // OpName, when present
};

struct ReflectedModule {
  std::vector<ReflectedBinding> bindings;
  std::optional<std::array<uint32_t, 3>> localSize;  // from OpExecutionMode LocalSize
};

// Throws std::invalid_argument on a malformed module (bad magic, truncated instruction).
ReflectedModule reflectSpirv(const std::vector<uint32_t>& words);

const char* toString(DescriptorKind k);

}  // namespace shadowc::rt

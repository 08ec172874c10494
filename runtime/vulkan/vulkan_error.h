// Errors from the Vulkan runtime: one clear message, caught by the CLI and printed as
// "shadowc: error: ..." with a non-zero exit.
#pragma once

#include <stdexcept>
#include <string>

#include "runtime/vulkan/vulkan_api.h"

namespace shadowc::rt {

struct VulkanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws VulkanError("<what>: <VK_RESULT_NAME>") unless r is VK_SUCCESS.
void checkVk(VkResult r, const char* what);

}  // namespace shadowc::rt

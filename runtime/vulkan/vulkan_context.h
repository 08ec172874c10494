// One Vulkan instance + device + compute/graphics queue: lavapipe (llvmpipe) by default,
// another device by name or index. With validation on (options, or env SHADOWC_VALIDATION=1
// as the test suite sets) the Khronos validation layer runs with synchronization validation,
// and every warning or error it reports is kept: tests fail unless the count stays zero.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "runtime/vulkan/vulkan_api.h"

namespace shadowc::rt {

struct VulkanOptions {
  std::string device;       // "" = the CPU device named llvmpipe; else an index or a name substring
  bool validation = false;  // also enabled by env SHADOWC_VALIDATION=1
};

struct PhysicalDeviceInfo {
  uint32_t index = 0;
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t apiVersion = 0;
};

class VulkanContext {
 public:
  explicit VulkanContext(const VulkanOptions& options = {});
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  std::string deviceName() const { return properties_.deviceName; }
  // "llvmpipe (LLVM 15.0.6, 256 bits), Vulkan 1.3.230"
  std::string describe() const;

  // Validation: messages (severity + text) reported by the layer since creation or the last clear.
  bool validationEnabled() const { return validation_; }
  size_t validationMessageCount() const;
  std::vector<std::string> validationMessages() const;
  void clearValidationMessages();

  // Records commands into a fresh primary command buffer, submits it and waits.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;
  // Submits an already recorded command buffer and waits for it.
  void submitAndWait(VkCommandBuffer cmd) const;
  VkCommandPool commandPool() const { return pool_; }

  // A memory type index with the properties; throws VulkanError when none.
  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags flags) const;
  VkFormatFeatureFlags formatFeatures(VkFormat format) const;  // optimal tiling

  // Per-context cache for SPIR-V built at startup (the rasterizer's shaders).
  const std::vector<uint32_t>& cachedSpirv(const std::string& key,
                                           const std::function<std::vector<uint32_t>()>& build);

  // Every physical device the loader reports (for --device and error messages).
  static std::vector<PhysicalDeviceInfo> listDevices();

  // Called by the debug messenger; public only for the C callback.
  void recordValidationMessage(std::string text);

 private:
  void release();

  bool validation_ = false;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger_ = nullptr;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  mutable std::mutex mutex_;
  std::vector<std::string> messages_;
  std::map<std::string, std::vector<uint32_t>> spirvCache_;
};

// True when env SHADOWC_VALIDATION is set to 1.
bool validationRequestedByEnvironment();

}  // namespace shadowc::rt

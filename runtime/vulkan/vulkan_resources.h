// Small owning wrappers for the Vulkan objects the runtime creates: move-only, destroyed with
// their device. Buffers are host-visible and persistently mapped (uniforms, staging); images
// are device-local with optimal tiling.
#pragma once

#include <cstdint>
#include <utility>

#include "runtime/vulkan/vulkan_api.h"

namespace shadowc::rt {

class VulkanContext;

// A device-owned handle destroyed by vkDestroyX(device, handle, nullptr). `Destroy` is the
// address of the loaded function pointer (the pointers are filled in at run time).
template <typename T, auto* Destroy>
class DeviceHandle {
 public:
  DeviceHandle() = default;
  DeviceHandle(VkDevice device, T handle) : device_(device), handle_(handle) {}
  ~DeviceHandle() { reset(); }
  DeviceHandle(DeviceHandle&& o) noexcept : device_(o.device_), handle_(std::exchange(o.handle_, T{})) {}
  DeviceHandle& operator=(DeviceHandle&& o) noexcept {
    if (this != &o) {
      reset();
      device_ = o.device_;
      handle_ = std::exchange(o.handle_, T{});
    }
    return *this;
  }
  DeviceHandle(const DeviceHandle&) = delete;
  DeviceHandle& operator=(const DeviceHandle&) = delete;
  T get() const { return handle_; }
  operator T() const { return handle_; }  // NOLINT: handles pass straight into vkCmd* calls
  void reset() {
    if (handle_) (*Destroy)(device_, handle_, nullptr);
    handle_ = T{};
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  T handle_{};
};

using UniqueMemory = DeviceHandle<VkDeviceMemory, &vkFreeMemory>;
using UniqueBufferHandle = DeviceHandle<VkBuffer, &vkDestroyBuffer>;
using UniqueImageHandle = DeviceHandle<VkImage, &vkDestroyImage>;
using UniqueImageView = DeviceHandle<VkImageView, &vkDestroyImageView>;
using UniqueSampler = DeviceHandle<VkSampler, &vkDestroySampler>;
using UniqueShaderModule = DeviceHandle<VkShaderModule, &vkDestroyShaderModule>;
using UniqueDescriptorSetLayout = DeviceHandle<VkDescriptorSetLayout, &vkDestroyDescriptorSetLayout>;
using UniquePipelineLayout = DeviceHandle<VkPipelineLayout, &vkDestroyPipelineLayout>;
using UniquePipeline = DeviceHandle<VkPipeline, &vkDestroyPipeline>;
using UniqueDescriptorPool = DeviceHandle<VkDescriptorPool, &vkDestroyDescriptorPool>;
using UniqueRenderPass = DeviceHandle<VkRenderPass, &vkDestroyRenderPass>;
using UniqueFramebuffer = DeviceHandle<VkFramebuffer, &vkDestroyFramebuffer>;
using UniqueQueryPool = DeviceHandle<VkQueryPool, &vkDestroyQueryPool>;

// A host-visible, host-coherent, persistently mapped buffer.
struct Buffer {
  UniqueBufferHandle buffer;
  UniqueMemory memory;
  VkDeviceSize size = 0;
  void* mapped = nullptr;
};
Buffer createHostBuffer(const VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage);

// A 2D (array) image with optimal tiling in device-local memory, still in UNDEFINED layout.
struct Image {
  UniqueImageHandle image;
  UniqueMemory memory;
  VkFormat format = VK_FORMAT_UNDEFINED;
  uint32_t width = 0, height = 0, levels = 1, layers = 1;
};
Image createImage(const VulkanContext& ctx, VkFormat format, uint32_t width, uint32_t height, uint32_t levels,
                  uint32_t layers, VkImageUsageFlags usage);

UniqueImageView createView(const VulkanContext& ctx, const Image& image, VkImageViewType type,
                           VkImageAspectFlags aspect, uint32_t baseLevel, uint32_t levelCount);
UniqueShaderModule createShaderModule(const VulkanContext& ctx, const uint32_t* words, size_t wordCount);

// A global memory barrier (all commands, all memory) — used at command-buffer boundaries,
// where the cost does not matter and a missed hazard would.
void fullBarrier(VkCommandBuffer cmd);

// A layout transition (content kept unless oldLayout is UNDEFINED) with its memory dependency.
void imageBarrier(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, VkImageLayout oldLayout,
                  VkImageLayout newLayout, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

}  // namespace shadowc::rt

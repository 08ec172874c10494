// The Vulkan side every engine already has, kept to what the sample needs: one device with a
// graphics+compute queue, images and buffers with their memory, one-shot command buffers, and
// the Khronos validation layer on request (SHADOWC_VALIDATION=1; its messages are counted).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace engine {

void check(VkResult r, const char* what);  // throws std::runtime_error naming the call

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  uint32_t width = 0, height = 0, levels = 1, layers = 1;
};
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;  // host-visible, coherent, mapped for its lifetime
  VkDeviceSize size = 0;
};

class Device {
 public:
  explicit Device(bool validation);  // picks $SHADOWC_ENGINE_DEVICE by name, else llvmpipe, else the first
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  VkDevice device() const { return device_; }
  std::string name() const { return name_; }
  Image createImage(VkFormat format, uint32_t w, uint32_t h, uint32_t levels, uint32_t layers, VkImageUsageFlags usage);
  Buffer createBuffer(VkDeviceSize size, VkBufferUsageFlags usage);
  VkImageView createView(const Image& im, VkImageViewType type, uint32_t baseLevel, uint32_t levels);
  VkSampler createSampler(bool linear, uint32_t levels);
  // Records into one command buffer, submits it and waits.
  void submit(const std::function<void(VkCommandBuffer)>& record);
  // Validation messages seen so far (empty without validation).
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags flags) const;
  VkDeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags flags);
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t family_ = 0;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::string name_;
  std::vector<std::string> messages_;
  std::vector<Image> images_;
  std::vector<Buffer> buffers_;
  std::vector<VkImageView> views_;
  std::vector<VkSampler> samplers_;
};

// A layout transition or memory dependency on the whole image (every level and layer).
void barrier(VkCommandBuffer c, const Image& im, VkImageLayout from, VkImageLayout to);
// Everything before against everything after (the sample orders its passes this way; an engine
// would scope the stages and accesses to the pass's bindings).
void fullBarrier(VkCommandBuffer c);

}  // namespace engine

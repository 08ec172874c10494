#include "runtime/vulkan/vulkan_resources.h"

#include "runtime/vulkan/vulkan_context.h"
#include "runtime/vulkan/vulkan_error.h"

namespace shadowc::rt {

Buffer createHostBuffer(const VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage) {
  Buffer b;
  b.size = size;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer handle = VK_NULL_HANDLE;
  checkVk(vkCreateBuffer(ctx.device(), &info, nullptr, &handle), "vkCreateBuffer");
  b.buffer = UniqueBufferHandle(ctx.device(), handle);
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(ctx.device(), handle, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex =
      ctx.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  checkVk(vkAllocateMemory(ctx.device(), &alloc, nullptr, &memory), "vkAllocateMemory");
  b.memory = UniqueMemory(ctx.device(), memory);
  checkVk(vkBindBufferMemory(ctx.device(), handle, memory, 0), "vkBindBufferMemory");
  checkVk(vkMapMemory(ctx.device(), memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  return b;
}

Image createImage(const VulkanContext& ctx, VkFormat format, uint32_t width, uint32_t height, uint32_t levels,
                  uint32_t layers, VkImageUsageFlags usage) {
  Image im;
  im.format = format;
  im.width = width;
  im.height = height;
  im.levels = levels;
  im.layers = layers;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = levels;
  info.arrayLayers = layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage handle = VK_NULL_HANDLE;
  checkVk(vkCreateImage(ctx.device(), &info, nullptr, &handle), "vkCreateImage");
  im.image = UniqueImageHandle(ctx.device(), handle);
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(ctx.device(), handle, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = ctx.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  checkVk(vkAllocateMemory(ctx.device(), &alloc, nullptr, &memory), "vkAllocateMemory");
  im.memory = UniqueMemory(ctx.device(), memory);
  checkVk(vkBindImageMemory(ctx.device(), handle, memory, 0), "vkBindImageMemory");
  return im;
}

UniqueImageView createView(const VulkanContext& ctx, const Image& image, VkImageViewType type, VkImageAspectFlags aspect,
                           uint32_t baseLevel, uint32_t levelCount) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image.image;
  info.viewType = type;
  info.format = image.format;
  info.subresourceRange = {aspect, baseLevel, levelCount, 0, image.layers};
  VkImageView view = VK_NULL_HANDLE;
  checkVk(vkCreateImageView(ctx.device(), &info, nullptr, &view), "vkCreateImageView");
  return UniqueImageView(ctx.device(), view);
}

UniqueShaderModule createShaderModule(const VulkanContext& ctx, const uint32_t* words, size_t wordCount) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = wordCount * sizeof(uint32_t);
  info.pCode = words;
  VkShaderModule module = VK_NULL_HANDLE;
  checkVk(vkCreateShaderModule(ctx.device(), &info, nullptr, &module), "vkCreateShaderModule");
  return UniqueShaderModule(ctx.device(), module);
}

void fullBarrier(VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
}

void imageBarrier(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range, VkImageLayout oldLayout,
                  VkImageLayout newLayout, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                  VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.srcAccessMask = srcAccess;
  b.dstAccessMask = dstAccess;
  b.oldLayout = oldLayout;
  b.newLayout = newLayout;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = range;
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

}  // namespace shadowc::rt

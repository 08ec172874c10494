// The Vulkan API as shadowc uses it: prototypes off, every entry point a function pointer
// loaded at run time from libvulkan.so.1 (dlopen). Why: `shadowc compile` must work on a
// machine without a Vulkan loader, and a missing loader must be one clear error message,
// not a dynamic-linker failure before main(). Include this instead of <vulkan/vulkan.h>.
#pragma once

#if defined(VULKAN_H_) && !defined(VK_NO_PROTOTYPES)
#error "include runtime/vulkan/vulkan_api.h instead of <vulkan/vulkan.h>"
#endif
#ifndef VK_NO_PROTOTYPES
#define VK_NO_PROTOTYPES
#endif
#include <vulkan/vulkan.h>

// Entry points resolved without an instance.
#define SHADOWC_VK_GLOBAL_FUNCTIONS(X)      \
  X(vkCreateInstance)                       \
  X(vkEnumerateInstanceLayerProperties)     \
  X(vkEnumerateInstanceExtensionProperties) \
  X(vkEnumerateInstanceVersion)

#define SHADOWC_VK_INSTANCE_FUNCTIONS(X)      \
  X(vkDestroyInstance)                        \
  X(vkEnumeratePhysicalDevices)               \
  X(vkGetPhysicalDeviceProperties)            \
  X(vkGetPhysicalDeviceProperties2)           \
  X(vkGetPhysicalDeviceQueueFamilyProperties) \
  X(vkGetPhysicalDeviceMemoryProperties)      \
  X(vkGetPhysicalDeviceFormatProperties)      \
  X(vkGetPhysicalDeviceFeatures)              \
  X(vkEnumerateDeviceExtensionProperties)     \
  X(vkCreateDevice)

#define SHADOWC_VK_DEVICE_FUNCTIONS(X) \
  X(vkDestroyDevice)                   \
  X(vkGetDeviceQueue)                  \
  X(vkDeviceWaitIdle)                  \
  X(vkQueueSubmit)                     \
  X(vkQueueWaitIdle)                   \
  X(vkCreateCommandPool)               \
  X(vkDestroyCommandPool)              \
  X(vkAllocateCommandBuffers)          \
  X(vkFreeCommandBuffers)              \
  X(vkBeginCommandBuffer)              \
  X(vkEndCommandBuffer)                \
  X(vkCreateFence)                     \
  X(vkDestroyFence)                    \
  X(vkWaitForFences)                   \
  X(vkResetFences)                     \
  X(vkCreateBuffer)                    \
  X(vkDestroyBuffer)                   \
  X(vkGetBufferMemoryRequirements)     \
  X(vkBindBufferMemory)                \
  X(vkCreateImage)                     \
  X(vkDestroyImage)                    \
  X(vkGetImageMemoryRequirements)      \
  X(vkBindImageMemory)                 \
  X(vkCreateImageView)                 \
  X(vkDestroyImageView)                \
  X(vkCreateSampler)                   \
  X(vkDestroySampler)                  \
  X(vkAllocateMemory)                  \
  X(vkFreeMemory)                      \
  X(vkMapMemory)                       \
  X(vkUnmapMemory)                     \
  X(vkCreateShaderModule)              \
  X(vkDestroyShaderModule)             \
  X(vkCreateDescriptorSetLayout)       \
  X(vkDestroyDescriptorSetLayout)      \
  X(vkCreatePipelineLayout)            \
  X(vkDestroyPipelineLayout)           \
  X(vkCreateComputePipelines)          \
  X(vkCreateGraphicsPipelines)         \
  X(vkDestroyPipeline)                 \
  X(vkCreateDescriptorPool)            \
  X(vkDestroyDescriptorPool)           \
  X(vkAllocateDescriptorSets)          \
  X(vkUpdateDescriptorSets)            \
  X(vkCreateRenderPass)                \
  X(vkDestroyRenderPass)               \
  X(vkCreateFramebuffer)               \
  X(vkDestroyFramebuffer)              \
  X(vkCreateQueryPool)                 \
  X(vkDestroyQueryPool)                \
  X(vkGetQueryPoolResults)             \
  X(vkCmdResetQueryPool)               \
  X(vkCmdWriteTimestamp)               \
  X(vkCmdPipelineBarrier)              \
  X(vkCmdBindPipeline)                 \
  X(vkCmdBindDescriptorSets)           \
  X(vkCmdPushConstants)                \
  X(vkCmdDispatch)                     \
  X(vkCmdCopyBufferToImage)            \
  X(vkCmdCopyImageToBuffer)            \
  X(vkCmdClearColorImage)              \
  X(vkCmdClearDepthStencilImage)       \
  X(vkCmdBeginRenderPass)              \
  X(vkCmdEndRenderPass)                \
  X(vkCmdSetViewport)                  \
  X(vkCmdSetScissor)                   \
  X(vkCmdBindVertexBuffers)            \
  X(vkCmdBindIndexBuffer)              \
  X(vkCmdDrawIndexed)

namespace shadowc::rt {

// The pointers live in this namespace (mangled names), so they never interpose on the
// loader's exported vk* symbols when libvulkan is in the same process.
#define SHADOWC_VK_DECLARE(name) extern PFN_##name name;
extern PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr;
SHADOWC_VK_GLOBAL_FUNCTIONS(SHADOWC_VK_DECLARE)
SHADOWC_VK_INSTANCE_FUNCTIONS(SHADOWC_VK_DECLARE)
SHADOWC_VK_DEVICE_FUNCTIONS(SHADOWC_VK_DECLARE)
#undef SHADOWC_VK_DECLARE

// dlopen("libvulkan.so.1") once and resolve every core entry point above from the loader's
// exported trampolines, which dispatch on the handle: one table is valid for every instance
// and device of the process. (Extension functions such as debug utils are per instance:
// VulkanContext resolves those itself.) Throws VulkanError ("no Vulkan loader ...") when the
// library is absent.
void loadVulkanLoader();

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" etc.
const char* vkResultName(VkResult r);

}  // namespace shadowc::rt

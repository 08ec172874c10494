// Manifest image formats <-> Vulkan formats.
#pragma once

#include "manifest/manifest.h"
#include "runtime/vulkan/vulkan_api.h"

namespace shadowc::rt {

VkFormat vkFormatOf(ImageFormat f);
uint32_t channelCount(ImageFormat f);
bool isIntegerFormat(ImageFormat f);  // the *UI formats (read with usampler / uimage)
// The aspect of every view, barrier and copy of an image of the format: depth for D32F / D24.
VkImageAspectFlags aspectOf(ImageFormat f);

}  // namespace shadowc::rt

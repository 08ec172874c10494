// Manifest image formats <-> Vulkan formats.
#pragma once

#include "manifest/manifest.h"
#include "runtime/vulkan/vulkan_api.h"

namespace shadowc::rt {

VkFormat vkFormatOf(ImageFormat f);
uint32_t channelCount(ImageFormat f);
bool isIntegerFormat(ImageFormat f);  // the *UI formats (read with usampler / uimage)

}  // namespace shadowc::rt

#include "runtime/vulkan/vulkan_formats.h"

namespace shadowc::rt {

VkFormat vkFormatOf(ImageFormat f) {
  switch (f) {
    case ImageFormat::R32F:
      return VK_FORMAT_R32_SFLOAT;
    case ImageFormat::RG32F:
      return VK_FORMAT_R32G32_SFLOAT;
    case ImageFormat::RGBA32F:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
    case ImageFormat::R16F:
      return VK_FORMAT_R16_SFLOAT;
    case ImageFormat::RG16F:
      return VK_FORMAT_R16G16_SFLOAT;
    case ImageFormat::RGBA16F:
      return VK_FORMAT_R16G16B16A16_SFLOAT;
    case ImageFormat::R16Unorm:
      return VK_FORMAT_R16_UNORM;
    case ImageFormat::RG16Unorm:
      return VK_FORMAT_R16G16_UNORM;
    case ImageFormat::RGBA16Unorm:
      return VK_FORMAT_R16G16B16A16_UNORM;
    case ImageFormat::R32UI:
      return VK_FORMAT_R32_UINT;
    case ImageFormat::RG32UI:
      return VK_FORMAT_R32G32_UINT;
    case ImageFormat::RGBA32UI:
      return VK_FORMAT_R32G32B32A32_UINT;
    case ImageFormat::D32F:
      return VK_FORMAT_D32_SFLOAT;
    case ImageFormat::D24:
      return VK_FORMAT_X8_D24_UNORM_PACK32;
  }
  return VK_FORMAT_UNDEFINED;
}

uint32_t channelCount(ImageFormat f) {
  switch (f) {
    case ImageFormat::R32F:
    case ImageFormat::R16F:
    case ImageFormat::R16Unorm:
    case ImageFormat::R32UI:
    case ImageFormat::D32F:
    case ImageFormat::D24:
      return 1;
    case ImageFormat::RG32F:
    case ImageFormat::RG16F:
    case ImageFormat::RG16Unorm:
    case ImageFormat::RG32UI:
      return 2;
    case ImageFormat::RGBA32F:
    case ImageFormat::RGBA16F:
    case ImageFormat::RGBA16Unorm:
    case ImageFormat::RGBA32UI:
      return 4;
  }
  return 0;
}

bool isIntegerFormat(ImageFormat f) {
  return f == ImageFormat::R32UI || f == ImageFormat::RG32UI || f == ImageFormat::RGBA32UI;
}

VkImageAspectFlags aspectOf(ImageFormat f) {
  return isDepthFormat(f) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

}  // namespace shadowc::rt

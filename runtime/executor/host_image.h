// An image in host memory: what the executor uploads and downloads, and what the rasterizer,
// the reference and the metrics exchange. Layer-major, rows top to bottom, texels packed.
#pragma once

#include <cstdint>
#include <vector>

#include "manifest/manifest.h"

namespace shadowc::rt {

struct HostImage {
  uint32_t width = 0, height = 0, layers = 1;
  ImageFormat format = ImageFormat::R32F;
  std::vector<uint8_t> bytes;

  // Float data (width*height*layers*channels values) converted to a float, half or unorm16
  // format (unorm clamps to [0,1] and rounds to nearest).
  static HostImage fromFloats(uint32_t width, uint32_t height, ImageFormat format, const std::vector<float>& values,
                              uint32_t layers = 1);
  // Integer data for the *UI formats.
  static HostImage fromUints(uint32_t width, uint32_t height, ImageFormat format, const std::vector<uint32_t>& values,
                             uint32_t layers = 1);
  // A zero-filled image.
  static HostImage zeros(uint32_t width, uint32_t height, ImageFormat format, uint32_t layers = 1);

  uint32_t channels() const;
  size_t texelOffset(uint32_t x, uint32_t y, uint32_t layer = 0) const;
  // Texel channel as float (float, half, unorm formats; integer formats convert the value).
  float texel(uint32_t x, uint32_t y, uint32_t channel = 0, uint32_t layer = 0) const;
  uint32_t texelUint(uint32_t x, uint32_t y, uint32_t channel = 0, uint32_t layer = 0) const;  // *UI formats
  // One channel of one layer as floats, row-major (width*height values).
  std::vector<float> channel(uint32_t channel = 0, uint32_t layer = 0) const;
  // Every channel of every texel as floats, interleaved (the layout of an fp32 image's bytes).
  std::vector<float> floats() const;
};

float halfToFloat(uint16_t h);
uint16_t floatToHalf(float f);  // round to nearest even

}  // namespace shadowc::rt

#include "runtime/executor/host_image.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "runtime/vulkan/vulkan_formats.h"

namespace shadowc::rt {
namespace {

enum class Scalar { F32, F16, Unorm16, U32 };
Scalar scalarOf(ImageFormat f) {
  switch (f) {
    case ImageFormat::R32F:
    case ImageFormat::RG32F:
    case ImageFormat::RGBA32F:
    case ImageFormat::D32F:
      return Scalar::F32;
    case ImageFormat::R16F:
    case ImageFormat::RG16F:
    case ImageFormat::RGBA16F:
      return Scalar::F16;
    case ImageFormat::R16Unorm:
    case ImageFormat::RG16Unorm:
    case ImageFormat::RGBA16Unorm:
      return Scalar::Unorm16;
    default:
      return Scalar::U32;
  }
}

void checkCount(size_t have, uint32_t w, uint32_t h, uint32_t layers, ImageFormat f) {
  const size_t need = size_t(w) * h * layers * channelCount(f);
  if (have != need)
    throw std::invalid_argument("HostImage: " + std::to_string(have) + " values for a " + std::to_string(w) + "x" +
                                std::to_string(h) + "x" + std::to_string(layers) + " " + toString(f) + " image (need " +
                                std::to_string(need) + ")");
}

}  // namespace

float halfToFloat(uint16_t h) {
  const uint32_t sign = uint32_t(h & 0x8000) << 16, exp = (h >> 10) & 0x1f, mant = h & 0x3ff;
  uint32_t bits;
  if (exp == 0) {
    if (mant == 0) {
      bits = sign;
    } else {  // subnormal: value = mant * 2^-24
      const float v = std::ldexp(float(mant), -24);
      return sign ? -v : v;
    }
  } else if (exp == 31) {
    bits = sign | 0x7f800000u | (mant << 13);
  } else {
    bits = sign | ((exp + 112) << 23) | (mant << 13);
  }
  return std::bit_cast<float>(bits);
}

uint16_t floatToHalf(float f) {
  const uint32_t bits = std::bit_cast<uint32_t>(f);
  const uint16_t sign = uint16_t((bits >> 16) & 0x8000);
  const float a = std::fabs(f);
  if (std::isnan(f)) return sign | 0x7e00;
  if (a >= 65520.0f) return sign | 0x7c00;                     // rounds to infinity
  if (a < std::ldexp(1.0f, -14)) {                             // subnormal half (or zero): multiples of 2^-24
    const float m = std::nearbyint(a * std::ldexp(1.0f, 24));  // default rounding: to nearest even
    return sign | uint16_t(m);
  }
  int e;
  const float frac = std::frexp(a, &e);  // a = frac * 2^e, frac in [0.5, 1)
  float m = std::nearbyint((frac * 2.0f - 1.0f) * 1024.0f);
  int exp = e - 1 + 15;
  if (m >= 1024.0f) {
    m = 0;
    ++exp;
  }
  if (exp >= 31) return sign | 0x7c00;
  return sign | uint16_t(exp << 10) | uint16_t(m);
}

uint32_t HostImage::channels() const { return channelCount(format); }

size_t HostImage::texelOffset(uint32_t x, uint32_t y, uint32_t layer) const {
  if (x >= width || y >= height || layer >= layers)
    throw std::out_of_range("HostImage: texel (" + std::to_string(x) + ", " + std::to_string(y) + ", layer " +
                            std::to_string(layer) + ") outside " + std::to_string(width) + "x" +
                            std::to_string(height));
  return ((size_t(layer) * height + y) * width + x) * bytesPerTexel(format);
}

HostImage HostImage::zeros(uint32_t w, uint32_t h, ImageFormat f, uint32_t layers) {
  HostImage im;
  im.width = w;
  im.height = h;
  im.layers = layers;
  im.format = f;
  im.bytes.assign(size_t(w) * h * layers * bytesPerTexel(f), 0);
  return im;
}

HostImage HostImage::fromFloats(uint32_t w, uint32_t h, ImageFormat f, const std::vector<float>& values,
                                uint32_t layers) {
  checkCount(values.size(), w, h, layers, f);
  if (scalarOf(f) == Scalar::U32)
    throw std::invalid_argument(std::string("HostImage::fromFloats: ") + toString(f) + " is an integer format");
  HostImage im = zeros(w, h, f, layers);
  for (size_t i = 0; i < values.size(); ++i) {
    switch (scalarOf(f)) {
      case Scalar::F32:
        std::memcpy(im.bytes.data() + 4 * i, &values[i], 4);
        break;
      case Scalar::F16: {
        const uint16_t v = floatToHalf(values[i]);
        std::memcpy(im.bytes.data() + 2 * i, &v, 2);
        break;
      }
      case Scalar::Unorm16: {
        const uint16_t v = uint16_t(std::lround(std::clamp(values[i], 0.0f, 1.0f) * 65535.0f));
        std::memcpy(im.bytes.data() + 2 * i, &v, 2);
        break;
      }
      case Scalar::U32:
        break;
    }
  }
  return im;
}

HostImage HostImage::fromUints(uint32_t w, uint32_t h, ImageFormat f, const std::vector<uint32_t>& values,
                               uint32_t layers) {
  checkCount(values.size(), w, h, layers, f);
  if (scalarOf(f) != Scalar::U32)
    throw std::invalid_argument(std::string("HostImage::fromUints: ") + toString(f) + " is not an integer format");
  HostImage im = zeros(w, h, f, layers);
  std::memcpy(im.bytes.data(), values.data(), values.size() * 4);
  return im;
}

float HostImage::texel(uint32_t x, uint32_t y, uint32_t c, uint32_t layer) const {
  if (c >= channels())
    throw std::out_of_range("HostImage: channel " + std::to_string(c) + " of a " + toString(format) + " image");
  const uint8_t* p = bytes.data() + texelOffset(x, y, layer);
  switch (scalarOf(format)) {
    case Scalar::F32: {
      float v;
      std::memcpy(&v, p + 4 * c, 4);
      return v;
    }
    case Scalar::F16: {
      uint16_t v;
      std::memcpy(&v, p + 2 * c, 2);
      return halfToFloat(v);
    }
    case Scalar::Unorm16: {
      uint16_t v;
      std::memcpy(&v, p + 2 * c, 2);
      return float(v) / 65535.0f;
    }
    case Scalar::U32:
      return float(texelUint(x, y, c, layer));
  }
  return 0;
}

uint32_t HostImage::texelUint(uint32_t x, uint32_t y, uint32_t c, uint32_t layer) const {
  if (scalarOf(format) != Scalar::U32)
    throw std::invalid_argument(std::string("HostImage::texelUint on ") + toString(format));
  if (c >= channels())
    throw std::out_of_range("HostImage: channel " + std::to_string(c) + " of a " + toString(format) + " image");
  uint32_t v;
  std::memcpy(&v, bytes.data() + texelOffset(x, y, layer) + 4 * c, 4);
  return v;
}

std::vector<float> HostImage::channel(uint32_t c, uint32_t layer) const {
  std::vector<float> out;
  out.reserve(size_t(width) * height);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) out.push_back(texel(x, y, c, layer));
  return out;
}

std::vector<float> HostImage::floats() const {
  std::vector<float> out;
  out.reserve(size_t(width) * height * layers * channels());
  for (uint32_t l = 0; l < layers; ++l)
    for (uint32_t y = 0; y < height; ++y)
      for (uint32_t x = 0; x < width; ++x)
        for (uint32_t c = 0; c < channels(); ++c) out.push_back(texel(x, y, c, l));
  return out;
}

}  // namespace shadowc::rt

#include "runtime/images/png_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "runtime/images/atomic_file.h"

// stb is third-party C: keep its warnings out of our -Werror build. The implementations live
// in this one file.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace shadowc::rt {
namespace {

void checkSize(const std::vector<float>& v, uint32_t w, uint32_t h, const char* what) {
  if (v.size() != size_t(w) * h) {
    throw std::invalid_argument(fmt::format("{}: {} values for a {}x{} image", what, v.size(), w, h));
  }
}

uint8_t toByte(double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

void errorColor(float r, float ref, float fullScale, uint8_t* out) {
  if (!std::isfinite(r) || !std::isfinite(ref)) {
    out[0] = 255, out[1] = 0, out[2] = 255;
    return;
  }
  const double e = std::clamp(double(r - ref) / fullScale, -1.0, 1.0);
  const uint8_t fade = toByte(1.0 - std::abs(e));
  if (e >= 0) {  // too bright: white -> red
    out[0] = 255, out[1] = fade, out[2] = fade;
  } else {  // too dark: white -> blue
    out[0] = fade, out[1] = fade, out[2] = 255;
  }
}

}  // namespace

Rgb8Image visibilityToGray(const std::vector<float>& v, uint32_t width, uint32_t height) {
  checkSize(v, width, height, "visibilityToGray");
  Rgb8Image img{width, height, 1, std::vector<uint8_t>(v.size())};
  for (size_t i = 0; i < v.size(); ++i) img.pixels[i] = std::isfinite(v[i]) ? toByte(v[i]) : 0;
  return img;
}

Rgb8Image errorHeatMap(const std::vector<float>& result, const std::vector<float>& reference, uint32_t width,
                       uint32_t height, float fullScale) {
  checkSize(result, width, height, "errorHeatMap result");
  checkSize(reference, width, height, "errorHeatMap reference");
  if (!(fullScale > 0)) throw std::invalid_argument("errorHeatMap: fullScale must be positive");
  Rgb8Image img{width, height, 3, std::vector<uint8_t>(result.size() * 3)};
  for (size_t i = 0; i < result.size(); ++i) errorColor(result[i], reference[i], fullScale, &img.pixels[i * 3]);
  return img;
}

Rgb8Image sideBySide(const std::vector<float>& result, const std::vector<float>& reference, uint32_t width,
                     uint32_t height, float fullScale) {
  const Rgb8Image a = visibilityToGray(result, width, height);
  const Rgb8Image b = visibilityToGray(reference, width, height);
  const Rgb8Image e = errorHeatMap(result, reference, width, height, fullScale);
  const uint32_t w = 3 * width + 2;
  Rgb8Image out{w, height, 3, std::vector<uint8_t>(size_t(w) * height * 3, 128)};  // separators mid-gray
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const size_t s = size_t(y) * width + x;
      uint8_t* row = &out.pixels[size_t(y) * w * 3];
      std::fill_n(row + size_t(x) * 3, 3, a.pixels[s]);
      std::fill_n(row + size_t(width + 1 + x) * 3, 3, b.pixels[s]);
      std::copy_n(&e.pixels[s * 3], 3, row + size_t(2 * width + 2 + x) * 3);
    }
  }
  return out;
}

void writePng(const std::filesystem::path& path, const Rgb8Image& image) {
  if (image.width == 0 || image.height == 0 ||
      image.pixels.size() != size_t(image.width) * image.height * image.channels) {
    throw std::runtime_error(fmt::format("{}: cannot write: empty or inconsistent image", path.string()));
  }
  std::string bytes;
  auto sink = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<char*>(data), size_t(size));
  };
  const int ok = stbi_write_png_to_func(sink, &bytes, int(image.width), int(image.height), int(image.channels),
                                        image.pixels.data(), int(image.width * image.channels));
  if (ok == 0) throw std::runtime_error(fmt::format("{}: cannot write: PNG encoding failed", path.string()));
  writeFileAtomically(path, bytes);
}

Rgb8Image readPng(const std::filesystem::path& path) {
  int w = 0, h = 0, c = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &c, 0);
  if (data == nullptr) {
    throw std::runtime_error(fmt::format("{}: cannot read PNG: {}", path.string(), stbi_failure_reason()));
  }
  Rgb8Image img{uint32_t(w), uint32_t(h), uint32_t(c), std::vector<uint8_t>(data, data + size_t(w) * h * c)};
  stbi_image_free(data);
  return img;
}

void writeVisibilityPng(const std::filesystem::path& path, const std::vector<float>& v, uint32_t width,
                        uint32_t height) {
  writePng(path, visibilityToGray(v, width, height));
}

void writeErrorPng(const std::filesystem::path& path, const std::vector<float>& result,
                   const std::vector<float>& reference, uint32_t width, uint32_t height, float fullScale) {
  writePng(path, errorHeatMap(result, reference, width, height, fullScale));
}

void writeComparisonPng(const std::filesystem::path& path, const std::vector<float>& result,
                        const std::vector<float>& reference, uint32_t width, uint32_t height, float fullScale) {
  writePng(path, sideBySide(result, reference, width, height, fullScale));
}

}  // namespace shadowc::rt

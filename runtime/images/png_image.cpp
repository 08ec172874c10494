#include "runtime/images/png_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
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
#include <stb/stb_easy_font.h>  // a public-domain bitmap font made of quads: the panel labels
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

// Text in the RGB image at (x, y) (top left), each font unit `scale` pixels, clipped to the
// columns [clipX0, clipX1). stb_easy_font gives axis-aligned quads in font units.
void drawText(Rgb8Image& img, int x, int y, const std::string& text, int scale, int clipX0, int clipX1) {
  std::string printable = text;
  for (char& ch : printable)
    if (ch < 32 || ch > 126) ch = '?';  // the font covers printable ASCII only
  std::vector<char> quads(printable.size() * 300 + 64);
  const int n = stb_easy_font_print(0, 0, printable.data(), nullptr, quads.data(), int(quads.size()));
  for (int q = 0; q < n; ++q) {
    float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
    for (int v = 0; v < 4; ++v) {  // 4 vertices of 16 bytes: x, y, z (float), colour (4 bytes)
      float xy[2];
      std::memcpy(xy, &quads[size_t(q * 4 + v) * 16], sizeof xy);
      x0 = std::min(x0, xy[0]), x1 = std::max(x1, xy[0]), y0 = std::min(y0, xy[1]), y1 = std::max(y1, xy[1]);
    }
    const int px0 = std::max({x + int(std::lround(x0 * float(scale))), clipX0, 0});
    const int px1 = std::min({x + int(std::lround(x1 * float(scale))), clipX1, int(img.width)});
    const int py0 = std::max(y + int(std::lround(y0 * float(scale))), 0);
    const int py1 = std::min(y + int(std::lround(y1 * float(scale))), int(img.height));
    for (int py = py0; py < py1; ++py)
      for (int px = px0; px < px1; ++px) std::fill_n(&img.pixels[(size_t(py) * img.width + size_t(px)) * 3], 3, 0);
  }
}

int textWidth(const std::string& text) { return stb_easy_font_width(const_cast<char*>(text.c_str())); }

// The largest scale (1..3) at which `text` fits `width` pixels; 1 when it does not fit at all
// (then it is clipped).
int fitScale(const std::string& text, int width) { return std::clamp(width / std::max(1, textWidth(text)), 1, 3); }

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

Rgb8Image labelledComparison(const std::vector<float>& result, const std::vector<float>& reference, uint32_t width,
                             uint32_t height, float fullScale) {
  const Rgb8Image panels = sideBySide(result, reference, width, height, fullScale);
  const std::string labels[3] = {"result", "reference", "error = result - reference"};
  const std::string legend = "error: blue = result too dark, red = too bright";
  const int w = int(width);
  int scale = 3;  // one scale for every label: the smallest that fits each
  for (const std::string& l : labels) scale = std::min(scale, fitScale(l, w));
  const int top = 13 * scale, bar = 6 * scale, bottom = 3 * scale + bar + 2 * scale + 12 * scale;
  Rgb8Image out{panels.width, uint32_t(top) + height + uint32_t(bottom), 3, {}};
  out.pixels.assign(size_t(out.width) * out.height * 3, 255);  // strips white
  std::copy(panels.pixels.begin(), panels.pixels.end(), out.pixels.begin() + size_t(top) * out.width * 3);
  for (int p = 0; p < 3; ++p)
    drawText(out, p * (w + 1) + scale, 2 * scale, labels[p], scale, p * (w + 1), p * (w + 1) + w);
  // The heat map's colour bar under the error panel: -fullScale at its left, +fullScale at its right.
  const int barY = top + int(height) + 3 * scale, errorX = 2 * (w + 1);
  for (int x = 0; x < w; ++x) {
    const float e = w > 1 ? fullScale * (2.0f * float(x) / float(w - 1) - 1.0f) : 0.0f;
    uint8_t rgb[3];
    errorColor(e, 0.0f, fullScale, rgb);
    for (int y = barY; y < barY + bar; ++y)
      std::copy_n(rgb, 3, &out.pixels[(size_t(y) * out.width + size_t(errorX + x)) * 3]);
  }
  const int textY = barY + bar + 2 * scale;
  const std::string low = fmt::format("-{:g}", fullScale), high = fmt::format("+{:g}", fullScale);
  drawText(out, errorX, textY, low, scale, errorX, errorX + w);
  drawText(out, errorX + w / 2 - textWidth("0") * scale / 2, textY, "0", scale, errorX, errorX + w);
  drawText(out, errorX + w - textWidth(high) * scale, textY, high, scale, errorX, errorX + w);
  const int legendScale = std::min(scale, fitScale(legend, errorX - 2 * scale));
  drawText(out, scale, barY, legend, legendScale, 0, errorX - scale);
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
  writePng(path, labelledComparison(result, reference, width, height, fullScale));
}

}  // namespace shadowc::rt

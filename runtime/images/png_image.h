// PNG output for visibility images, error heat maps and side-by-side comparisons (stb), and
// PNG input for tests and tools. Every write is atomic; the same input gives the same bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace shadowc::rt {

struct Rgb8Image {
  uint32_t width = 0, height = 0, channels = 3;  // 1 (gray), 3 (RGB) or 4
  std::vector<uint8_t> pixels;                   // row 0 = top
};

// Visibility in [0, 1] -> gray, linear (v * 255 rounded; clamped; NaN/Inf -> 0).
Rgb8Image visibilityToGray(const std::vector<float>& v, uint32_t width, uint32_t height);
// Signed error result - reference: white at 0, towards blue where the result is too dark,
// towards red where it is too bright, saturated at |error| >= fullScale; NaN/Inf -> magenta.
Rgb8Image errorHeatMap(const std::vector<float>& result, const std::vector<float>& reference, uint32_t width,
                       uint32_t height, float fullScale = 0.5f);
// result | reference | error heat map, separated by 1-pixel mid-gray columns (3w + 2 wide).
Rgb8Image sideBySide(const std::vector<float>& result, const std::vector<float>& reference, uint32_t width,
                     uint32_t height, float fullScale = 0.5f);
// sideBySide with a white strip above naming each panel ("result", "reference", "error = result
// - reference") and one below with the legend: the heat map's colour bar under the error panel
// from -fullScale to +fullScale and what blue and red mean. Text scale 1..3 font units per pixel,
// the largest at which every label fits its panel (clipped on panels under ~160 pixels).
Rgb8Image labelledComparison(const std::vector<float>& result, const std::vector<float>& reference, uint32_t width,
                             uint32_t height, float fullScale = 0.5f);

// Throws std::runtime_error("<path>: cannot write: ...") / ("<path>: cannot read PNG: ...").
void writePng(const std::filesystem::path& path, const Rgb8Image& image);
Rgb8Image readPng(const std::filesystem::path& path);

// Convenience: straight to files (writeComparisonPng writes labelledComparison).
void writeVisibilityPng(const std::filesystem::path& path, const std::vector<float>& v, uint32_t width,
                        uint32_t height);
void writeErrorPng(const std::filesystem::path& path, const std::vector<float>& result,
                   const std::vector<float>& reference, uint32_t width, uint32_t height, float fullScale = 0.5f);
void writeComparisonPng(const std::filesystem::path& path, const std::vector<float>& result,
                        const std::vector<float>& reference, uint32_t width, uint32_t height, float fullScale = 0.5f);

}  // namespace shadowc::rt

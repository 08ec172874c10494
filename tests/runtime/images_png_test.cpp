// PNG writing: read back with stb_image and check sizes and pixel values.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "runtime/images/png_image.h"
#include "support/test_support.h"

namespace shadowc::rt {
namespace {

TEST(ImagesPng, VisibilityRoundTrips) {
  const auto dir = test::freshTempDir("images_png");
  const std::vector<float> v = {0.0f, 0.5f, 1.0f, 2.0f, -1.0f, std::numeric_limits<float>::quiet_NaN()};
  writeVisibilityPng(dir / "vis.png", v, 3, 2);
  const Rgb8Image img = readPng(dir / "vis.png");
  EXPECT_EQ(img.width, 3u);
  EXPECT_EQ(img.height, 2u);
  EXPECT_EQ(img.channels, 1u);
  EXPECT_EQ(img.pixels, (std::vector<uint8_t>{0, 128, 255, 255, 0, 0}));
  // No temporary file is left behind; same input, same bytes.
  writeVisibilityPng(dir / "vis2.png", v, 3, 2);
  EXPECT_EQ(test::readFile(dir / "vis.png"), test::readFile(dir / "vis2.png"));
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 2u);
}

TEST(ImagesPng, ErrorHeatMapColours) {
  const std::vector<float> ref = {0.5f, 0.5f, 0.5f, 0.5f};
  const std::vector<float> res = {0.5f, 1.0f, 0.0f, std::numeric_limits<float>::infinity()};
  const Rgb8Image e = errorHeatMap(res, ref, 4, 1, 0.5f);
  auto px = [&](int i) { return std::vector<uint8_t>(e.pixels.begin() + i * 3, e.pixels.begin() + i * 3 + 3); };
  EXPECT_EQ(px(0), (std::vector<uint8_t>{255, 255, 255}));  // no error: white
  EXPECT_EQ(px(1), (std::vector<uint8_t>{255, 0, 0}));      // too bright: red
  EXPECT_EQ(px(2), (std::vector<uint8_t>{0, 0, 255}));      // too dark: blue
  EXPECT_EQ(px(3), (std::vector<uint8_t>{255, 0, 255}));    // not finite: magenta
  const Rgb8Image half = errorHeatMap({0.75f}, {0.5f}, 1, 1, 0.5f);
  EXPECT_EQ(half.pixels, (std::vector<uint8_t>{255, 128, 128}));
}

TEST(ImagesPng, SideBySideLayout) {
  const std::vector<float> res = {0.0f, 1.0f, 1.0f, 1.0f};  // 2x2
  const std::vector<float> ref = {1.0f, 1.0f, 1.0f, 1.0f};
  const Rgb8Image img = sideBySide(res, ref, 2, 2);
  ASSERT_EQ(img.width, 3u * 2 + 2);
  ASSERT_EQ(img.height, 2u);
  ASSERT_EQ(img.channels, 3u);
  auto px = [&](uint32_t x, uint32_t y) {
    const size_t i = (size_t(y) * img.width + x) * 3;
    return std::vector<uint8_t>(img.pixels.begin() + i, img.pixels.begin() + i + 3);
  };
  EXPECT_EQ(px(0, 0), (std::vector<uint8_t>{0, 0, 0}));        // result: dark
  EXPECT_EQ(px(2, 0), (std::vector<uint8_t>{128, 128, 128}));  // separator
  EXPECT_EQ(px(3, 0), (std::vector<uint8_t>{255, 255, 255}));  // reference: lit
  EXPECT_EQ(px(5, 1), (std::vector<uint8_t>{128, 128, 128}));  // separator
  EXPECT_EQ(px(6, 0), (std::vector<uint8_t>{0, 0, 255}));      // error: too dark
  EXPECT_EQ(px(7, 1), (std::vector<uint8_t>{255, 255, 255}));  // error: none
}

// comparison.png: the panels of sideBySide between a label strip and a legend strip. Each
// panel's label is ink (black) in the top strip inside that panel's columns, the three labels
// differ, and the legend's colour bar under the error panel runs from the heat map's blue
// (-fullScale) through white to red (+fullScale).
TEST(ImagesPng, ComparisonIsLabelledWithALegend) {
  const uint32_t w = 200, h = 40;
  std::vector<float> res(w * h, 0.25f), ref(w * h, 0.5f);
  const Rgb8Image panels = sideBySide(res, ref, w, h);
  const Rgb8Image img = labelledComparison(res, ref, w, h);
  ASSERT_EQ(img.width, panels.width);
  ASSERT_GT(img.height, h);
  ASSERT_EQ(img.channels, 3u);
  auto px = [&](uint32_t x, uint32_t y) {
    const size_t i = (size_t(y) * img.width + x) * 3;
    return std::vector<uint8_t>(img.pixels.begin() + i, img.pixels.begin() + i + 3);
  };
  // The panels sit unchanged below the top strip: find it as the first row equal to panels' row 0.
  uint32_t top = 0;
  auto rowEquals = [&](uint32_t y, uint32_t panelRow) {
    return std::equal(panels.pixels.begin() + size_t(panelRow) * panels.width * 3,
                      panels.pixels.begin() + size_t(panelRow + 1) * panels.width * 3,
                      img.pixels.begin() + size_t(y) * img.width * 3);
  };
  while (top < img.height && !rowEquals(top, 0)) ++top;
  ASSERT_GT(top, 0u) << "no label strip above the panels";
  ASSERT_LE(top + h, img.height);
  for (uint32_t y = 0; y < h; ++y) ASSERT_TRUE(rowEquals(top + y, y)) << "panel row " << y;
  // Ink per panel in the top strip, and each label's ink pattern its own.
  std::vector<std::vector<uint8_t>> ink(3);
  for (uint32_t p = 0; p < 3; ++p)
    for (uint32_t y = 0; y < top; ++y)
      for (uint32_t x = 0; x < w; ++x) ink[p].push_back(px(p * (w + 1) + x, y)[0] == 0 ? 1 : 0);
  for (uint32_t p = 0; p < 3; ++p)
    EXPECT_GT(std::count(ink[p].begin(), ink[p].end(), 1), 20) << "panel " << p << " has no label";
  EXPECT_NE(ink[0], ink[1]);
  EXPECT_NE(ink[1], ink[2]);
  // The colour bar: the first row under the panels whose left end under the error panel is blue.
  const uint32_t errorX = 2 * (w + 1);
  uint32_t bar = top + h;
  while (bar < img.height && px(errorX, bar) != std::vector<uint8_t>{0, 0, 255}) ++bar;
  ASSERT_LT(bar, img.height) << "no colour bar under the error panel";
  EXPECT_EQ(px(errorX + w - 1, bar), (std::vector<uint8_t>{255, 0, 0}));  // +fullScale: red
  const std::vector<uint8_t> mid = px(errorX + w / 2, bar);               // about 0: near white
  EXPECT_GE(mid[0], 250);
  EXPECT_GE(mid[1], 250);
  EXPECT_GE(mid[2], 250);
  // Legend text under the result and reference panels (ink below the panels, left of the bar).
  int legendInk = 0;
  for (uint32_t y = top + h; y < img.height; ++y)
    for (uint32_t x = 0; x < errorX; ++x) legendInk += px(x, y)[0] == 0 ? 1 : 0;
  EXPECT_GT(legendInk, 50);
  // The file is that image.
  const auto dir = test::freshTempDir("images_cmp");
  writeComparisonPng(dir / "cmp.png", res, ref, w, h);
  EXPECT_EQ(readPng(dir / "cmp.png").pixels, img.pixels);
}

// The sibling: the unlabelled panels have no such strip (row 0 is the panels' own), so the
// search for a strip above is what finds the labels.
TEST(ImagesPng, SiblingSideBySideHasNoLabelStrip) {
  const uint32_t w = 200, h = 40;
  std::vector<float> res(w * h, 0.25f), ref(w * h, 0.5f);
  const Rgb8Image panels = sideBySide(res, ref, w, h);
  EXPECT_EQ(panels.height, h);
  EXPECT_EQ(panels.pixels[0], 64);  // the result panel's 0.25 at (0, 0), not a white strip
}

TEST(ImagesPng, ErrorsAreClear) {
  EXPECT_THROW(readPng("/nonexistent/x.png"), std::runtime_error);
  EXPECT_THROW(writeVisibilityPng(test::freshTempDir("images_bad") / "v.png", {1.0f}, 2, 2), std::invalid_argument);
}

}  // namespace
}  // namespace shadowc::rt

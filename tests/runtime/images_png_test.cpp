// PNG writing: read back with stb_image and check sizes and pixel values.
#include <gtest/gtest.h>

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
  const auto dir = test::freshTempDir("images_side");
  const std::vector<float> res = {0.0f, 1.0f, 1.0f, 1.0f};  // 2x2
  const std::vector<float> ref = {1.0f, 1.0f, 1.0f, 1.0f};
  writeComparisonPng(dir / "cmp.png", res, ref, 2, 2);
  const Rgb8Image img = readPng(dir / "cmp.png");
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

TEST(ImagesPng, ErrorsAreClear) {
  EXPECT_THROW(readPng("/nonexistent/x.png"), std::runtime_error);
  EXPECT_THROW(writeVisibilityPng(test::freshTempDir("images_bad") / "v.png", {1.0f}, 2, 2), std::invalid_argument);
}

}  // namespace
}  // namespace shadowc::rt

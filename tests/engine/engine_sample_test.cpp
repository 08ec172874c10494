// samples/engine on lavapipe with validation on (any message fails the run): it writes a shaded
// PNG and its raw shadow term, and that shadow term — the includable lookup evaluated in the
// engine's own lighting shader, fed by the passes the engine ran from the generated header —
// equals the run harness's visibility for the same filter, scene and sizes (the shade pass,
// same G-buffer) within 1e-5 per pixel: the same lookup code, compiled twice. The shaded image
// is Lambert N·L (from the light's centre) times that term, within 8-bit rounding. Sibling: the
// same comparison against another filter (hard PCF) must fail.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>

#include "emit/emit_support.h"
#include "runtime/harness/run_harness.h"
#include "runtime/images/png_image.h"
#include "runtime/raster/rasterizer.h"
#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"
#include "runtime/vulkan/vulkan_context.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

constexpr const char* kScene = "overlapping_occluders";
constexpr uint32_t kScreen = 128, kMap = 512;
constexpr double kTermTolerance = 1e-5;

struct Harness {
  rt::Scene scene;
  rt::FrameSetup setup;
  rt::RasterOutputs raster;
};

std::vector<float> harnessVisibility(rt::VulkanContext& ctx, const Harness& h, const std::string& sample) {
  const driver::Result r = test::compileSample(sample);
  EXPECT_TRUE(r.ok) << r.log;
  if (!r.ok) return {};
  rt::RunInputs in;
  in.frame = h.setup.frame;
  in.mapSize = kMap;
  in.width = in.height = kScreen;
  in.lightDepth = h.raster.lightDepth;
  in.position = h.raster.gbufferPosition;
  in.normal = h.raster.gbufferNormal;
  return rt::runPasses(ctx, r.artifact->passes(), in).visibility;
}

// Largest |a - b| over the geometry pixels.
double worstDifference(const std::vector<float>& a, const std::vector<float>& b, const rt::HostImage& position) {
  double worst = 0;
  for (uint32_t y = 0; y < kScreen; ++y)
    for (uint32_t x = 0; x < kScreen; ++x)
      if (position.texel(x, y, 3) != 0.0f) {
        const double d = std::fabs(double(a[y * kScreen + x]) - double(b[y * kScreen + x]));
        worst = std::isnan(d) ? INFINITY : std::max(worst, d);
      }
  return worst;
}

TEST(EngineSample, RunsWithValidationOnAndItsShadowTermEqualsTheHarness) {
  const auto out = test::freshTempDir("engine-sample");
  const std::string cmd = "SHADOWC_VALIDATION=1 " + test::engineSampleBinary() + " " + out.string() + " " + kScene +
                          " " + std::to_string(kScreen) + " " + std::to_string(kMap) + " 2>" +
                          (out / "stderr.txt").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0) << test::readFile(out / "stderr.txt");
  const rt::Rgb8Image png = rt::readPng(out / "shaded.png");
  ASSERT_EQ(png.width, kScreen);
  ASSERT_EQ(png.height, kScreen);
  const std::string termBytes = test::readFile(out / "shadow_term.f32");
  ASSERT_EQ(termBytes.size(), size_t(kScreen) * kScreen * 4);
  std::vector<float> term(kScreen * kScreen);
  std::memcpy(term.data(), termBytes.data(), termBytes.size());

  rt::VulkanContext ctx;
  Harness h{rt::loadScene(kScene), {}, {}};
  h.setup = rt::setupFrame(h.scene, kMap, kScreen, kScreen);
  h.raster = rt::rasterize(ctx, h.scene, h.setup);
  const std::vector<float> visibility = harnessVisibility(ctx, h, "vssm_pcf_fallback");
  ASSERT_EQ(visibility.size(), term.size());
  const double worstTerm = worstDifference(term, visibility, h.raster.gbufferPosition);
  EXPECT_LE(worstTerm, kTermTolerance);

  // The scene has penumbrae (the comparison is not of two all-lit images).
  int partial = 0;
  for (float v : term) partial += v > 0.05f && v < 0.95f;
  EXPECT_GT(partial, 50);

  // Lambert: albedo (0.9, 0.85, 0.8, engine_main.cpp) * N.L * term, 8-bit rounded.
  double worstColour = 0;
  const glm::vec3 albedo(0.9f, 0.85f, 0.8f);
  for (uint32_t y = 0; y < kScreen; ++y)
    for (uint32_t x = 0; x < kScreen; ++x) {
      const auto& pos = h.raster.gbufferPosition;
      const auto& nrm = h.raster.gbufferNormal;
      glm::vec3 expected(0.0f);
      if (pos.texel(x, y, 3) != 0.0f) {
        const glm::vec3 p(pos.texel(x, y, 0), pos.texel(x, y, 1), pos.texel(x, y, 2));
        const glm::vec3 n = glm::normalize(glm::vec3(nrm.texel(x, y, 0), nrm.texel(x, y, 1), nrm.texel(x, y, 2)));
        expected = albedo * std::max(glm::dot(n, glm::normalize(h.scene.light.position - p)), 0.0f) *
                   visibility[y * kScreen + x];
      }
      for (int c = 0; c < 3; ++c)
        worstColour = std::max(worstColour, std::fabs(png.pixels[3 * (y * kScreen + x) + c] / 255.0 - expected[c]));
    }
  EXPECT_LE(worstColour, 0.5 / 255 + 1e-4) << "shaded.png is not Lambert N.L times the shadow term";

  // Sibling: the same comparison against hard-edged PCF must fail.
  const std::vector<float> other = harnessVisibility(ctx, h, "pcf_grid5x5");
  const double worstOther = worstDifference(term, other, h.raster.gbufferPosition);
  EXPECT_GT(worstOther, 100 * kTermTolerance);
  std::printf(
      "measured: shadow term vs harness max %.3g, colour vs Lambert max %.3g, %d penumbra pixels, "
      "vs pcf_grid5x5 max %.3g\n",
      worstTerm, worstColour, partial, worstOther);
  EXPECT_EQ(ctx.validationMessageCount(), 0u) << ::testing::PrintToString(ctx.validationMessages());
  std::filesystem::remove_all(out);
}

// `--help` prints the usage and writes nothing (it once became the output folder ./--help/);
// an unknown option is an error naming it, also writing nothing. Both run in an empty folder
// so that anything written shows. The run above is the sibling that does write shaded.png.
struct EngineRun {
  int code = -1;
  std::string out, err;
  size_t entries = 0;  // what the run left in its working folder
};
EngineRun runEngineIn(const std::string& tag, const std::string& args) {
  const auto cwd = test::freshTempDir(tag), logs = test::freshTempDir(tag + "-logs");
  const std::string cmd = "cd " + cwd.string() + " && " + test::engineSampleBinary() + " " + args + " >" +
                          (logs / "out.txt").string() + " 2>" + (logs / "err.txt").string();
  const int status = std::system(cmd.c_str());
  EngineRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = test::readFile(logs / "out.txt");
  r.err = test::readFile(logs / "err.txt");
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(cwd)) ++r.entries;
  return r;
}

TEST(EngineSample, HelpPrintsUsageAndWritesNothing) {
  for (const char* flag : {"--help", "-h"}) {
    const EngineRun r = runEngineIn("engine-help", flag);
    EXPECT_EQ(r.code, 0) << flag << r.err;
    EXPECT_NE(r.out.find("usage: shadowc_engine_sample OUT_DIR [SCENE] [SCREEN] [MAP]"), std::string::npos) << r.out;
    EXPECT_EQ(r.entries, 0u) << flag << " wrote into the working folder";
  }
}

TEST(EngineSample, UnknownOptionIsAnErrorAndWritesNothing) {
  const EngineRun r = runEngineIn("engine-bad-option", "--out x");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: unknown option '--out'"), std::string::npos) << r.err;
  EXPECT_EQ(r.entries, 0u);
}

TEST(EngineSample, BadScreenIsAnErrorNamingIt) {
  const EngineRun r = runEngineIn("engine-bad-screen", "out two_planes big");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("SCREEN must be a whole number in [1, 65536], got 'big'"), std::string::npos) << r.err;
  EXPECT_EQ(r.entries, 0u);
}

}  // namespace
}  // namespace shadowc

// samples/engine on lavapipe with validation on (any message fails the run): from a scene
// written by `shadowc export-scene` it renders its own light-depth map and G-buffer, runs the
// filter's passes from the generated header and the lookup in its own lighting shader, and
// writes a shaded PNG and its raw shadow term. That term equals `shadowc validate`'s visibility
// (`--images DIR`: visibility.f32) on the same scene and sizes: the same lookup compiled twice
// over the same maps, so within 1e-5 per pixel and RMSE 1e-3. The shaded image is Lambert N·L
// times the term within 8-bit rounding. Built in tree for the default filter, and from a copy
// of samples/engine outside the source tree against an installed prefix alone for five filters
// (PCSS, VSSM with fallback, MSM, a cascaded sun, a point light). Sibling: the comparison
// against another filter (hard PCF) fails.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <string>

#include "emit/emit_support.h"
#include "runtime/images/png_image.h"
#include "runtime/raster/rasterizer.h"
#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"
#include "runtime/vulkan/vulkan_context.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

namespace fs = std::filesystem;
constexpr uint32_t kScreen = 128, kMap = 512;
constexpr double kTermTolerance = 1e-5, kRmseBound = 1e-3;

std::vector<float> readFloats(const fs::path& file) {
  const std::string bytes = test::readFile(file);
  std::vector<float> v(bytes.size() / 4);
  std::memcpy(v.data(), bytes.data(), v.size() * 4);
  return v;
}

// Runs a shell command; its exit status (0 = success), stderr into `log`.
int shell(const std::string& cmd, const fs::path& log) {
  const int status = std::system((cmd + " >" + log.string() + " 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// shadowc validate's visibility of `filter` on `scene` (visibility.f32 of --images).
std::vector<float> validateVisibility(const std::string& filter, const std::string& scene, const fs::path& dir) {
  const test::CliResult c =
      test::runShadowc("validate " + filter + " --scene " + scene + " --screen " + std::to_string(kScreen) + " --map " +
                       std::to_string(kMap) + " --samples 2 --runs 1 --warmup 0 --images " + dir.string());
  EXPECT_EQ(c.code, 0) << c.err;
  return readFloats(dir / "visibility.f32");
}

// The scene's G-buffer as the harness rasterizes it: which pixels are geometry, where, facing what.
rt::RasterOutputs harnessGBuffer(rt::VulkanContext& ctx, const std::string& scene) {
  const rt::Scene s = rt::loadScene(scene);
  return rt::rasterize(ctx, s, rt::setupFrame(s, kMap, kScreen, kScreen));
}

struct Difference {
  double worst = 0, rmse = 0;
  size_t pixels = 0, penumbra = 0;
};
Difference compare(const std::vector<float>& a, const std::vector<float>& b, const rt::HostImage& position) {
  Difference d;
  double sum = 0;
  for (uint32_t y = 0; y < kScreen; ++y)
    for (uint32_t x = 0; x < kScreen; ++x) {
      if (position.texel(x, y, 3) == 0.0f) continue;
      const size_t i = size_t(y) * kScreen + x;
      const double e = std::fabs(double(a[i]) - double(b[i]));
      d.worst = std::isnan(e) ? INFINITY : std::max(d.worst, e);
      sum += e * e;
      ++d.pixels;
      d.penumbra += a[i] > 0.05f && a[i] < 0.95f;
    }
  d.rmse = d.pixels ? std::sqrt(sum / double(d.pixels)) : INFINITY;
  return d;
}

// Exports `scene` (with `filter`'s light views), runs `engine` on it with validation on.
std::vector<float> engineTerm(const std::string& engine, const std::string& filter, const std::string& scene,
                              const fs::path& dir) {
  const test::CliResult e =
      test::runShadowc("export-scene " + scene + " -o " + (dir / "scene").string() + " --screen " +
                       std::to_string(kScreen) + " --map " + std::to_string(kMap) + " --filter " + filter);
  EXPECT_EQ(e.code, 0) << e.err;
  EXPECT_EQ(shell("SHADOWC_VALIDATION=1 " + engine + " " + (dir / "scene").string() + " " + (dir / "out").string(),
                  dir / "engine.log"),
            0)
      << test::readFile(dir / "engine.log");
  return readFloats(dir / "out" / "shadow_term.f32");
}

TEST(EngineSample, RunsWithValidationOnAndItsShadowTermEqualsValidate) {
  const fs::path dir = test::freshTempDir("engine-sample");
  const std::string filter = test::samplePath("vssm_pcf_fallback").string(), scene = "overlapping_occluders";
  const std::vector<float> term = engineTerm(test::engineSampleBinary(), filter, scene, dir);
  ASSERT_EQ(term.size(), size_t(kScreen) * kScreen);
  const std::vector<float> visibility = validateVisibility(filter, scene, dir / "validate");
  ASSERT_EQ(visibility.size(), term.size());
  rt::VulkanContext ctx;
  const rt::RasterOutputs g = harnessGBuffer(ctx, scene);
  const Difference d = compare(term, visibility, g.gbufferPosition);
  EXPECT_LE(d.worst, kTermTolerance);
  EXPECT_LE(d.rmse, kRmseBound);
  EXPECT_GT(d.penumbra, 50u) << "the comparison is not of two all-lit images";

  // Lambert: albedo (0.9, 0.85, 0.8, engine_main.cpp) * N.L * term, 8-bit rounded.
  const rt::Rgb8Image png = rt::readPng(dir / "out" / "shaded.png");
  ASSERT_EQ(png.width, kScreen);
  const glm::vec3 albedo(0.9f, 0.85f, 0.8f), light = rt::loadScene(scene).light.position;
  double worstColour = 0;
  for (uint32_t y = 0; y < kScreen; ++y)
    for (uint32_t x = 0; x < kScreen; ++x) {
      glm::vec3 expected(0.0f);
      if (g.gbufferPosition.texel(x, y, 3) != 0.0f) {
        const glm::vec3 p(g.gbufferPosition.texel(x, y, 0), g.gbufferPosition.texel(x, y, 1),
                          g.gbufferPosition.texel(x, y, 2));
        const glm::vec3 n = glm::normalize(
            glm::vec3(g.gbufferNormal.texel(x, y, 0), g.gbufferNormal.texel(x, y, 1), g.gbufferNormal.texel(x, y, 2)));
        expected = albedo * std::max(glm::dot(n, glm::normalize(light - p)), 0.0f) * visibility[y * kScreen + x];
      }
      for (int c = 0; c < 3; ++c)
        worstColour = std::max(worstColour, std::fabs(png.pixels[3 * (y * kScreen + x) + c] / 255.0 - expected[c]));
    }
  EXPECT_LE(worstColour, 0.5 / 255 + 1e-4) << "shaded.png is not Lambert N.L times the shadow term";

  // Sibling: the same comparison against hard-edged PCF fails.
  const std::vector<float> other =
      validateVisibility(test::samplePath("pcf_grid5x5").string(), scene, dir / "validate-pcf");
  const Difference o = compare(term, other, g.gbufferPosition);
  EXPECT_GT(o.worst, 100 * kTermTolerance);
  EXPECT_GT(o.rmse, kRmseBound);
  std::printf(
      "measured: shadow term vs validate max %.3g rmse %.3g over %zu pixels (%zu penumbra), colour max %.3g, "
      "vs pcf_grid5x5 rmse %.3g\n",
      d.worst, d.rmse, d.pixels, d.penumbra, worstColour, o.rmse);
  fs::remove_all(dir);
}

// A filter file for the outside build, named after its filter (the name rule of shadowc_add_filters).
fs::path writeFilter(const fs::path& dir, const std::string& sample, const std::string& name, const std::string& light,
                     const std::string& extra) {
  std::string text = test::readFile(test::samplePath(sample));
  if (!light.empty()) text = test::withLight(text, light);
  const size_t decl = text.find("filter " + sample + " ");
  text.replace(decl, 7 + sample.size(), "filter " + name);
  text.insert(text.rfind('}'), extra);
  const fs::path file = dir / (name + ".shadow");
  std::ofstream(file) << text;
  return file;
}

// CI's integration check: install shadowc into a prefix, copy samples/engine out of the source
// tree and build it against the prefix alone for five filters; no include path may point into
// the source tree, and each build's shadow term equals validate's.
TEST(EngineSample, BuildsOutsideTheSourceTreeAgainstTheInstallPrefixForFiveFilters) {
  const fs::path dir = test::freshTempDir("engine-outside"), prefix = dir / "prefix", copy = dir / "engine";
  const std::string cmake = test::cmakeCommand();
  ASSERT_EQ(shell(cmake + " --install " + test::buildDir() + " --prefix " + prefix.string(), dir / "install.log"), 0)
      << test::readFile(dir / "install.log");
  fs::copy(test::sourceDir() / "samples" / "engine", copy, fs::copy_options::recursive);
  const fs::path filters = dir / "filters";
  fs::create_directories(filters);
  struct Case {
    fs::path filter;
    std::string scene;
  };
  const std::vector<Case> cases{
      {writeFilter(filters, "pcss_poisson", "pcss", "", ""), "two_planes"},
      {writeFilter(filters, "vssm_pcf_fallback", "vssm_fallback", "", ""), "overlapping_occluders"},
      {writeFilter(filters, "msm_plain", "msm", "", ""), "two_planes"},
      {writeFilter(filters, "pcss_poisson", "pcss_sun_cascades", "light sun(angle: scene)", "    cascades 4\n"),
       "sun_outdoor"},
      {writeFilter(filters, "pcf_poisson16", "pcf_point", "light point(radius: scene)", ""), "point_room"}};
  rt::VulkanContext ctx;
  const fs::path build = dir / "build";
  for (const Case& c : cases) {
    const std::string name = c.filter.stem().string();
    ASSERT_EQ(shell(cmake + " -S " + copy.string() + " -B " + build.string() +
                        " -G \"Unix Makefiles\" -DCMAKE_CXX_COMPILER=" + test::cxxCompiler() +
                        " -DCMAKE_PREFIX_PATH=" + prefix.string() + " -DSHADOWC_FILTER=" + c.filter.string() + " && " +
                        cmake + " --build " + build.string() + " -j 2",
                    dir / "build.log"),
              0)
        << name << ":\n"
        << test::readFile(dir / "build.log");
    // Every include path is the prefix's, the build tree's or the system's.
    const std::string flags = test::readFile(build / "CMakeFiles" / "shadowc_engine_sample.dir" / "flags.make");
    ASSERT_NE(flags.find("CXX_INCLUDES"), std::string::npos);
    EXPECT_NE(flags.find(prefix.string() + "/include"), std::string::npos) << flags;
    EXPECT_EQ(flags.find(test::sourceDir().string()), std::string::npos) << "an include path into the source tree:\n"
                                                                         << flags;
    const fs::path run = dir / name;
    const std::vector<float> term =
        engineTerm((build / "shadowc_engine_sample").string(), c.filter.string(), c.scene, run);
    const std::vector<float> visibility = validateVisibility(c.filter.string(), c.scene, run / "validate");
    ASSERT_EQ(term.size(), visibility.size()) << name;
    const Difference d = compare(term, visibility, harnessGBuffer(ctx, c.scene).gbufferPosition);
    EXPECT_LE(d.rmse, kRmseBound) << name;
    EXPECT_LE(d.worst, kTermTolerance) << name;
    EXPECT_GT(d.pixels, 1000u) << name;
    std::printf("measured: %s on %s: shadow term vs validate max %.3g rmse %.3g over %zu pixels (%zu penumbra)\n",
                name.c_str(), c.scene.c_str(), d.worst, d.rmse, d.pixels, d.penumbra);
  }
  fs::remove_all(dir);
}

// `--help` prints the usage and writes nothing (it once became the output folder ./--help/);
// an unknown option is an error naming it, also writing nothing. Both run in an empty folder
// so that anything written shows. The runs above are the siblings that do write shaded.png.
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
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(cwd)) ++r.entries;
  return r;
}

TEST(EngineSample, HelpPrintsUsageAndWritesNothing) {
  for (const char* flag : {"--help", "-h"}) {
    const EngineRun r = runEngineIn("engine-help", flag);
    EXPECT_EQ(r.code, 0) << flag << r.err;
    EXPECT_NE(r.out.find("usage: shadowc_engine_sample SCENE_DIR OUT_DIR"), std::string::npos) << r.out;
    EXPECT_EQ(r.entries, 0u) << flag << " wrote into the working folder";
  }
}

TEST(EngineSample, UnknownOptionIsAnErrorAndWritesNothing) {
  const EngineRun r = runEngineIn("engine-bad-option", "--out x");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("error: unknown option '--out'"), std::string::npos) << r.err;
  EXPECT_EQ(r.entries, 0u);
}

TEST(EngineSample, AMissingSceneIsOneMessageNamingTheExportAndWritesNothing) {
  const EngineRun r = runEngineIn("engine-no-scene", "no_such_dir out");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no_such_dir/scene.json: cannot read (write it with `shadowc export-scene SCENE -o DIR`)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.entries, 0u);
}

}  // namespace
}  // namespace shadowc

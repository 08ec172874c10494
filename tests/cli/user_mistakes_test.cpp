// Small mistakes a new user makes, each with the exact input: one clear error on stderr and a
// non-zero exit, before expensive work where a cheap check can tell. Every case has a sibling
// that makes the same call right and succeeds, so the error is the mistake's doing, not a broken
// set-up (docs/cli.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/cli_expect.h"
#include "runtime/images/png_image.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

const std::string kFilter = (test::sourceDir() / "samples/filters/pcf_grid5x5.shadow").string();
// Small, so a run that gets through is quick.
const std::string kSmall = " --map 256 --samples 2 --runs 1 --warmup 0 --no-reference-cache";
const std::string kScreen = " --screen 32";

using test::errorLines;
using test::expectOneError;

void expectReport(const test::CliResult& r) {
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rmse"), std::string::npos) << r.out;
  EXPECT_EQ(errorLines(r.err), 0) << r.err;
}

std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// ---- One spelling per option: the old one names the new one ------------------------------------

TEST(UserMistakes, ValidateSizeNamesScreen) {
  expectOneError(test::runShadowc("validate " + kFilter + " --scene two_planes --size 32" + kSmall),
                 "--size: this option is now spelled --screen");
}

TEST(UserMistakes, SiblingValidateScreenRuns) {
  expectReport(test::runShadowc("validate " + kFilter + " --scene two_planes --screen 32" + kSmall));
}

TEST(UserMistakes, ValidateNoCacheNamesNoReferenceCache) {
  expectOneError(test::runShadowc("validate " + kFilter +
                                  " --scene two_planes --screen 32 --map 256 --samples 2 "
                                  "--runs 1 --warmup 0 --no-cache"),
                 "--no-cache: this option is now spelled --no-reference-cache");
}

TEST(UserMistakes, CompileOutputNamesOut) {
  const auto dir = test::freshTempDir("mistake-output");
  const test::CliResult r = test::runShadowc("compile " + kFilter + " --output " + dir.string());
  expectOneError(r, "--output: this option is now spelled -o/--out");
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json"));
}

TEST(UserMistakes, SiblingCompileOutWrites) {
  const auto dir = test::freshTempDir("mistake-out");
  const test::CliResult r = test::runShadowc("compile " + kFilter + " --out " + dir.string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "manifest.json"));
}

// The instrumented build describes no filter to ship: with the C++ header it is one error, and
// nothing is written. Sibling: the same build without the header writes its manifest.
TEST(UserMistakes, CompileCountersWithTheCppHeaderIsOneError) {
  const auto dir = test::freshTempDir("mistake-counters-cpp");
  const test::CliResult r = test::runShadowc("compile " + kFilter + " --counters --emit spirv,cpp -o " + dir.string());
  expectOneError(r, "--counters with --emit cpp");
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json"));
  const test::CliResult counted = test::runShadowc("compile " + kFilter + " --counters -o " + dir.string());
  EXPECT_EQ(counted.code, 0) << counted.err;
  EXPECT_NE(test::readFile(dir / "manifest.json").find("\"work_counters\""), std::string::npos);
}

// --help lists the one spelling and hides the old one (which would only say its new name).
TEST(UserMistakes, HelpShowsScreenNotSize) {
  for (const char* sub : {"validate", "demo", "plan", "analyze"}) {
    const test::CliResult r = test::runShadowc(std::string(sub) + " --help");
    EXPECT_EQ(r.code, 0) << sub << r.err;
    EXPECT_NE(r.out.find("--screen"), std::string::npos) << sub << r.out;
    EXPECT_EQ(r.out.find("--size"), std::string::npos) << sub << r.out;
  }
}

// ---- A manifest is known by its content, not its file name ------------------------------------

struct Compiled {
  std::filesystem::path dir, renamed;
};
Compiled compiledUnderAnotherName(const std::string& tag) {
  Compiled c;
  c.dir = test::freshTempDir(tag);
  const test::CliResult r = test::runShadowc("compile " + kFilter + " -O0 -o " + c.dir.string());
  EXPECT_EQ(r.code, 0) << r.err;
  c.renamed = c.dir / "renamed.json";
  std::filesystem::rename(c.dir / "manifest.json", c.renamed);
  return c;
}

TEST(UserMistakes, RenamedManifestValidates) {
  const Compiled c = compiledUnderAnotherName("mistake-renamed");
  const test::CliResult r =
      test::runShadowc("validate " + c.renamed.string() + " --scene two_planes" + kScreen + kSmall);
  expectReport(r);
  EXPECT_NE(r.out.find("filter   pcf_grid5x5"), std::string::npos) << r.out;
}

// Other JSON where a manifest goes (a scene file): one message saying it is not a manifest.
TEST(UserMistakes, SceneJsonAsFilterIsNotAManifest) {
  const std::string scene = (test::sourceDir() / "samples/scenes/two_planes.json").string();
  expectOneError(test::runShadowc("validate " + scene + " --scene two_planes" + kScreen + kSmall),
                 "not a shadowc manifest");
}

// `compile` given a manifest: one E0004 at the brace, not an error per quote.
TEST(UserMistakes, CompileOfAManifestIsOneError) {
  const Compiled c = compiledUnderAnotherName("mistake-compile-json");
  const test::CliResult r = test::runShadowc("compile " + c.renamed.string() + " -o " + (c.dir / "out").string());
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(errorLines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("renamed.json:1:1: error: file is JSON, not a filter description"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[E0004]"), std::string::npos) << r.err;
}

// ---- "Nothing compared" is an error ------------------------------------------------------------

// two_planes with the camera turned up and away from every object, or (sibling) at them.
std::filesystem::path sceneLookingAt(const std::string& tag, const std::string& target) {
  return writeFile(test::freshTempDir(tag) / "scene.json", R"({
    "camera": {"eye": [0, 6, 8], "target": )" + target + R"(, "up": [0, 1, 0], "fov_y": 45},
    "light": {"shape": "rect", "position": [0, 6, 0], "direction": [0, -1, 0], "up": [0, 0, 1], "size": 1},
    "objects": [{"type": "plane", "name": "floor", "size": [10, 10]},
                {"type": "plane", "name": "occluder", "size": [2, 2], "transform": {"translate": [0, 2, 0]}}]
  })");
}

TEST(UserMistakes, CameraThatSeesNoGeometryIsAnError) {
  const auto scene = sceneLookingAt("mistake-no-geometry", "[0, 12, 16]");
  const test::CliResult r = test::runShadowc("validate " + kFilter + " --scene " + scene.string() + kScreen + kSmall);
  expectOneError(r, "the camera sees no geometry");
  EXPECT_EQ(r.out.find("0 geometry pixels"), std::string::npos) << r.out;
}

TEST(UserMistakes, SiblingCameraAtTheObjectsValidates) {
  const auto scene = sceneLookingAt("mistake-geometry", "[0, 0, 0]");
  expectReport(test::runShadowc("validate " + kFilter + " --scene " + scene.string() + kScreen + kSmall));
}

// ---- "Nothing ran" is an error -----------------------------------------------------------------

// A sweep of `filters` (JSON array items) on two_planes at the tiny sizes.
std::filesystem::path sweepOf(const std::string& tag, const std::string& filters) {
  const auto dir = test::freshTempDir(tag);
  writeFile(dir / "sweep.json", R"({"name": "mistake", "filters": [)" + filters +
                                    R"(], "scenes": ["two_planes"], "screen": 32, "map": 256,
                                    "reference_samples": 2, "runs": 1, "warmup": 0})");
  return dir;
}

// pcss_poisson with a point light: the checker refuses it (E0416), the only variant.
const std::string kRefused = R"({"name": "point_pcss", "file": ")" +
                             (test::sourceDir() / "samples/filters/pcss_poisson.shadow").string() +
                             R"(", "set": {"light": "point"}})";

TEST(UserMistakes, SweepWhoseEveryVariantIsRefusedIsAnError) {
  const auto dir = sweepOf("mistake-sweep-none", kRefused);
  const test::CliResult r =
      test::runShadowc("sweep " + (dir / "sweep.json").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("error: nothing ran: all 1 variant(s) of sweep 'mistake' were skipped"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("E0416"), std::string::npos) << r.err;  // the reason is listed above it
}

TEST(UserMistakes, SiblingSweepWithOneValidVariantSucceeds) {
  const auto dir = sweepOf("mistake-sweep-one", "\"" + kFilter + "\", " + kRefused);
  const test::CliResult r =
      test::runShadowc("sweep " + (dir / "sweep.json").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("sweep: 1 rows"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("nothing ran"), std::string::npos) << r.err;
}

// ---- Cheap checks before expensive work --------------------------------------------------------

// A spot filter on a sun scene is refused before the reference is traced or anything runs.
TEST(UserMistakes, LightTypeMismatchIsRefusedBeforeTheTrace) {
  const test::CliResult r = test::runShadowc("validate " + kFilter + " --scene sun_two_planes" + kScreen + kSmall);
  expectOneError(r, "compile the filter with 'light sun'");
  EXPECT_EQ(r.err.find("tracing the Embree reference"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("shadowc: running"), std::string::npos) << r.err;
}

// The sibling: the same scene with a sun filter does trace (so the progress line is what the
// check above looks for).
TEST(UserMistakes, SiblingASunFilterTracesAndRuns) {
  const auto file = writeFile(test::freshTempDir("mistake-sun") / "pcf_sun.shadow",
                              "filter pcf_sun {\n    light sun\n    depth\n    kernel fixed(5)\n"
                              "    sampling grid(5x5)\n}\n");
  const test::CliResult r =
      test::runShadowc("validate " + file.string() + " --scene sun_two_planes" + kScreen + kSmall);
  expectReport(r);
  EXPECT_NE(r.err.find("tracing the Embree reference"), std::string::npos) << r.err;
}

// ---- comparison.png is labelled -----------------------------------------------------------------

// `--images` writes comparison.png with the label strip above the three panels and the legend
// below; a 256-pixel screen gives the labels room (labelledComparison: tests/runtime).
TEST(UserMistakes, ComparisonImageHasLabelsAndLegend) {
  const auto dir = test::freshTempDir("mistake-images");
  const test::CliResult r =
      test::runShadowc("validate " + kFilter + " --scene two_planes --screen 256 --images " + dir.string() + kSmall);
  ASSERT_EQ(r.code, 0) << r.err;
  const rt::Rgb8Image cmp = rt::readPng(dir / "comparison.png");
  const rt::Rgb8Image result = rt::readPng(dir / "result.png");
  EXPECT_EQ(cmp.width, 3 * result.width + 2);
  EXPECT_GT(cmp.height, result.height);  // the strips
}

}  // namespace
}  // namespace shadowc

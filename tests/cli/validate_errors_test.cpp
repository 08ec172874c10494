// `shadowc validate` with bad input: each case gives ONE clear message on stderr and a non-zero
// exit. The sibling runs a good invocation to prove that the harness sees success, so
// the failures above are the inputs' doing, not a broken test set-up.
#include <gtest/gtest.h>

#include <fstream>

#include "cli/cli_expect.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

const std::string kFilter = (test::sourceDir() / "samples/filters/pcf_grid5x5.shadow").string();
// Small, so a run that gets through is quick.
const std::string kSmall = " --screen 32 --map 256 --samples 2 --runs 1 --warmup 0 --no-reference-cache";

using test::errorLines;
using test::expectOneError;

std::filesystem::path writeTemp(const std::string& tag, const std::string& name, const std::string& text) {
  const auto path = test::freshTempDir(tag) / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(ValidateErrors, UnknownSceneName) {
  expectOneError(test::runShadowc("validate " + kFilter + " --scene two_plane" + kSmall), "unknown scene 'two_plane'");
}

TEST(ValidateErrors, MissingSceneFile) {
  expectOneError(test::runShadowc("validate " + kFilter + " --scene /nonexistent/scene.json" + kSmall),
                 "scene file not found");
}

TEST(ValidateErrors, MalformedSceneFile) {
  const auto scene = writeTemp("bad-scene", "bad.json", "{ \"camera\": { \"eye\": [0, 1, ");
  expectOneError(test::runShadowc("validate " + kFilter + " --scene " + scene.string() + kSmall), "bad.json");
}

TEST(ValidateErrors, MeshThatFailsToLoad) {
  const auto dir = test::freshTempDir("bad-mesh");
  std::ofstream(dir / "broken.obj") << "this is not an OBJ file\n\x01\x02\x03\n";
  std::ofstream(dir / "scene.json") << R"({
    "camera": {"eye": [0, 4, 6], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 45},
    "light": {"shape": "rect", "position": [0, 8, 0], "direction": [0, -1, 0], "up": [0, 0, 1], "size": 1},
    "objects": [{"type": "mesh", "path": "broken.obj"}]
  })";
  expectOneError(test::runShadowc("validate " + kFilter + " --scene " + (dir / "scene.json").string() + kSmall),
                 "cannot load mesh");
}

TEST(ValidateErrors, ManifestFromAnotherVersion) {
  const auto dir = test::freshTempDir("old-manifest");
  const test::CliResult compiled = test::runShadowc("compile " + kFilter + " -O0 -o " + dir.string());
  ASSERT_EQ(compiled.code, 0) << compiled.err;
  std::string manifest = test::readFile(dir / "manifest.json");
  const std::string current = "\"format_version\": 1";
  ASSERT_NE(manifest.find(current), std::string::npos);
  manifest.replace(manifest.find(current), current.size(), "\"format_version\": 99");
  std::ofstream(dir / "manifest.json", std::ios::binary) << manifest;
  expectOneError(test::runShadowc("validate " + dir.string() + " --scene two_planes" + kSmall),
                 "format version 99 is not supported");
}

TEST(ValidateErrors, NoVulkanDeviceAtAll) {
  // The loader finds no driver when pointed at a manifest that does not exist.
  expectOneError(test::runShadowc("validate " + kFilter + " --scene two_planes" + kSmall,
                                  "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json"),
                 "no Vulkan");
}

TEST(ValidateErrors, SiblingAGoodRunSucceedsAndReports) {
  const test::CliResult r = test::runShadowc("validate " + kFilter + " --scene two_planes" + kSmall);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rmse"), std::string::npos) << r.out;
  EXPECT_EQ(errorLines(r.err), 0) << r.err;
}

TEST(ValidateErrors, SiblingACompiledManifestRunsToo) {
  const auto dir = test::freshTempDir("good-manifest");
  ASSERT_EQ(test::runShadowc("compile " + kFilter + " -O0 -o " + dir.string()).code, 0);
  const test::CliResult r =
      test::runShadowc("validate " + (dir / "manifest.json").string() + " --scene two_planes" + kSmall);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("filter   pcf_grid5x5"), std::string::npos) << r.out;
}

// Light types: a spot filter on a sun scene is one clear error naming the fix, and the
// same filter compiled for a sun validates on it (the sibling).
// `validate FILE --scene SCENE` succeeds: exit 0, an RMSE printed, no error line.
void expectValidates(const std::filesystem::path& file, const std::string& scene) {
  const test::CliResult r = test::runShadowc("validate " + file.string() + " --scene " + scene + kSmall);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rmse"), std::string::npos) << r.out;
  EXPECT_EQ(errorLines(r.err), 0) << r.err;
}

// A 5x5 PCF for a point light (the spot and sun filters of these tests differ only in `light`).
const std::string kPcfPointFilter =
    "filter pcf_point {\n    light point(radius: scene)\n    depth\n    kernel fixed(5)\n    sampling grid(5x5)\n}\n";

TEST(ValidateErrors, SpotFilterOnSunScene) {
  expectOneError(test::runShadowc("validate " + kFilter + " --scene sun_two_planes" + kSmall),
                 "compile the filter with 'light sun'");
}

TEST(ValidateErrors, SiblingASunFilterValidatesOnASunScene) {
  const auto file = writeTemp("sun-filter", "pcf_sun.shadow",
                              "filter pcf_sun {\n    light sun\n    depth\n    kernel fixed(5)\n"
                              "    sampling grid(5x5)\n}\n");
  expectValidates(file, "sun_two_planes");
}

// Point lights: a spot filter on point_room is one error naming the fix; a
// point filter on a spot scene too; the point filter validates on point_room (the sibling).
TEST(ValidateErrors, SpotFilterOnPointScene) {
  expectOneError(test::runShadowc("validate " + kFilter + " --scene point_room" + kSmall),
                 "compile the filter with 'light point(radius: scene)'");
}

TEST(ValidateErrors, PointFilterOnSpotScene) {
  const auto file = writeTemp("point-filter-spot", "pcf_point.shadow", kPcfPointFilter);
  expectOneError(test::runShadowc("validate " + file.string() + " --scene two_planes" + kSmall),
                 "is for a point light but scene 'two_planes' has a spot light");
}

TEST(ValidateErrors, SiblingAPointFilterValidatesOnAPointScene) {
  const auto file = writeTemp("point-filter", "pcf_point.shadow", kPcfPointFilter);
  expectValidates(file, "point_room");
}

// A form override no pass can have is refused for every filter, those without multi-form passes
// (PCF) and those with them (an int32-SAT VSSM) alike, from the option and from the environment,
// before the reference is traced (no "reference" progress line) and before any timing.
TEST(ValidateErrors, UnknownPassFormBeforeAnyWork) {
  for (const char* sample : {"pcf_grid5x5", "vssm_int32_sat"}) {
    const std::string filter = (test::sourceDir() / "samples/filters" / (std::string(sample) + ".shadow")).string();
    const test::CliResult option =
        test::runShadowc("validate " + filter + " --scene two_planes --pass-form diagonal" + kSmall);
    expectOneError(option, "--pass-form 'diagonal' is not a pass form: auto, serial, parallel");
    EXPECT_EQ(option.err.find("reference"), std::string::npos) << sample << ":\n" << option.err;
    const test::CliResult env =
        test::runShadowc("validate " + filter + " --scene two_planes" + kSmall, "SHADOWC_PASS_FORM=sideways");
    expectOneError(env, "SHADOWC_PASS_FORM 'sideways' is not a pass form");
    EXPECT_EQ(env.err.find("reference"), std::string::npos) << sample << ":\n" << env.err;
  }
}

TEST(ValidateErrors, SiblingAKnownPassFormValidates) {
  const std::string filter = (test::sourceDir() / "samples/filters/vssm_int32_sat.shadow").string();
  const test::CliResult r = test::runShadowc("validate " + filter + " --scene two_planes --pass-form serial" + kSmall);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rmse"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sat_rows serial"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace shadowc

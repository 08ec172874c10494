// PassExecutor on lavapipe with hand-written manifests and inline GLSL: exact results, every
// dispatch mode, push constants, the frame UBO, layered/mipped images, timing and the errors
// a bad manifest must produce. Validation on; zero messages allowed.
#include "runtime/executor/pass_executor.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "gpu/gpu_test_util.h"
#include "gpu/vulkan_fixture.h"
#include "support/test_support.h"

namespace shadowc::test {
namespace {

using ExecutorTest = VulkanTest;

constexpr uint32_t kW = 37, kH = 23;  // not multiples of the local size: bounds checks matter

ImageDesc image(const std::string& name, ImageFormat f, SizeDomain d = SizeDomain::Screen) {
  ImageDesc im;
  im.name = name;
  im.format = f;
  im.size.domain = d;
  return im;
}

Pass pass(const std::string& name, std::vector<Binding> bindings, DispatchMode mode = DispatchMode::Texels,
          std::array<uint32_t, 3> local = {8, 8, 1}) {
  Pass p;
  p.name = name;
  p.kind = "test";
  p.spirv = name + ".spv";
  p.glsl = name + ".glsl";
  p.localSize = local;
  p.dispatch.size.domain = SizeDomain::Screen;
  p.dispatch.mode = mode;
  p.bindings = std::move(bindings);
  return p;
}

// Pass 1 doubles `input` into `doubled` (storage read -> storage write). Pass 2 reads `doubled`
// through a sampler and adds the frame block's mapInfo.x and a push constant: checks the barrier between
// passes, the UBO and push constants at once.
constexpr const char* kDouble = R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1, r32f) readonly uniform image2D inputImage;
layout(set = 0, binding = 2, r32f) writeonly uniform image2D doubled;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(doubled)))) return;
  imageStore(doubled, p, vec4(2.0 * imageLoad(inputImage, p).r));
}
)";
constexpr const char* kAdd = R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler2D doubled;
layout(set = 0, binding = 2, r32f) writeonly uniform image2D result;
layout(push_constant) uniform Push { float offset; uint scale; } pc;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(result)))) return;
  imageStore(result, p, vec4(float(pc.scale) * texelFetch(doubled, p, 0).r + shadowc_frameBlock.mapInfo.x + pc.offset));
}
)";

Manifest twoPassManifest() {
  Manifest m;
  m.filter = "test";
  m.images = {image("input", ImageFormat::R32F), image("doubled", ImageFormat::R32F),
              image("result", ImageFormat::R32F)};
  m.passes.push_back(pass("double", {{1, "input", Access::StorageRead, -1}, {2, "doubled", Access::StorageWrite, -1}}));
  Pass add = pass("add", {{0, "frame", Access::Uniform, -1},
                          {1, "doubled", Access::Sampled, -1},
                          {2, "result", Access::StorageWrite, -1}});
  add.pushConstants = {{"offset", 0, ScalarType::F32, 0.25}, {"scale", 4, ScalarType::U32, 3}};
  m.passes.push_back(add);
  return m;
}

using SpirvFiles = std::map<std::string, std::string>;  // CompiledPasses::files

SpirvFiles twoPassFiles() {
  return {{"double.spv", computeSpirv("double.spv", kDouble)}, {"add.spv", computeSpirv("add.spv", kAdd)}};
}

std::vector<float> ramp() {
  std::vector<float> v(kW * kH);
  for (uint32_t i = 0; i < v.size(); ++i) v[i] = float(i) * 0.5f - 100.0f;
  return v;
}

TEST_F(ExecutorTest, TwoPassesGiveExactValues) {
  const SpirvFiles files = twoPassFiles();
  rt::PassExecutor ex(context(), CompiledPasses{twoPassManifest(), files}, 64, kW, kH);
  ShadowcFrame frame{};
  frame.mapInfo[0] = 1000.0f;
  ex.setFrame(frame);
  const auto in = ramp();
  ex.upload("input", rt::HostImage::fromFloats(kW, kH, ImageFormat::R32F, in));
  ex.run();
  const rt::HostImage doubled = ex.download("doubled");
  const rt::HostImage result = ex.download("result");
  // All values are exact in fp32 (halves of small integers), so the tolerance is 0.
  EXPECT_TRUE(imageMatches(
      doubled, [&](uint32_t x, uint32_t y) { return 2.0 * in[y * kW + x]; }, 0.0));
  EXPECT_TRUE(imageMatches(
      result, [&](uint32_t x, uint32_t y) { return 3.0 * 2.0 * in[y * kW + x] + 1000.0 + 0.25; }, 0.0));
}

// The comparison above can fail: a wrong expectation (3x instead of 2x) is reported.
TEST_F(ExecutorTest, WrongExpectationIsReported) {
  const SpirvFiles files = twoPassFiles();
  rt::PassExecutor ex(context(), CompiledPasses{twoPassManifest(), files}, 64, kW, kH);
  const auto in = ramp();
  ex.upload("input", rt::HostImage::fromFloats(kW, kH, ImageFormat::R32F, in));
  ex.run();
  const rt::HostImage doubled = ex.download("doubled");
  const auto verdict = imageMatches(
      doubled, [&](uint32_t x, uint32_t y) { return 3.0 * in[y * kW + x]; }, 1e-3);
  EXPECT_FALSE(verdict);
  EXPECT_NONFATAL_FAILURE(EXPECT_TRUE(verdict), "should be");
}

// Rows mode: one invocation per row along x runs an inclusive prefix sum (a SAT row scan) on
// r32ui with wrap-around arithmetic; Columns mode then scans the columns: a full integer SAT.
constexpr const char* kRows = R"(#version 460
layout(local_size_x = 16) in;
layout(set = 0, binding = 1, r32ui) uniform uimage2D sat;
void main() {
  int y = int(gl_GlobalInvocationID.x);
  ivec2 size = imageSize(sat);
  if (y >= size.y) return;
  uint sum = 0u;
  for (int x = 0; x < size.x; ++x) { sum += imageLoad(sat, ivec2(x, y)).r; imageStore(sat, ivec2(x, y), uvec4(sum)); }
}
)";
constexpr const char* kColumns = R"(#version 460
layout(local_size_x = 16) in;
layout(set = 0, binding = 1, r32ui) uniform uimage2D sat;
void main() {
  int x = int(gl_GlobalInvocationID.x);
  ivec2 size = imageSize(sat);
  if (x >= size.x) return;
  uint sum = 0u;
  for (int y = 0; y < size.y; ++y) { sum += imageLoad(sat, ivec2(x, y)).r; imageStore(sat, ivec2(x, y), uvec4(sum)); }
}
)";

TEST_F(ExecutorTest, RowsAndColumnsBuildAnIntegerSat) {
  const SpirvFiles files = {{"rows.spv", computeSpirv("rows.spv", kRows)},
                            {"columns.spv", computeSpirv("columns.spv", kColumns)}};
  Manifest m;
  m.images = {image("sat", ImageFormat::R32UI)};
  m.passes = {pass("rows", {{1, "sat", Access::StorageReadWrite, -1}}, DispatchMode::Rows, {16, 1, 1}),
              pass("columns", {{1, "sat", Access::StorageReadWrite, -1}}, DispatchMode::Columns, {16, 1, 1})};
  rt::PassExecutor ex(context(), CompiledPasses{m, files}, 64, kW, kH);
  std::vector<uint32_t> v(kW * kH);
  for (uint32_t i = 0; i < v.size(); ++i) v[i] = (i * 2654435761u) >> 8;  // large values: sums wrap mod 2^32
  ex.upload("sat", rt::HostImage::fromUints(kW, kH, ImageFormat::R32UI, v));
  ex.run();
  const rt::HostImage sat = ex.download("sat");
  uint32_t mismatches = 0;
  for (uint32_t y = 0; y < kH; ++y)
    for (uint32_t x = 0; x < kW; ++x) {
      uint32_t expect = 0;
      for (uint32_t j = 0; j <= y; ++j)
        for (uint32_t i = 0; i <= x; ++i) expect += v[j * kW + i];
      mismatches += sat.texelUint(x, y) != expect;
    }
  EXPECT_EQ(mismatches, 0u);
}

// A layered image with mips: a pass writes level 1 of both layers through a 2D-array storage
// view; sampled reads see every level through a sampler2DArray.
constexpr const char* kLayers = R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1, rg32f) writeonly uniform image2DArray level1;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(level1).xy))) return;
  for (int l = 0; l < 2; ++l) imageStore(level1, ivec3(p, l), vec4(p.x + 100 * l, p.y, 0, 0));
}
)";
constexpr const char* kReadLayers = R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1) uniform sampler2DArray moments;
layout(set = 0, binding = 2, r32f) writeonly uniform image2D result;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(result)))) return;
  imageStore(result, p, vec4(texelFetch(moments, ivec3(p, 1), 1).x));
}
)";

TEST_F(ExecutorTest, LayeredMipLevelsAreAddressable) {
  const SpirvFiles files = {{"write.spv", computeSpirv("write.spv", kLayers)},
                            {"read.spv", computeSpirv("read.spv", kReadLayers)}};
  Manifest m;
  ImageDesc moments = image("moments", ImageFormat::RG32F, SizeDomain::Map);
  moments.mipLevels = 0;
  moments.layers = 2;
  moments.linearFilter = true;
  ImageDesc result = image("result", ImageFormat::R32F, SizeDomain::Map);
  result.size.shift = 1;
  m.images = {moments, result};
  Pass write = pass("write", {{1, "moments", Access::StorageWrite, 1}});
  write.dispatch.size = {SizeDomain::Map, 1};
  Pass read = pass("read", {{1, "moments", Access::Sampled, -1}, {2, "result", Access::StorageWrite, -1}});
  read.dispatch.size = {SizeDomain::Map, 1};
  m.passes = {write, read};
  rt::PassExecutor ex(context(), CompiledPasses{m, files}, 32, kW, kH);
  ex.run();
  const rt::HostImage l1 = ex.download("moments", 1, 1);
  ASSERT_EQ(l1.width, 16u);
  EXPECT_TRUE(imageMatches(
      l1, [](uint32_t x, uint32_t) { return x + 100.0; }, 0.0));
  EXPECT_FLOAT_EQ(l1.texel(3, 5, 1), 5.0f);
  EXPECT_EQ(ex.download("moments", 5, 0).width, 1u) << "full mip chain of a 32^2 image has 6 levels";
  EXPECT_TRUE(imageMatches(
      ex.download("result"), [](uint32_t x, uint32_t) { return x + 100.0; }, 0.0));
}

TEST_F(ExecutorTest, TimingReportsEveryPass) {
  const SpirvFiles files = twoPassFiles();
  rt::PassExecutor ex(context(), CompiledPasses{twoPassManifest(), files}, 64, 256, 256);
  ex.upload("input", rt::HostImage::zeros(256, 256, ImageFormat::R32F));
  const rt::TimingResult t = ex.time(2, 5);
  ASSERT_EQ(t.passes.size(), 2u);
  EXPECT_EQ(t.passes[0].name, "double");
  EXPECT_EQ(t.passes[1].name, "add");
  for (const auto& p : t.passes) {
    EXPECT_GT(p.medianMs, 0.0) << p.name;
    EXPECT_LE(p.minMs, p.medianMs) << p.name;
  }
  EXPECT_GE(t.totalMs, t.passes[0].medianMs);
  EXPECT_EQ(t.runs, 5);
}

// Attribution, not speed: a pass with ~1000x the work of its neighbour gets most of the time
// whichever order they run in (lavapipe resolves timestamps lazily; a naive stamp placement
// charged each pass's work to the next one).
constexpr const char* kHeavy = R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1, r32f) writeonly uniform image2D heavy;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  float v = float(p.x) * 1e-3;
  for (int i = 0; i < 3000; ++i) v = fract(v * 1.61803 + 0.1234);
  imageStore(heavy, p, vec4(v));
}
)";
constexpr const char* kLight = R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1, r32f) writeonly uniform image2D light;
void main() { imageStore(light, ivec2(gl_GlobalInvocationID.xy), vec4(1.0)); }
)";

TEST_F(ExecutorTest, TimeGoesToThePassThatDidTheWork) {
  const SpirvFiles files = {{"heavy.spv", computeSpirv("heavy.spv", kHeavy)},
                            {"light.spv", computeSpirv("light.spv", kLight)}};
  for (const bool heavyFirst : {true, false}) {
    Manifest m;
    ImageDesc heavyImage = image("heavy", ImageFormat::R32F);
    ImageDesc lightImage = image("light", ImageFormat::R32F, SizeDomain::Map);
    m.images = {heavyImage, lightImage};
    Pass heavy = pass("heavy", {{1, "heavy", Access::StorageWrite, -1}});
    Pass light = pass("light", {{1, "light", Access::StorageWrite, -1}});
    light.dispatch.size = {SizeDomain::Map, 0};
    m.passes = heavyFirst ? std::vector<Pass>{heavy, light} : std::vector<Pass>{light, heavy};
    rt::PassExecutor ex(context(), CompiledPasses{m, files}, 8, 128, 128);
    const rt::TimingResult t = ex.time(1, 5);
    const double heavyMs = t.passes[heavyFirst ? 0 : 1].medianMs, lightMs = t.passes[heavyFirst ? 1 : 0].medianMs;
    EXPECT_GT(heavyMs, 0.5 * t.totalMs) << "heavy first: " << heavyFirst << ", heavy " << heavyMs << " ms, light "
                                        << lightMs;
    EXPECT_GT(heavyMs, 5 * lightMs) << "heavy first: " << heavyFirst;
  }
}

// --- errors: each one names the pass and says what is wrong ---

std::string errorOf(const Manifest& m, const SpirvFiles& files) {
  try {
    rt::PassExecutor ex(VulkanTest::context(), CompiledPasses{m, files}, 64, kW, kH);
  } catch (const rt::ExecutorError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST_F(ExecutorTest, ManifestFromAnotherVersionIsRejected) {
  Manifest m = twoPassManifest();
  m.formatVersion = kManifestFormatVersion + 1;
  EXPECT_NE(errorOf(m, twoPassFiles()).find("format version"), std::string::npos);
  // The same through manifest.json.
  const auto dir = freshTempDir("executor_old_manifest");
  nlohmann::ordered_json j = toJson(twoPassManifest());
  j["format_version"] = kManifestFormatVersion + 1;
  std::ofstream(dir / "manifest.json") << j.dump(2);
  try {
    loadManifest((dir / "manifest.json").string());
    FAIL() << "expected ManifestError";
  } catch (const ManifestError& e) {
    EXPECT_NE(std::string(e.what()).find("format version"), std::string::npos) << e.what();
  }
}

TEST_F(ExecutorTest, MissingSpirvNamesThePass) {
  SpirvFiles files = twoPassFiles();
  files.erase("add.spv");
  const std::string e = errorOf(twoPassManifest(), files);
  EXPECT_NE(e.find("pass 'add'"), std::string::npos) << e;
  EXPECT_NE(e.find("not found"), std::string::npos) << e;
}

TEST_F(ExecutorTest, UnknownImageNamesThePass) {
  Manifest m = twoPassManifest();
  m.passes[1].bindings[1].image = "moments";
  const std::string e = errorOf(m, twoPassFiles());
  EXPECT_NE(e.find("pass 'add'"), std::string::npos) << e;
  EXPECT_NE(e.find("'moments'"), std::string::npos) << e;
}

TEST_F(ExecutorTest, ShaderManifestMismatchesAreCaught) {
  const SpirvFiles files = twoPassFiles();
  Manifest wrongFormat = twoPassManifest();
  wrongFormat.images[1].format = ImageFormat::RG32F;  // the shader says r32f
  EXPECT_NE(errorOf(wrongFormat, files).find("shader declares r32f"), std::string::npos) << errorOf(wrongFormat, files);
  Manifest wrongKind = twoPassManifest();
  wrongKind.passes[1].bindings[1].access = Access::StorageRead;  // the shader samples it
  EXPECT_NE(errorOf(wrongKind, files).find("combined image sampler in the shader"), std::string::npos)
      << errorOf(wrongKind, files);
  Manifest wrongLocal = twoPassManifest();
  wrongLocal.passes[0].localSize = {16, 16, 1};
  EXPECT_NE(errorOf(wrongLocal, files).find("local size"), std::string::npos) << errorOf(wrongLocal, files);
  Manifest unlisted = twoPassManifest();
  unlisted.passes[1].bindings.erase(unlisted.passes[1].bindings.begin());  // frame UBO not listed
  EXPECT_NE(errorOf(unlisted, files).find("does not list"), std::string::npos) << errorOf(unlisted, files);
}

TEST_F(ExecutorTest, UploadOfTheWrongShapeIsRejected) {
  rt::PassExecutor ex(context(), CompiledPasses{twoPassManifest(), twoPassFiles()}, 64, kW, kH);
  EXPECT_THROW(ex.upload("input", rt::HostImage::zeros(kW + 1, kH, ImageFormat::R32F)), rt::ExecutorError);
  EXPECT_THROW(ex.upload("input", rt::HostImage::zeros(kW, kH, ImageFormat::RG32F)), rt::ExecutorError);
  EXPECT_THROW(ex.upload("nope", rt::HostImage::zeros(kW, kH, ImageFormat::R32F)), rt::ExecutorError);
}

}  // namespace
}  // namespace shadowc::test

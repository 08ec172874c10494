// `depth_input d32|d24[(z: reverse)]` (docs/dsl.md "depth_input"): the filter reads the engine's
// depth attachment and its first pass (passes/depth_convert.comp) turns it into the normalized
// linear depth L = (z - near) / (far - near) the other passes read. For D32 and D24, standard and
// reverse Z, on a spot (perspective), a sun (orthographic) and a point light (six perspective
// faces; a cascaded sun is refused, E0452), with the harness's rasterizer keeping its own depth
// attachment in that format from the same draw as its linear depth:
//  1. the conversion: every texel within kConvertUlps ulp(L) of the exact (double) L of the
//     stored depth value d, plus |dL/dd| ulp(d) for D24, whose unorm -> float conversion in the
//     sampler need not round correctly; "nothing hit" exactly 1;
//  2. the pipeline: the converted map against the harness's own linear depth (computed from the
//     view z in the fragment shader) within |dL/dd| e_d + kLinearUlps ulp(L), where e_d bounds the
//     stored d's error: the vertex stage's fp32 clip z and w (a 4-term dot product and the
//     matrix's own rounding: 5 u sum|terms|, u = 2^-24, over the scene's vertices, divided by the
//     nearest w for a perspective map), the rasterizer's interpolation (1 u) and the rounding to
//     the format (u / 2, D24's quantum and D32's ulp below 1 alike);
//  3. the filter: its visibility equals the same filter's on the linear input within RMSE 1e-3.
// The sibling: the reverse-Z words read as standard Z (the wrong convention) break bound 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

using HardwareDepthTest = VulkanTest;

constexpr uint32_t kMap = 256, kScreen = 64;
constexpr int kSamples = 4;
// depth_convert.comp: 1 - d, the two products, their sum and the quotient each round once
// (<= 1/2 ulp relative each, and L's sensitivity to each is at most 1): 2.5 ulp.
constexpr double kConvertUlps = 2.5;
// The harness's L = (z - near) / (far - near) rounds its subtraction and quotient (1 ulp), and
// its interpolated view z is perspective-correct in fp32 (1 ulp more).
constexpr double kLinearUlps = 2.0;

struct Case {
  const char* label;
  const char* scene;
  const char* light;  // the filter's `light` and more settings
};
const Case kCases[] = {
    {"spot", "two_planes", "    light     area(size: scene)\n"},
    {"sun", "sun_two_planes", "    light     sun\n"},
    {"point", "point_room", "    light     point(radius: scene)\n"},
};
const char* const kInputs[] = {"d32", "d32(z: reverse)", "d24", "d24(z: reverse)"};

std::string source(const Case& c, const std::string& input) {
  std::string s = std::string("filter hardware_depth {\n") + c.light +
                  "    depth\n    kernel    fixed(3)\n    sampling  grid(3x3)\n    bias      constant(0.002)\n";
  if (!input.empty()) s += "    depth_input " + input + "\n";
  return s + "}\n";
}

double ulp(double v) {
  const float f = float(v);
  return double(std::nextafter(f, std::numeric_limits<float>::infinity())) - double(f);
}

// The stored value d of one texel, as the depth-aspect view returns it.
double storedDepth(const rt::HostImage& hw, size_t i) {
  uint32_t w;
  std::memcpy(&w, hw.bytes.data() + 4 * i, 4);
  if (hw.format == ImageFormat::D24) return double(float(double(w & 0xFFFFFFu) / 16777215.0));
  float f;
  std::memcpy(&f, &w, 4);
  return f;
}

// The exact linear depth of stored d (depth_convert.comp's formulas in double) and |dL/dd|.
struct Linear {
  double value, slope;
};
Linear exactLinear(double d, bool reversed, bool ortho, double n, double f) {
  const double a = reversed ? 1.0 - d : d, b = 1.0 - a;  // the near and far weights
  if (ortho) return {a, 1.0};
  const double den = a * n + b * f;
  return {a * n / den, n * f / (den * den)};  // d/da (a n / (a n + (1 - a) f)) = n f / den^2
}

struct Comparison {
  size_t texels = 0, hits = 0;
  double worstConvertUlps = 0;  // (|converted - exact| - the D24 sampler's part) / ulp(L)
  double worstFormatRatio = 0;  // |converted - harness| / bound 2
  size_t formatFailures = 0;
};

constexpr double kU = 1.0 / 16777216.0;  // 2^-24

// e_d of bound 2 for the light pass's clip matrices (reversed: z' = w - z, one more rounding).
double clipDepthError(const rt::PreparedScene& sc, bool reversed) {
  const rt::FrameSetup& s = sc.setup;
  std::vector<glm::mat4> clips{s.lightViewProj};
  if (s.cube) clips.assign(s.faceViewProj.begin(), s.faceViewProj.end());
  for (int i = 0; i < s.cascadeCount; ++i) clips.push_back(s.cascadeViewProj[size_t(i)]);
  double worst = 0;
  for (const glm::mat4& m : clips) {
    double terms = 0, minW = std::numeric_limits<double>::max();
    for (const rt::Mesh& mesh : sc.scene.meshes)
      for (const glm::vec3& p : mesh.positions) {
        const double q[4] = {p.x, p.y, p.z, 1.0};
        double z = 0, w = 0, wv = 0;
        for (int j = 0; j < 4; ++j) {
          z += std::abs(m[j][2] * q[j]) + (reversed ? std::abs(m[j][3] * q[j]) : 0.0);
          w += std::abs(m[j][3] * q[j]);
          wv += m[j][3] * q[j];
        }
        terms = std::max(terms, s.orthographic ? z : z + w);
        if (wv > 0) minW = std::min(minW, wv);
      }
    const double scale = s.orthographic ? 1.0 : 1.0 / std::max(double(s.nearPlane), std::min(minW, 1e30));
    worst = std::max(worst, (5.0 + (reversed ? 1.0 : 0.0)) * kU * terms * scale);
  }
  return worst + kU + kU / 2;
}

Comparison compare(const rt::HostImage& hw, const std::vector<float>& converted, const std::vector<float>& harness,
                   bool reversed, bool ortho, double n, double f, double depthError) {
  Comparison c;
  c.texels = converted.size();
  for (size_t i = 0; i < converted.size(); ++i) {
    const double d = storedDepth(hw, i);
    const Linear exact = exactLinear(d, reversed, ortho, n, f);
    const double sampler = hw.format == ImageFormat::D24 ? exact.slope * ulp(d) : 0.0;
    c.worstConvertUlps =
        std::max(c.worstConvertUlps, (std::abs(converted[i] - exact.value) - sampler) / ulp(exact.value));
    if (harness[i] >= 1.0f) continue;  // nothing hit: checked exactly below
    ++c.hits;
    const double bound = exact.slope * depthError + kLinearUlps * ulp(harness[i]);
    const double ratio = std::abs(double(converted[i]) - harness[i]) / bound;
    c.worstFormatRatio = std::max(c.worstFormatRatio, ratio);
    if (ratio > 1.0) ++c.formatFailures;
  }
  return c;
}

struct FilterRun {
  std::shared_ptr<const rt::PreparedScene> scene;
  rt::RunOutputs outputs;
};
FilterRun run(rt::VulkanContext& ctx, const Case& c, const std::string& input) {
  const CompiledFilter* cf =
      compileFilterCached(std::string("hardware_depth_") + c.label + "_" + input, source(c, input));
  EXPECT_NE(cf, nullptr);
  if (!cf) return {};
  FilterRun r;
  r.scene = sceneCaseFor(ctx, c.scene, kMap, kScreen, kSamples, cf->passes);
  rt::RunOptions options;
  if (!input.empty()) options.downloads = {"shadow_depth"};
  r.outputs = rt::runPasses(ctx, cf->passes, rt::sceneInputs(cf->passes, *r.scene), options);
  return r;
}

TEST_F(HardwareDepthTest, ConvertedMapIsTheLinearDepthTheFormatHolds) {
  for (const Case& c : kCases) {
    const FilterRun linear = run(context(), c, "");
    for (const char* input : kInputs) {
      SCOPED_TRACE(std::string(c.label) + " " + input);
      const FilterRun r = run(context(), c, input);
      ASSERT_TRUE(r.scene);
      const rt::HostImage& hw = r.scene->raster.hardwareDepth;
      ASSERT_EQ(hw.width, kMap);
      const std::string in = input;
      const bool reversed = in.find("reverse") != std::string::npos;
      EXPECT_EQ(hw.format, in.rfind("d24", 0) == 0 ? ImageFormat::D24 : ImageFormat::D32F);
      const std::vector<float> converted = r.outputs.images.at("shadow_depth").floats();
      const std::vector<float> harness = r.scene->raster.lightDepth.floats();
      const float n = r.scene->setup.frame.lightParams[1], f = r.scene->setup.frame.lightParams[2];
      const Comparison cmp = compare(hw, converted, harness, reversed, r.scene->setup.orthographic, n, f,
                                     clipDepthError(*r.scene, reversed));
      RecordProperty(std::string(c.label) + "_" + in + "_convert_ulps", std::to_string(cmp.worstConvertUlps));
      RecordProperty(std::string(c.label) + "_" + in + "_format_ratio", std::to_string(cmp.worstFormatRatio));
      EXPECT_GT(cmp.hits, cmp.texels / 8) << "too few texels hit geometry";
      EXPECT_LE(cmp.worstConvertUlps, kConvertUlps);
      EXPECT_EQ(cmp.formatFailures, 0u) << "worst |converted - harness| / bound " << cmp.worstFormatRatio;
      size_t nothingHitWrong = 0;
      for (size_t i = 0; i < converted.size(); ++i) nothingHitWrong += harness[i] >= 1.0f && converted[i] != 1.0f;
      EXPECT_EQ(nothingHitWrong, 0u) << "texels where nothing was hit must convert to exactly 1";
      const rt::Metrics m = rt::computeMetrics(r.outputs.visibility, linear.outputs.visibility, r.scene->mask);
      EXPECT_LE(m.rmse, 1e-3) << "visibility against the linear-input filter's";
    }
  }
}

TEST_F(HardwareDepthTest, ReverseZReadAsStandardBreaksTheFormatBound) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.label);
    const FilterRun r = run(context(), c, "d32(z: reverse)");
    ASSERT_TRUE(r.scene);
    const std::vector<float> harness = r.scene->raster.lightDepth.floats();
    std::vector<float> wrong(harness.size());
    const float n = r.scene->setup.frame.lightParams[1], f = r.scene->setup.frame.lightParams[2];
    const bool ortho = r.scene->setup.orthographic;
    for (size_t i = 0; i < wrong.size(); ++i)
      wrong[i] = float(exactLinear(storedDepth(r.scene->raster.hardwareDepth, i), false, ortho, n, f).value);
    const Comparison cmp =
        compare(r.scene->raster.hardwareDepth, wrong, harness, false, ortho, n, f, clipDepthError(*r.scene, true));
    EXPECT_GT(cmp.formatFailures, cmp.hits / 2) << "the wrong convention passed the bound";
  }
}

}  // namespace
}  // namespace shadowc::test

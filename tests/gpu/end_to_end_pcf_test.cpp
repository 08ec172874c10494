// End to end: the pcf_grid5x5 sample on a rasterized scene, against (1) the CPU PCF of the very
// same downloaded shadow map at the same receivers (the implementation error: should be ~0) and
// (2) the Embree ground truth (the method error of 5x5 PCF with shadow mapping). Telling the two
// apart is the point: a GPU result far from the CPU PCF is a bug; far from Embree, a limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"
#include "runtime/reference/cpu_filters.h"

namespace shadowc::test {
namespace {

using EndToEndPcfTest = VulkanTest;

TEST_F(EndToEndPcfTest, Pcf5x5OnTwoPlanesMatchesCpuPcfAndSeparatesMethodError) {
  constexpr uint32_t kScreen = 128, kMap = 512;
  const CompiledFilter* cf = compileFilterCached("pcf_grid5x5", sampleSource("pcf_grid5x5"));
  ASSERT_NE(cf, nullptr);
  const rt::PreparedScene& sc = sceneCase(context(), "two_planes", kMap, kScreen, 8);
  rt::RunOptions options;
  options.downloads = {"shadow_depth"};
  const rt::SceneRunResult run = rt::runOnScene(context(), cf->passes, sc, options);
  const std::vector<float>& gpu = run.outputs.visibility;
  const std::vector<float> depth = run.outputs.images.at("shadow_depth").channel(0);  // what the shader read

  // CPU PCF at each receiver: frame.glsl light space and bias.glsl's slope-scaled bias, in double.
  const BiasSpec& bias = cf->spec.bias;
  ASSERT_EQ(bias.kind, BiasKind::SlopeScaled);
  const ShadowcFrame& f = sc.setup.frame;
  const glm::dmat4 view = glm::dmat4(sc.setup.lightView);
  const rt::cpu::ImageView map{depth.data(), kMap, kMap, 1};
  const std::vector<float> pos = sc.raster.gbufferPosition.floats(), nrm = sc.raster.gbufferNormal.floats();
  std::vector<float> cpu(gpu.size(), 1.0f);
  for (size_t i = 0; i < gpu.size(); ++i) {
    if (pos[i * 4 + 3] == 0.0f) continue;
    const glm::dvec3 p = glm::dvec3(view * glm::dvec4(pos[i * 4], pos[i * 4 + 1], pos[i * 4 + 2], 1.0));
    const glm::dvec3 n = glm::dmat3(view) * glm::dvec3(nrm[i * 4], nrm[i * 4 + 1], nrm[i * 4 + 2]);
    const double u = 0.5 + 0.5 * p.x / (p.z * f.lightParams[0]), v = 0.5 + 0.5 * p.y / (p.z * f.lightParams[0]);
    if (p.z <= 0 || u < 0 || u > 1 || v < 0 || v > 1) continue;
    const double d = (p.z - f.lightParams[1]) / (f.lightParams[2] - f.lightParams[1]);
    const double len = glm::length(n) * glm::length(p);
    const double ndotl = len > 0 ? std::clamp(glm::dot(n, -p) / len, 0.0, 1.0) : 0.0;
    const double b = std::max(bias.slope * (1.0 - ndotl), bias.constant);
    cpu[i] = float(rt::cpu::pcfGridAt(map, u, v, 5, d, b));
  }

  const rt::Metrics implementation = rt::computeMetrics(gpu, cpu, sc.mask);
  const rt::Metrics gpuVsTruth = rt::computeMetrics(gpu, sc.reference, sc.mask);
  const rt::Metrics methodVsTruth = rt::computeMetrics(cpu, sc.reference, sc.mask);
  fmt::print(
      "pcf_grid5x5 on two_planes: GPU vs CPU PCF rmse {:.2e} (max {:.3f}, {} px differ > 1e-5 of {}); "
      "CPU PCF vs Embree rmse {:.4f}; GPU vs Embree rmse {:.4f}\n",
      implementation.rmse, implementation.maxAbsError,
      std::count_if(gpu.begin(), gpu.end(),
                    [&](const float& g) { return std::fabs(g - cpu[size_t(&g - gpu.data())]) > 1e-5f; }),
      implementation.compared, methodVsTruth.rmse, gpuVsTruth.rmse);
  // The implementation reproduces the CPU PCF: differences only where fp32 and double put a
  // receiver on different sides of a texel edge or of the biased depth (one tap = 1/25).
  EXPECT_LT(implementation.rmse, 0.005);
  EXPECT_LE(implementation.p99AbsError, 1e-5);
  // Shadow mapping's own error dominates and the GPU inherits exactly it.
  EXPECT_GT(methodVsTruth.rmse, 10 * implementation.rmse);
  EXPECT_NEAR(gpuVsTruth.rmse, methodVsTruth.rmse, 0.005);
}

}  // namespace
}  // namespace shadowc::test

// The two forms of the SAT scans (docs/manifest.md "Pass forms"): the serial scan (one invocation
// per row or column, the CPU form) and the parallel one (a workgroup per row or column, the GPU
// form) of an int32 table must give bit-identical tables: the serial form adds running sums, the
// parallel one the blocked order of templates/passes/sat_common.glsl, and sums mod 2^32 are exact
// in any order. Each form is forced with the executor's override and the tables are compared byte
// for byte, on maps of 256^2, 509^2 (prime: every chunk, group and tile boundary falls mid-row),
// 1024^2, 2048^2 and 4096^2 (two tiles per row). An fp32 table has the serial form only: it equals
// a CPU emulation of running sums bit for bit, and the blocked order would give another table (the
// sibling: the order matters in fp32, which is why no parallel form is offered for it).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/gpu_test_util.h"
#include "gpu/vulkan_fixture.h"

namespace shadowc::test {
namespace {

using SatFormsTest = VulkanTest;

// Its own depths (gpu_test_util.h craftedDepth), not closed_form_sat_test.cpp's.
constexpr uint64_t kDepthSeed = 0x2545F4914F6CDD1Dull;

struct FormRun {
  rt::HostImage sat;
  std::vector<rt::FormChoice> forms;
};

FormRun runForm(rt::VulkanContext& ctx, const CompiledFilter& cf, uint32_t map, const std::string& form) {
  rt::RunOptions options;
  options.downloads = {"sat"};
  options.passForm = form;
  rt::RunOutputs out = rt::runPasses(
      ctx, cf.passes,
      craftedInputs(map, 8, 8, identityFrame(map, 8, 8, 0.5f), craftedDepth(map, kDepthSeed), craftGBuffer({}, 8, 8)),
      options);
  return {std::move(out.images.at("sat")), std::move(out.forms)};
}

std::string formsRun(const FormRun& r) {
  std::string s;
  for (const rt::FormChoice& c : r.forms) s += c.pass + "=" + c.form + " ";
  return s;
}

// Byte-for-byte: the number of differing texel channels (4-byte words).
uint64_t differingWords(const rt::HostImage& a, const rt::HostImage& b) {
  if (a.bytes.size() != b.bytes.size()) return UINT64_MAX;
  uint64_t bad = 0;
  for (size_t i = 0; i + 4 <= a.bytes.size(); i += 4)
    bad += std::memcmp(a.bytes.data() + i, b.bytes.data() + i, 4) != 0;
  return bad;
}

struct FormCase {
  const char* sample;
  uint32_t map;
};
void PrintTo(const FormCase& c, std::ostream* os) { *os << c.sample << " " << c.map << "^2"; }

class SatFormsBitIdentical : public VulkanTest, public ::testing::WithParamInterface<FormCase> {};

TEST_P(SatFormsBitIdentical, SerialAndParallelFormsGiveTheSameTable) {
  const FormCase c = GetParam();
  const CompiledFilter* cf = compileFilterCached(c.sample, sampleSource(c.sample));
  ASSERT_NE(cf, nullptr);
  const FormRun serial = runForm(context(), *cf, c.map, "serial");
  const FormRun parallel = runForm(context(), *cf, c.map, "parallel");
  EXPECT_EQ(formsRun(serial), "sat_rows=serial sat_columns=serial ");
  EXPECT_EQ(formsRun(parallel), "sat_rows=parallel sat_columns=parallel ");
  ASSERT_EQ(serial.sat.width, c.map);
  EXPECT_EQ(differingWords(serial.sat, parallel.sat), 0u) << c.sample << " " << c.map << "^2";
}

INSTANTIATE_TEST_SUITE_P(Maps, SatFormsBitIdentical,
                         ::testing::Values(FormCase{"vssm_int32_sat", 256}, FormCase{"vssm_int32_sat", 509},
                                           FormCase{"vssm_int32_sat", 1024}, FormCase{"vssm_int32_sat", 2048},
                                           FormCase{"vssm_int32_sat", 4096}),
                         [](const auto& info) {
                           return std::string(info.param.sample).substr(5) + "_" + std::to_string(info.param.map);
                         });

// Four channels (moment shadow maps' rgba32ui table) in both forms.
TEST_F(SatFormsTest, FourChannelInt32TableIsTheSameInBothForms) {
  const CompiledFilter* cf = compileFilterCached("msm_sat_int32", sampleSource("msm_sat_int32"));
  ASSERT_NE(cf, nullptr);
  const FormRun serial = runForm(context(), *cf, 509, "serial");
  ASSERT_EQ(serial.sat.format, ImageFormat::RGBA32UI);
  EXPECT_EQ(differingWords(serial.sat, runForm(context(), *cf, 509, "parallel").sat), 0u);
}

// The unfused row scan (it reads the moments image that `mips on` keeps) has both forms too.
TEST_F(SatFormsTest, UnfusedScansGiveTheSameTableInBothForms) {
  const CompiledFilter* cf =
      compileFilterCached("vssm_int32_sat_unfused", withSetting(sampleSource("vssm_int32_sat"), "mips", "on"));
  ASSERT_NE(cf, nullptr);
  EXPECT_EQ(differingWords(runForm(context(), *cf, 509, "serial").sat, runForm(context(), *cf, 509, "parallel").sat),
            0u);
}

// The fp32 centered moments (d, d*d) - 0.5 of the depths, interleaved rg, as the scans encode them.
std::vector<float> centered(const std::vector<float>& d) {
  std::vector<float> m(d.size() * 2);
  for (size_t i = 0; i < d.size(); ++i) {
    const float sq = d[i] * d[i];
    m[2 * i] = d[i] - 0.5f;
    m[2 * i + 1] = sq - 0.5f;
  }
  return m;
}

// One row or column of n values at stride `step`, scanned in place in fp32: the blocked order of
// sat_common.glsl (chunks of 8, groups of 16 chunks, tiles of 16 groups), or plain running sums.
void scanLine(float* v, uint32_t n, size_t step, bool blocked) {
  float tile = 0, group = 0, chunkCarry = 0, run = 0;
  for (uint32_t x0 = 0, chunk = 0; x0 < n; x0 += 8, ++chunk) {
    const float base = blocked ? (tile + group) + chunkCarry : 0.0f;
    float local = blocked ? 0.0f : run;
    for (uint32_t x = x0; x < std::min(n, x0 + 8); ++x) {
      local += v[x * step];
      v[x * step] = base + local;
    }
    run = local;
    chunkCarry += local;
    if ((chunk + 1) % 16 == 0) group += chunkCarry, chunkCarry = 0;
    if ((chunk + 1) % 256 == 0) tile += group, group = 0;
  }
}

std::vector<float> cpuTable(std::vector<float> m, uint32_t n, bool blocked) {
  for (uint32_t c = 0; c < 2; ++c) {
    for (uint32_t y = 0; y < n; ++y) scanLine(m.data() + size_t(y) * n * 2 + c, n, 2, blocked);
    for (uint32_t x = 0; x < n; ++x) scanLine(m.data() + size_t(x) * 2 + c, n, size_t(n) * 2, blocked);
  }
  return m;
}

uint64_t differingFromCpu(const rt::HostImage& gpu, const std::vector<float>& cpu) {
  rt::HostImage want = gpu;
  std::memcpy(want.bytes.data(), cpu.data(), std::min(want.bytes.size(), cpu.size() * 4));
  return differingWords(gpu, want);
}

TEST_F(SatFormsTest, Fp32TableIsRunningSumsBitForBit) {
  const CompiledFilter* cf = compileFilterCached("vssm_fp32_centered_sat", sampleSource("vssm_fp32_centered_sat"));
  ASSERT_NE(cf, nullptr);
  for (const uint32_t map : {509u, 4096u}) {
    const FormRun serial = runForm(context(), *cf, map, "auto");
    EXPECT_EQ(formsRun(serial), "") << "an fp32 table has one form";
    EXPECT_EQ(differingFromCpu(serial.sat, cpuTable(centered(craftedDepth(map, kDepthSeed)), map, false)), 0u) << map;
  }
}

// Sibling: the blocked order gives another fp32 table, so the byte comparison above would catch a
// scan that added in another order (and a parallel fp32 form would not be bit-identical).
TEST_F(SatFormsTest, Fp32TableDiffersFromTheBlockedOrder) {
  const CompiledFilter* cf = compileFilterCached("vssm_fp32_centered_sat", sampleSource("vssm_fp32_centered_sat"));
  ASSERT_NE(cf, nullptr);
  const uint32_t map = 509;
  const std::vector<float> blocked = cpuTable(centered(craftedDepth(map, kDepthSeed)), map, true);
  EXPECT_GT(differingFromCpu(runForm(context(), *cf, map, "auto").sat, blocked), 0u);
}

// The executor's own choice on lavapipe (a CPU device): the serial form, said so; the
// environment's override (SHADOWC_PASS_FORM) is honoured when the caller passes none.
TEST_F(SatFormsTest, AutoChoosesTheSerialFormOnTheCpuDeviceAndTheEnvironmentOverrides) {
  const CompiledFilter* cf = compileFilterCached("vssm_int32_sat", sampleSource("vssm_int32_sat"));
  ASSERT_NE(cf, nullptr);
  ASSERT_EQ(context().properties().deviceType, VK_PHYSICAL_DEVICE_TYPE_CPU);
  const FormRun automatic = runForm(context(), *cf, 256, "auto");
  EXPECT_EQ(formsRun(automatic), "sat_rows=serial sat_columns=serial ");
  EXPECT_EQ(rt::describeChoices(automatic.forms), "pass forms: sat_rows serial, sat_columns serial (auto, cpu device)");
  ::setenv("SHADOWC_PASS_FORM", "parallel", 1);
  const FormRun env = runForm(context(), *cf, 256, "");
  ::unsetenv("SHADOWC_PASS_FORM");
  EXPECT_EQ(formsRun(env), "sat_rows=parallel sat_columns=parallel ");
  EXPECT_EQ(env.forms.front().why, "override");
}

}  // namespace
}  // namespace shadowc::test

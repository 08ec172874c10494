// Every sample filter compiles in process (the driver), and every written .spv passes spirv-val again when
// read back from disk; the manifest names only files that exist. Samples are discovered at run
// time, so a new samples/filters/*.shadow is covered without editing this test.
#include <gtest/gtest.h>

#include "backend/spirv_backend.h"
#include "emit/emit_support.h"

namespace shadowc {
namespace {

class SampleCompile : public ::testing::TestWithParam<std::string> {};

void compileAndCheck(const std::string& sample, bool optimize) {
  const driver::Result r = test::compileSample(sample, optimize);
  ASSERT_TRUE(r.ok) << sample << ":\n" << r.log;
  const FilterSpec& spec = r.artifact->spec;
  const auto dir = test::freshTempDir("sample-" + sample);
  ASSERT_EQ(driver::writeArtifact(dir, *r.artifact), "");
  const auto files = test::readDir(dir);
  int spv = 0;
  for (const auto& [name, bytes] : files)
    if (name.ends_with(".spv")) {
      EXPECT_EQ(validateSpirv(test::spirvWords(bytes)), "") << sample << "/" << name;
      ++spv;
    }
  const Manifest m = loadManifest((dir / "manifest.json").string());
  EXPECT_EQ(m.filter, spec.name);
  EXPECT_EQ(m.passes.back().name, "shade");
  for (const Pass& p : m.passes) {
    EXPECT_TRUE(files.count(p.spirv)) << p.spirv;
    EXPECT_TRUE(files.count(p.glsl)) << p.glsl;
  }
  EXPECT_TRUE(files.count(m.shade.glsl));
  EXPECT_GE(spv, 1);
  std::filesystem::remove_all(dir);
}

TEST_P(SampleCompile, OptimizedCompilesAndEveryWrittenSpvValidates) { compileAndCheck(GetParam(), true); }
TEST_P(SampleCompile, UnoptimizedCompilesAndEveryWrittenSpvValidates) { compileAndCheck(GetParam(), false); }

TEST_P(SampleCompile, RecompilingGivesByteIdenticalFiles) {
  const auto a = test::freshTempDir("det-a"), b = test::freshTempDir("det-b");
  const driver::Result ra = test::compileSample(GetParam()), rb = test::compileSample(GetParam());
  ASSERT_TRUE(ra.ok && rb.ok) << ra.log << rb.log;
  ASSERT_EQ(driver::writeArtifact(a, *ra.artifact), "");
  ASSERT_EQ(driver::writeArtifact(b, *rb.artifact), "");
  const auto fa = test::readDir(a), fb = test::readDir(b);
  ASSERT_EQ(fa.size(), fb.size());
  for (const auto& [name, bytes] : fa) EXPECT_TRUE(fb.at(name) == bytes) << name << " differs between two compiles";
  std::filesystem::remove_all(a);
  std::filesystem::remove_all(b);
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleCompile, ::testing::ValuesIn(test::sampleFilterNames()),
                         [](const auto& info) { return info.param; });

TEST(SampleCompile, ThereAreSamplesToCompile) { EXPECT_FALSE(test::sampleFilterNames().empty()); }

}  // namespace
}  // namespace shadowc

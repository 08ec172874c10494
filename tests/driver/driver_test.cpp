// The compiler driver (compiler/driver/driver.h): where each stage stops, what the artifact
// holds, that -M's planned names are exactly the written files, and that an artifact written to
// disk reads back (CompiledPasses::fromDirectory) as the same passes the run harness gets in memory.
#include "driver/driver.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>

#include "support/test_support.h"

namespace shadowc {
namespace {

const std::string kPcf =
    "filter pcf_t {\n  light area(size: scene)\n  depth\n  kernel fixed(5)\n  sampling grid(5x5)\n}\n";

std::string samplePath(const std::string& name) {
  return (test::sourceDir() / "samples" / "filters" / (name + ".shadow")).string();
}

driver::Options stopAfter(driver::Stage stage) {
  driver::Options o;
  o.stopAfter = stage;
  return o;
}

TEST(Driver, EachStageStopsWhereAsked) {
  const driver::Result check = driver::compileSource(kPcf, "pcf_t.shadow", stopAfter(driver::Stage::Check));
  EXPECT_TRUE(check.ok) << check.log;
  EXPECT_TRUE(check.spec.has_value());
  EXPECT_FALSE(check.plan.has_value());
  EXPECT_FALSE(check.artifact.has_value());
  const driver::Result plan = driver::compileSource(kPcf, "pcf_t.shadow", stopAfter(driver::Stage::Plan));
  EXPECT_TRUE(plan.ok) << plan.log;
  ASSERT_TRUE(plan.plan.has_value());
  EXPECT_EQ(plan.plan->manifest.passes.back().name, "shade");
  EXPECT_FALSE(plan.artifact.has_value());
  const driver::Result full = driver::compileSource(kPcf, "pcf_t.shadow");
  ASSERT_TRUE(full.ok) << full.log;
  ASSERT_TRUE(full.artifact.has_value());
  EXPECT_EQ(full.artifact->spec.name, "pcf_t");
  EXPECT_EQ(full.artifact->manifest.filter, "pcf_t");
}

TEST(Driver, AnErrorIsADiagnosticAndNoArtifact) {
  const driver::Result r = driver::compileSource("filter bad {\n  kernel quadtre(height: 3)\n}\n", "bad.shadow");
  EXPECT_FALSE(r.ok);
  EXPECT_FALSE(r.spec.has_value());
  EXPECT_FALSE(r.artifact.has_value());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_FALSE(r.diagnostics.front().code.empty());
  EXPECT_NE(r.log.find("bad.shadow:2:"), std::string::npos) << r.log;
}

TEST(Driver, WerrorTurnsAFrontEndWarningIntoAFailure) {
  const driver::Result warn = driver::compileFile(samplePath("sat_fp32_naive"), stopAfter(driver::Stage::Check));
  EXPECT_TRUE(warn.ok) << warn.log;
  EXPECT_NE(warn.log.find("W0504"), std::string::npos) << warn.log;
  driver::Options werror = stopAfter(driver::Stage::Check);
  werror.warningsAsErrors = true;
  const driver::Result fail = driver::compileFile(samplePath("sat_fp32_naive"), werror);
  EXPECT_FALSE(fail.ok);
  EXPECT_NE(fail.log.find("W0504"), std::string::npos) << fail.log;
}

TEST(Driver, ArtifactFilesAreSortedAndFindable) {
  const driver::Result r = driver::compileFile(samplePath("vssm_int32_sat"));
  ASSERT_TRUE(r.ok) << r.log;
  const auto& files = r.artifact->files;
  for (size_t i = 1; i < files.size(); ++i) EXPECT_LT(files[i - 1].name, files[i].name);
  for (const EmittedFile& f : files) {
    const std::string* bytes = r.artifact->file(f.name);
    ASSERT_NE(bytes, nullptr) << f.name;
    EXPECT_EQ(*bytes, f.bytes);
  }
  EXPECT_EQ(r.artifact->file("no_such_file.spv"), nullptr);
  const CompiledPasses passes = r.artifact->passes();
  for (const Pass& p : passes.manifest.passes) EXPECT_TRUE(passes.files.count(p.spirv)) << p.spirv;
}

// -M lists what compile writes: the planned names equal the artifact's file names.
TEST(Driver, PlannedOutputsAreTheWrittenFiles) {
  for (const char* sample : {"pcf_grid5x5", "vssm_adaptive", "vsm_blur_mips_bleeding", "layered_vsm_lloyd"}) {
    const driver::Result r = driver::compileFile(samplePath(sample));
    ASSERT_TRUE(r.ok) << sample << ": " << r.log;
    std::set<std::string> written;
    for (const EmittedFile& f : r.artifact->files) written.insert(f.name);
    const std::vector<std::string> planned = driver::plannedOutputs(*r.plan, *r.spec);
    EXPECT_EQ(std::set<std::string>(planned.begin(), planned.end()), written) << sample;
  }
}

TEST(Driver, WrittenArtifactReadsBackAsTheSamePasses) {
  const driver::Result r = driver::compileFile(samplePath("vssm_int32_sat"));
  ASSERT_TRUE(r.ok) << r.log;
  const auto dir = test::freshTempDir("driver-artifact");
  ASSERT_EQ(driver::writeArtifact(dir, *r.artifact, {}, {{"extra.d", "x: y\n"}}), "");
  const CompiledPasses inMemory = r.artifact->passes();
  const CompiledPasses fromDisk = CompiledPasses::fromDirectory(dir);
  EXPECT_EQ(toJson(fromDisk.manifest).dump(), toJson(inMemory.manifest).dump());
  EXPECT_TRUE(fromDisk.files == inMemory.files);
  EXPECT_EQ(test::readFile(dir / "extra.d"), "x: y\n");
  // The manifest file itself names the directory just as well.
  EXPECT_TRUE(CompiledPasses::fromDirectory(dir / "manifest.json").files == inMemory.files);
  // Sibling: a missing .spv is an error that names the pass.
  const std::string spv = inMemory.manifest.passes.front().spirv;
  std::filesystem::remove(dir / spv);
  try {
    CompiledPasses::fromDirectory(dir);
    FAIL() << "expected an error for the missing " << spv;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("pass '" + inMemory.manifest.passes.front().name + "'"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("not found"), std::string::npos) << e.what();
  }
}

TEST(Driver, WriteArtifactKeepsOnlyTheRequestedKinds) {
  const driver::Result r = driver::compileSource(kPcf, "pcf_t.shadow");
  ASSERT_TRUE(r.ok) << r.log;
  const auto dir = test::freshTempDir("driver-kinds");
  ASSERT_EQ(driver::writeArtifact(dir, *r.artifact, {driver::OutputKind::Spirv}), "");
  int spv = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(e.path().extension(), ".spv") << e.path();
    ++spv;
  }
  EXPECT_GE(spv, 1);
  EXPECT_EQ(driver::outputKindOf("manifest.json"), driver::OutputKind::Manifest);
  EXPECT_EQ(driver::outputKindOf("shade.spv"), driver::OutputKind::Spirv);
  EXPECT_EQ(driver::outputKindOf("pcf_t_lookup.glsl"), driver::OutputKind::Glsl);
}

}  // namespace
}  // namespace shadowc

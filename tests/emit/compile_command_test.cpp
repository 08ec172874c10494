// `shadowc compile` end to end through the executable: flags, depfiles, errors, atomicity.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "emit/emit_support.h"

namespace shadowc {
namespace {

struct CliRun {
  int code;
  std::string out;
};

// stdout in the result, stderr into `stderrFile` (the tests read it when they need it).
CliRun shadowc(const std::string& args, const std::filesystem::path& stderrFile) {
  const test::CliResult r = test::runShadowc(args);
  std::ofstream(stderrFile, std::ios::binary) << r.err;
  return {r.code, r.out};
}

const std::string kSample = test::samplePath("vssm_adaptive").string();

TEST(CompileCommand, WritesTheOutputsAndAMakeDepfile) {
  const auto dir = test::freshTempDir("cli-out");
  const CliRun r = shadowc("compile " + kSample + " -o " + (dir / "o").string() + " -MD -O0", dir / "err");
  ASSERT_EQ(r.code, 0) << test::readFile(dir / "err");
  EXPECT_TRUE(std::filesystem::exists(dir / "o" / "manifest.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "o" / "shade.spv"));
  const std::string dep = test::readFile(dir / "o" / "vssm_adaptive.d");
  EXPECT_NE(dep.find("/o/manifest.json"), std::string::npos) << dep;
  EXPECT_NE(dep.find(": " + kSample), std::string::npos) << dep;
}

TEST(CompileCommand, DashMTNamesOnlyTheGivenTarget) {
  const auto dir = test::freshTempDir("cli-MT");
  const auto target = (dir / "o" / "vssm_adaptive.d").string();
  const CliRun r = shadowc("compile " + kSample + " -o " + (dir / "o").string() + " -MD -MT " + target, dir / "err");
  ASSERT_EQ(r.code, 0) << test::readFile(dir / "err");
  EXPECT_EQ(test::readFile(dir / "o" / "vssm_adaptive.d"), target + ": " + kSample + "\n");
  EXPECT_TRUE(std::filesystem::exists(dir / "o" / "shade.spv")) << "-MT changes the rule, not the outputs";
}

TEST(CompileCommand, DashMTWithoutATargetIsAnError) {
  const auto dir = test::freshTempDir("cli-MT-missing");
  const CliRun r = shadowc("compile " + kSample + " -o " + (dir / "o").string() + " -MD -MT", dir / "err");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(test::readFile(dir / "err").find("-MT needs a target"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "o"));
}

TEST(CompileCommand, DashMPrintsDependenciesAndWritesNothing) {
  const auto dir = test::freshTempDir("cli-M");
  const CliRun r = shadowc("compile " + kSample + " -o " + (dir / "o").string() + " -M --emit spirv", dir / "err");
  ASSERT_EQ(r.code, 0) << test::readFile(dir / "err");
  EXPECT_NE(r.out.find("/o/shade.spv"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(".glsl"), std::string::npos) << "--emit spirv lists no GLSL: " << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir / "o"));
}

TEST(CompileCommand, EmitSubsetWritesOnlyThoseKinds) {
  const auto dir = test::freshTempDir("cli-emit");
  const auto err = test::freshTempDir("cli-emit-err") / "err";
  ASSERT_EQ(shadowc("compile " + kSample + " -o " + dir.string() + " --emit manifest", err).code, 0);
  const auto files = test::readDir(dir);
  EXPECT_EQ(files.size(), 1u);
  EXPECT_TRUE(files.count("manifest.json"));
}

TEST(CompileCommand, PrintSpecAndRecipe) {
  const auto dir = test::freshTempDir("cli-print");
  const CliRun spec = shadowc("compile " + kSample + " --print-spec", dir / "err");
  ASSERT_EQ(spec.code, 0);
  EXPECT_EQ(nlohmann::json::parse(spec.out).at("name"), "vssm_adaptive");
  const CliRun recipe = shadowc("compile --print-recipe", dir / "err");
  ASSERT_EQ(recipe.code, 0);
  EXPECT_NE(recipe.out.find("--ccp\n"), std::string::npos);
}

TEST(CompileCommand, BadFilterPrintsDiagnosticsExitsOneAndWritesNothing) {
  const auto dir = test::freshTempDir("cli-bad");
  { std::ofstream(dir / "bad.shadow") << "filter bad {\n    kernel quadtre(height: 3)\n}\n"; }
  const CliRun r = shadowc("compile " + (dir / "bad.shadow").string() + " -o " + (dir / "o").string(), dir / "err");
  EXPECT_EQ(r.code, 1);
  const std::string err = test::readFile(dir / "err");
  EXPECT_NE(err.find("bad.shadow:2:"), std::string::npos) << err;
  EXPECT_NE(err.find("error"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o"));
}

TEST(CompileCommand, UnwritableOutputIsOneClearMessage) {
  const auto dir = test::freshTempDir("cli-unwritable");
  { std::ofstream(dir / "file") << "x"; }
  const CliRun r = shadowc("compile " + kSample + " -o " + (dir / "file" / "o").string(), dir / "err");
  EXPECT_EQ(r.code, 1);
  const std::string err = test::readFile(dir / "err");
  EXPECT_NE(err.find("shadowc: error: cannot create output directory"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

TEST(CompileCommand, UnknownFlagIsAnError) {
  const auto dir = test::freshTempDir("cli-flag");
  const CliRun r = shadowc("compile " + kSample + " -o " + (dir / "o").string() + " -O7", dir / "err");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(test::readFile(dir / "err").find("unknown argument '-O7'"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "o"));
}

}  // namespace
}  // namespace shadowc

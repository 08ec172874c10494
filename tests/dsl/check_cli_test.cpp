// `shadowc check` end to end: exit codes 0 / 1 / 2, -Werror, --print-spec.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "support/test_support.h"

namespace {
struct CliRun {
  int code;
  std::string out;  // stdout then stderr
};
CliRun run(const std::string& args) {
  const shadowc::test::CliResult r = shadowc::test::runShadowc("check " + args);
  return {r.code, r.out + r.err};
}
std::string path(const std::string& rel) { return (shadowc::test::sourceDir() / rel).string(); }
}  // namespace

TEST(CheckCli, CleanFileExitsZero) {
  const CliRun r = run(path("samples/filters/vssm_adaptive.shadow"));
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out, "");
}

TEST(CheckCli, ErrorsExitOne) {
  const CliRun r = run(path("tests/dsl/negative/several_errors.shadow"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("7 errors generated."), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[E0301]"), std::string::npos);
}

TEST(CheckCli, WarningsPassUnlessWerror) {
  const std::string file = path("samples/filters/sat_fp32_naive.shadow");
  const CliRun warn = run(file);
  EXPECT_EQ(warn.code, 0) << warn.out;
  EXPECT_NE(warn.out.find("warning:"), std::string::npos);
  const CliRun err = run("-Werror " + file);
  EXPECT_EQ(err.code, 1) << err.out;
  EXPECT_NE(err.out.find("error:"), std::string::npos);
}

TEST(CheckCli, UsageErrorsExitTwo) {
  EXPECT_EQ(run("").code, 2);
  EXPECT_EQ(run("-Wbogus " + path("samples/filters/esm.shadow")).code, 2);
}

TEST(CheckCli, PrintSpecIsJson) {
  const CliRun r = run("--print-spec " + path("samples/filters/layered_vsm_uniform.shadow"));
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("\"splits\": ["), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"name\": \"layered_vsm_uniform\""), std::string::npos);
}

TEST(CheckCli, SeveralFilesAnyErrorFails) {
  const CliRun r = run(path("samples/filters/esm.shadow") + " " + path("tests/dsl/negative/zero_layers.shadow"));
  EXPECT_EQ(r.code, 1);
}

// Helpers shared by every test folder: paths into the source tree, temp dirs, golden files.
#pragma once

#include <filesystem>
#include <string>

namespace shadowc::test {

// The build's paths, compiled into this one file (test_support.cpp) only: a test file that wrote
// them in through the generated headers would be compiled differently in every clone, and a
// compiler cache shared by clones (scripts/ccache.sh) could never hit it.
std::filesystem::path sourceDir();                           // the repository root
std::string shadowcBinary();                                 // the shadowc executable
std::string engineSampleBinary();                            // samples/engine's executable
std::string cxxCompiler();                                   // the project's C++ compiler
std::string buildDir();                                      // the build tree (to install from)
std::string cmakeCommand();                                  // the cmake that configured it
std::filesystem::path freshTempDir(const std::string& tag);  // empty, unique per test
std::string readFile(const std::filesystem::path& p);

// A filter text with its `light` line replaced by `light` (inserted after `{` when it has none).
std::string withLight(const std::string& text, const std::string& light);

// Golden files (glslang's Test/baseResults habit): compares `actual` with the file; when the
// environment has SHADOWC_UPDATE_GOLDEN=1 the file is rewritten instead and the check passes.
// Returns an empty string on match, else a short diff description.
std::string compareGolden(const std::filesystem::path& golden, const std::string& actual);

// Runs the shadowc executable (SHADOWC_BINARY) with `args` (shell words), stdout and stderr
// captured apart. `env` is prepended as shell assignments, e.g. "VK_ICD_FILENAMES=/none".
struct CliResult {
  int code = -1;  // exit status, -1 when killed by a signal
  std::string out, err;
};
CliResult runShadowc(const std::string& args, const std::string& env = "");

}  // namespace shadowc::test

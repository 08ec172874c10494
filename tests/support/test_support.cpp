#include "support/test_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "shadowc_source_dir.h"
#include "shadowc_test_paths.h"

namespace shadowc::test {

std::filesystem::path sourceDir() { return SHADOWC_SOURCE_DIR; }
std::string shadowcBinary() { return SHADOWC_BINARY; }
std::string engineSampleBinary() { return SHADOWC_ENGINE_BINARY; }
std::string cxxCompiler() { return SHADOWC_CXX_COMPILER; }
std::string buildDir() { return SHADOWC_BUILD_DIR; }
std::string cmakeCommand() { return SHADOWC_CMAKE_COMMAND; }

std::filesystem::path freshTempDir(const std::string& tag) {
  static std::atomic<int> counter{0};
  auto dir = std::filesystem::temp_directory_path() /
             ("shadowc-test-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string compareGolden(const std::filesystem::path& golden, const std::string& actual) {
  const char* update = std::getenv("SHADOWC_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    std::filesystem::create_directories(golden.parent_path());
    std::ofstream(golden, std::ios::binary) << actual;
    return {};
  }
  if (!std::filesystem::exists(golden))
    return "golden file " + golden.string() + " is missing (run with SHADOWC_UPDATE_GOLDEN=1 to create it)";
  const std::string expected = readFile(golden);
  if (expected == actual) return {};
  // First differing line, for a readable failure.
  std::istringstream a(actual), e(expected);
  std::string la, le;
  for (int line = 1;; ++line) {
    const bool ga = static_cast<bool>(std::getline(a, la)), ge = static_cast<bool>(std::getline(e, le));
    if (!ga && !ge) break;
    if (la != le || ga != ge)
      return golden.string() + ":" + std::to_string(line) + ": expected '" + (ge ? le : "<eof>") + "', got '" +
             (ga ? la : "<eof>") + "' (SHADOWC_UPDATE_GOLDEN=1 rewrites it after review)";
  }
  return golden.string() + ": differs";
}

CliResult runShadowc(const std::string& args, const std::string& env) {
  const auto errFile = freshTempDir("cli-stderr") / "stderr";
  const std::string cmd = env + (env.empty() ? "" : " ") + shadowcBinary() + " " + args + " 2>" + errFile.string();
  CliResult r;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
  const int status = ::pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = readFile(errFile);
  std::filesystem::remove_all(errFile.parent_path());
  return r;
}

std::string withLight(const std::string& text, const std::string& light) {
  const std::regex lightLine(R"(\n[ \t]*light[ \t][^\n#]*)");
  if (std::regex_search(text, lightLine))
    return std::regex_replace(text, lightLine, "\n    " + light, std::regex_constants::format_first_only);
  const size_t open = text.find('{');
  return text.substr(0, open + 1) + "\n    " + light + text.substr(open + 1);
}

}  // namespace shadowc::test

// The pipeline's layering: data flows load -> check -> plan -> emit -> backend, and only
// compiler/driver/ wires plan and emit together and calls the backend. The build holds the stage
// order (each stage target sees only its own and earlier stages' headers: planted_includes.cmake);
// these tests scan every folder's #include lines and the planner's string literals for what the
// build cannot see; each rule has a sibling that plants a violation and proves the scanner
// reports it.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <set>
#include <regex>
#include <string>
#include <vector>

#include "support/test_support.h"

namespace shadowc {
namespace {

namespace fs = std::filesystem;

struct SourceFile {
  std::string path;  // relative to the repository root, '/' separated
  std::string text;
};

// Every folder that holds the project's C++ (all of them: a new one must be added here, which
// EveryFolderWithCppIsScanned checks).
constexpr std::array kScannedFolders = {"compiler", "cli",     "runtime", "validation", "planning",
                                        "sweep",    "samples", "bench",   "tests",      "include"};

// Every C++ source and header of the project outside build trees; tests/architecture itself
// is left out (its planted violations are string literals, not includes, but keep it simple).
std::vector<SourceFile> projectSources() {
  std::vector<SourceFile> out;
  const fs::path root = test::sourceDir();
  for (const char* top : kScannedFolders) {
    if (!fs::exists(root / top)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
      const std::string rel = fs::relative(e.path(), root).generic_string();
      if (rel.starts_with("tests/architecture/")) continue;
      out.push_back({rel, test::readFile(e.path())});
    }
  }
  return out;
}

// The quoted #include targets, relative to compiler/ (bench/ spells "compiler/emit/...").
std::vector<std::string> includesOf(const std::string& text) {
  static const std::regex re(R"re(^\s*#\s*include\s*"([^"]+)")re", std::regex::multiline);
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it) {
    std::string inc = (*it)[1].str();
    if (inc.starts_with("compiler/")) inc.erase(0, 9);
    out.push_back(inc);
  }
  return out;
}

// String literals of C++ code, comments and #include lines skipped (good enough for our style:
// no raw strings in plan/).
std::vector<std::string> stringLiterals(const std::string& text) {
  std::vector<std::string> out;
  size_t i = 0;
  while (i < text.size()) {
    if (text.compare(i, 2, "//") == 0) {
      i = text.find('\n', i);
      if (i == std::string::npos) break;
    } else if (text.compare(i, 2, "/*") == 0) {
      i = text.find("*/", i);
      if (i == std::string::npos) break;
      i += 2;
    } else if (text[i] == '#' && (i == 0 || text[i - 1] == '\n')) {
      i = text.find('\n', i);  // preprocessor line (#include "...")
      if (i == std::string::npos) break;
    } else if (text[i] == '\'') {
      i = text.find('\'', i + (text.compare(i, 2, "'\\") == 0 ? 3 : 2)) + 1;
      if (i == 0) break;
    } else if (text[i] == '"') {
      std::string lit;
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\' && i + 1 < text.size()) lit += text[i++];
        lit += text[i];
      }
      out.push_back(lit);
      ++i;
    } else {
      ++i;
    }
  }
  return out;
}

// Rule 1: nothing under compiler/plan includes compiler/emit.
std::vector<std::string> planIncludesEmit(const std::vector<SourceFile>& files) {
  std::vector<std::string> bad;
  for (const SourceFile& f : files)
    if (f.path.starts_with("compiler/plan/"))
      for (const std::string& inc : includesOf(f.text))
        if (inc.starts_with("emit/")) bad.push_back(f.path + " includes " + inc);
  return bad;
}

// Rule 2: only compiler/driver/ includes both the planner and the emitter's entry point.
constexpr const char* kPlannerHeader = "plan/planner.h";
constexpr const char* kEmitterHeader = "emit/filter_emitter.h";
std::vector<std::string> wiresPlanAndEmit(const std::vector<SourceFile>& files) {
  std::vector<std::string> bad;
  for (const SourceFile& f : files) {
    if (f.path.starts_with("compiler/driver/")) continue;
    bool planner = false, emitter = false;
    for (const std::string& inc : includesOf(f.text)) {
      planner = planner || inc == kPlannerHeader;
      emitter = emitter || inc == kEmitterHeader;
    }
    if (planner && emitter) bad.push_back(f.path + " includes both " + kPlannerHeader + " and " + kEmitterHeader);
  }
  return bad;
}

// Rule 3: the planner writes no GLSL: no string literal under compiler/plan holds a
// preprocessor directive or GLSL declaration text.
std::vector<std::string> glslTextInPlan(const std::vector<SourceFile>& files) {
  static const std::regex glsl(
      R"(#\s*(define|line|version|if|extension)\b|\b[iu]?vec[234]\s*[\[(]|\b(float|int)\s*\[\s*\]|\blayout\s*\(|\bconst\s+(float|int|[iu]?vec[234])\b|\buniform\s+\w)");
  std::vector<std::string> bad;
  for (const SourceFile& f : files)
    if (f.path.starts_with("compiler/plan/"))
      for (const std::string& lit : stringLiterals(f.text))
        if (std::regex_search(lit, glsl)) bad.push_back(f.path + ": \"" + lit + "\"");
  return bad;
}

// Rule 4: inside compiler/, only driver/ includes the backend (emit renders text only).
std::vector<std::string> backendOutsideTheDriver(const std::vector<SourceFile>& files) {
  std::vector<std::string> bad;
  for (const SourceFile& f : files)
    if (f.path.starts_with("compiler/") && !f.path.starts_with("compiler/driver/") &&
        !f.path.starts_with("compiler/backend/"))
      for (const std::string& inc : includesOf(f.text))
        if (inc.starts_with("backend/")) bad.push_back(f.path + " includes " + inc);
  return bad;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += x + "\n";
  return s;
}

TEST(PipelineLayering, TheScanSeesTheSources) {
  const std::vector<SourceFile> files = projectSources();
  int plan = 0, driverOrEmit = 0;
  for (const SourceFile& f : files) {
    plan += f.path.starts_with("compiler/plan/");
    driverOrEmit += f.path.starts_with("compiler/emit/");
  }
  EXPECT_GE(plan, 8);  // planner, shade plan, pass graph, tables, ...
  EXPECT_GE(driverOrEmit, 8);
}

TEST(PipelineLayering, EveryFolderWithCppIsScanned) {
  const fs::path root = test::sourceDir();
  const std::set<std::string> scanned(kScannedFolders.begin(), kScannedFolders.end());
  for (const auto& top : fs::directory_iterator(root)) {
    const std::string name = top.path().filename().string();
    if (!top.is_directory() || name.starts_with(".") || name.starts_with("build") || scanned.count(name)) continue;
    for (const auto& e : fs::recursive_directory_iterator(top.path())) {
      const std::string ext = e.path().extension().string();
      EXPECT_FALSE(e.is_regular_file() && (ext == ".cpp" || ext == ".h"))
          << fs::relative(e.path(), root).generic_string() << " is C++ in a folder the layering scan skips";
    }
  }
}

TEST(PipelineLayering, OnlyTheDriverIncludesTheBackend) {
  EXPECT_EQ(joined(backendOutsideTheDriver(projectSources())), "");
}

TEST(PipelineLayering, APlantedBackendIncludeInEmitIsReported) {
  const std::vector<SourceFile> planted = {{"compiler/emit/shader_emitter.cpp", "#include \"backend/spirv_backend.h\"\n"},
                                           {"compiler/driver/driver.cpp", "#include \"backend/spirv_backend.h\"\n"},
                                           {"runtime/raster/r.cpp", "#include \"backend/spirv_backend.h\"\n"}};
  const std::vector<std::string> bad = backendOutsideTheDriver(planted);
  ASSERT_EQ(bad.size(), 1u) << joined(bad);
  EXPECT_EQ(bad[0], "compiler/emit/shader_emitter.cpp includes backend/spirv_backend.h");
}

TEST(PipelineLayering, NoPlanFileIncludesEmit) { EXPECT_EQ(joined(planIncludesEmit(projectSources())), ""); }

TEST(PipelineLayering, APlantedPlanToEmitIncludeIsReported) {
  const std::vector<SourceFile> planted = {
      {"compiler/plan/planner.cpp", "#include \"plan/planner.h\"\n  #include \"emit/template_codes.h\"\n"},
      {"compiler/emit/x.cpp", "#include \"plan/planner.h\"\n"}};
  const std::vector<std::string> bad = planIncludesEmit(planted);
  ASSERT_EQ(bad.size(), 1u);
  EXPECT_EQ(bad[0], "compiler/plan/planner.cpp includes emit/template_codes.h");
}

TEST(PipelineLayering, OnlyTheDriverWiresPlannerAndEmitter) {
  EXPECT_EQ(joined(wiresPlanAndEmit(projectSources())), "");
}

TEST(PipelineLayering, APlantedWiringOutsideTheDriverIsReported) {
  const std::string both = "#include \"emit/filter_emitter.h\"\n#include \"plan/planner.h\"\n";
  const std::vector<SourceFile> planted = {
      {"cli/cmd_compile.cpp", both},
      {"bench/b.cpp", "#include \"compiler/plan/planner.h\"\n#include \"compiler/emit/filter_emitter.h\"\n"},
      {"compiler/driver/driver.cpp", both},
      {"cli/cmd_check.cpp", "#include \"plan/planner.h\"\n"}};
  const std::vector<std::string> bad = wiresPlanAndEmit(planted);
  ASSERT_EQ(bad.size(), 2u) << joined(bad);
  EXPECT_TRUE(bad[0].starts_with("cli/cmd_compile.cpp")) << bad[0];
  EXPECT_TRUE(bad[1].starts_with("bench/b.cpp")) << bad[1];
}

TEST(PipelineLayering, ThePlannerWritesNoGlsl) { EXPECT_EQ(joined(glslTextInPlan(projectSources())), ""); }

TEST(PipelineLayering, PlantedGlslTextInThePlannerIsReported) {
  const std::vector<SourceFile> planted = {
      {"compiler/plan/a.cpp", "d.emplace_back(fmt::format(\"#define {} {}\", n, v));\n"},
      {"compiler/plan/b.cpp", "// a comment may say #define\nout += \"const vec2 taps[16] = vec2[](\";\n"},
      {"compiler/plan/c.cpp", "s += \"float[](\" + x;\n"},
      {"compiler/plan/d.cpp", "note = \"Poisson-disk taps in the unit disk\"; // const float ok in a comment\n"},
      {"compiler/emit/e.cpp", "out += \"#define X 1\";\n"}};
  const std::vector<std::string> bad = glslTextInPlan(planted);
  ASSERT_EQ(bad.size(), 3u) << joined(bad);
  EXPECT_TRUE(bad[0].starts_with("compiler/plan/a.cpp"));
  EXPECT_TRUE(bad[1].starts_with("compiler/plan/b.cpp"));
  EXPECT_TRUE(bad[2].starts_with("compiler/plan/c.cpp"));
}

}  // namespace
}  // namespace shadowc

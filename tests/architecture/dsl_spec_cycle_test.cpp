// The front end's layering: spec/ builds on dsl/, never the other way round, so no
// file under compiler/dsl includes a header of compiler/spec. The scanner reads the #include
// lines of the sources; its sibling proves it finds a planted include (and skips comments).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_support.h"

namespace fs = std::filesystem;

namespace {

// The targets of the #include directives of `text` that start with `prefix` (quoted or angled),
// "file:line: target" each. A directive starts its line (after blanks): "// #include" is no directive.
std::vector<std::string> includesOf(const std::string& text, const std::string& name, const std::string& prefix) {
  static const std::regex directive(R"(^\s*#\s*include\s*["<]([^">]+)[">])");
  std::vector<std::string> found;
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::smatch m;
    if (std::regex_search(line, m, directive) && m[1].str().rfind(prefix, 0) == 0)
      found.push_back(name + ":" + std::to_string(n) + ": " + m[1].str());
  }
  return found;
}

std::vector<std::string> includesUnder(const fs::path& dir, const std::string& prefix) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() || (ext != ".h" && ext != ".cpp" && ext != ".def")) continue;
    for (std::string& f : includesOf(shadowc::test::readFile(e.path()), e.path().string(), prefix))
      found.push_back(std::move(f));
  }
  return found;
}

TEST(Architecture, DslIncludesNothingOfSpec) {
  const fs::path dsl = shadowc::test::sourceDir() / "compiler/dsl";
  ASSERT_TRUE(fs::is_directory(dsl));
  const std::vector<std::string> bad = includesUnder(dsl, "spec/");
  std::string list;
  for (const std::string& b : bad) list += b + "\n";
  EXPECT_TRUE(bad.empty()) << "compiler/dsl must not include compiler/spec (spec/ builds on dsl/):\n" << list;
  // The scan saw real directives: dsl/ includes its own headers.
  EXPECT_FALSE(includesUnder(dsl, "dsl/").empty());
}

TEST(Architecture, ScannerFindsAPlantedInclude) {
  const std::string planted =
      "// comment\n#include <string>\n#include \"spec/load_filter.h\"\n  #  include <spec/check.h>\n"
      "// #include \"spec/commented_out.h\"\nconst char* s = \"#include spec/not_a_directive.h\";\n";
  const std::vector<std::string> found = includesOf(planted, "planted.h", "spec/");
  EXPECT_EQ(found, (std::vector<std::string>{"planted.h:3: spec/load_filter.h", "planted.h:4: spec/check.h"}));
  EXPECT_TRUE(includesOf("#include \"dsl/ast.h\"\n", "clean.h", "spec/").empty());
}

}  // namespace

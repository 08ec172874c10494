// Negative tests (Slang's habit): each tests/dsl/negative/NAME.shadow carries its directive
//   # expect: CODE at LINE:COL      the first diagnostic's stable code and location
//   # options: -Werror              (optional)
// and NAME.expected holds the full glslc-style output (SHADOWC_UPDATE_GOLDEN=1 rewrites it).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>

#include "spec/load_filter.h"
#include "support/test_support.h"

namespace fs = std::filesystem;
using namespace shadowc;

namespace {
fs::path negativeDir() { return test::sourceDir() / "tests/dsl/negative"; }

std::vector<std::string> negativeCases() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(negativeDir()))
    if (e.path().extension() == ".shadow") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

struct Directive {
  std::string code;
  int line = 0, column = 0;
  bool werror = false;
};

Directive readDirective(const std::string& text) {
  Directive d;
  std::smatch m;
  const std::string head = text.substr(0, text.find('\n', text.find('\n') + 1));
  if (std::regex_search(head, m, std::regex(R"(# expect: ([EWN]\d{4}) at (\d+):(\d+))")))
    d.code = m[1], d.line = std::stoi(m[2]), d.column = std::stoi(m[3]);
  d.werror = head.find("# options: -Werror") != std::string::npos;
  return d;
}

class Negative : public ::testing::TestWithParam<std::string> {};

TEST_P(Negative, ReportsExpectedCodeLocationAndText) {
  const std::string name = GetParam();
  const std::string text = test::readFile(negativeDir() / (name + ".shadow"));
  const Directive d = readDirective(text);
  ASSERT_FALSE(d.code.empty()) << name << ": missing '# expect: CODE at L:C' directive on line 1";
  LoadOptions options;
  options.warningsAsErrors = d.werror;
  const LoadResult r = loadFilterSource(text, name + ".shadow", options);
  ASSERT_FALSE(r.diagnostics.empty()) << name;
  const Diagnostic& first = r.diagnostics.front();
  EXPECT_EQ(first.code, d.code) << formatDiagnostics(r);
  EXPECT_EQ(first.location.line, d.line) << formatDiagnostics(r);
  EXPECT_EQ(first.location.column, d.column) << formatDiagnostics(r);
  if (d.code[0] == 'E' || d.werror) {
    EXPECT_GT(r.errorCount(), 0);
    EXPECT_FALSE(r.spec.has_value()) << "a file with errors must not produce a spec";
  } else {
    EXPECT_EQ(r.errorCount(), 0) << formatDiagnostics(r);
    EXPECT_GT(r.warningCount(), 0);
    EXPECT_TRUE(r.spec.has_value()) << "warnings alone must still produce a spec";
  }
  // Never more than the cap, whatever the input.
  EXPECT_LE(r.errorCount(), 21);
  const std::string diff = test::compareGolden(negativeDir() / (name + ".expected"), formatDiagnostics(r));
  EXPECT_TRUE(diff.empty()) << diff;
}

INSTANTIATE_TEST_SUITE_P(Files, Negative, ::testing::ValuesIn(negativeCases()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(NegativeSuite, HasAtLeast45Cases) { EXPECT_GE(negativeCases().size(), 45u); }

// The directive check itself can fail: a wrong expectation must not match.
TEST(NegativeSuite, WrongDirectiveWouldFail) {
  const std::string text = test::readFile(negativeDir() / "unknown_setting.shadow");
  const LoadResult r = loadFilterSource(text, "unknown_setting.shadow");
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics.front().code, "E0302");
  EXPECT_NE(r.diagnostics.front().location.column, 1);
}

TEST(NegativeSuite, SuggestionsForTypos) {
  auto suggestionOf = [](const std::string& name) {
    const LoadResult r = loadFilterSource(test::readFile(negativeDir() / (name + ".shadow")), name);
    return r.diagnostics.empty() ? std::string() : r.diagnostics.front().suggestion;
  };
  EXPECT_EQ(suggestionOf("misspelled_kernel"), "did you mean 'quadtree'?");
  EXPECT_EQ(suggestionOf("misspelled_option"), "did you mean 'height'?");
  EXPECT_EQ(suggestionOf("misspelled_enum_value"), "did you mean 'unrolled'?");
  EXPECT_EQ(suggestionOf("unknown_setting"), "did you mean 'kernel'?");
  EXPECT_EQ(suggestionOf("missing_filter_keyword"), "did you mean 'filter'?");
  EXPECT_EQ(suggestionOf("unknown_setting_no_suggestion"), "");  // 'colour' is no typo of anything
}

TEST(NegativeSuite, SeveralErrorsAllReported) {
  const LoadResult r = loadFilterSource(test::readFile(negativeDir() / "several_errors.shadow"), "several_errors");
  std::vector<std::string> codes;
  for (const Diagnostic& d : r.diagnostics) codes.push_back(d.code);
  const std::vector<std::string> expected = {"E0301", "E0304", "E0302", "E0304", "E0302", "E0310", "E0302"};
  EXPECT_EQ(codes, expected) << formatDiagnostics(r);
  EXPECT_NE(formatDiagnostics(r).find("7 errors generated."), std::string::npos);
}

TEST(NegativeSuite, TooManyErrorsIsCapped) {
  const LoadResult r = loadFilterSource(test::readFile(negativeDir() / "too_many_errors.shadow"), "t");
  EXPECT_EQ(r.errorCount(), 21);  // 20 reported + E0003
  EXPECT_EQ(r.diagnostics.back().code, "E0003");
}

}  // namespace

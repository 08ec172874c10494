// Lexer and parser units: token kinds, numbers, sizes, comments, line starts, AST shape.
#include "dsl/lexer.h"

#include <gtest/gtest.h>

#include <set>

#include "dsl/diagnostics.h"
#include "dsl/parser.h"
#include "spec/load_filter.h"

using namespace shadowc;
using namespace shadowc::dsl;

namespace {
struct Lexed {
  std::vector<Diagnostic> diags;
  std::vector<Token> tokens;
};
Lexed lexText(std::string_view text) {
  Lexed l;
  DiagnosticSink sink(l.diags, "t");
  l.tokens = lex(text, sink);
  return l;
}
}  // namespace

TEST(Lexer, KindsAndPositions) {
  const Lexed l = lexText("filter f {\n  kernel quadtree(height: 3, x: 2x2) # comment\n}");
  ASSERT_TRUE(l.diags.empty());
  std::vector<TokenKind> kinds;
  for (const Token& t : l.tokens) kinds.push_back(t.kind);
  using K = TokenKind;
  const std::vector<K> expected = {K::Name,   K::Name,  K::LBrace, K::Name,  K::Name, K::LParen, K::Name,   K::Colon,
                                   K::Number, K::Comma, K::Name,   K::Colon, K::Size, K::RParen, K::RBrace, K::End};
  EXPECT_EQ(kinds, expected);
  EXPECT_EQ(l.tokens[3].text, "kernel");
  EXPECT_EQ(l.tokens[3].line, 2);
  EXPECT_EQ(l.tokens[3].column, 3);
  EXPECT_TRUE(l.tokens[3].lineStart);
  EXPECT_FALSE(l.tokens[4].lineStart);
  EXPECT_EQ(l.tokens[12].width, 2);
  EXPECT_EQ(l.tokens[12].height, 2);
  EXPECT_TRUE(l.tokens[14].lineStart);
}

TEST(Lexer, Numbers) {
  const Lexed l = lexText("1 0.04 1e-5 -0.5 +2 .5 12E+2");
  ASSERT_TRUE(l.diags.empty());
  ASSERT_EQ(l.tokens.size(), 8u);
  EXPECT_DOUBLE_EQ(l.tokens[0].number, 1);
  EXPECT_TRUE(l.tokens[0].integer);
  EXPECT_DOUBLE_EQ(l.tokens[1].number, 0.04);
  EXPECT_FALSE(l.tokens[1].integer);
  EXPECT_DOUBLE_EQ(l.tokens[2].number, 1e-5);
  EXPECT_DOUBLE_EQ(l.tokens[3].number, -0.5);
  EXPECT_DOUBLE_EQ(l.tokens[4].number, 2);
  EXPECT_DOUBLE_EQ(l.tokens[5].number, 0.5);
  EXPECT_DOUBLE_EQ(l.tokens[6].number, 1200);
}

TEST(Lexer, MalformedTokensAreOneErrorEach) {
  const Lexed l = lexText("1.2.3 3x 4q $");
  ASSERT_EQ(l.diags.size(), 4u);
  EXPECT_EQ(l.diags[0].code, "E0103");
  EXPECT_EQ(l.diags[1].code, "E0105");
  EXPECT_EQ(l.diags[2].code, "E0103");
  EXPECT_EQ(l.diags[3].code, "E0101");
  EXPECT_EQ(l.diags[3].location.column, 13);
}

TEST(Lexer, CommentsAndCrlf) {
  const Lexed l = lexText("# only a comment\r\nfilter # trailing\r\n");
  ASSERT_TRUE(l.diags.empty());
  ASSERT_EQ(l.tokens.size(), 2u);
  EXPECT_EQ(l.tokens[0].line, 2);
  EXPECT_EQ(l.tokens[0].column, 1);
}

TEST(Lexer, Utf8InCommentsIsFineInvalidIsNot) {
  EXPECT_TRUE(lexText("# Schatten \xc3\xa4\xc3\xb6 \xe2\x80\x94 ok\nfilter").diags.empty());
  const Lexed bad = lexText("filter\n  \xc3\x28");
  ASSERT_EQ(bad.diags.size(), 1u);
  EXPECT_EQ(bad.diags[0].code, "E0102");
  EXPECT_EQ(bad.diags[0].location.line, 2);
  EXPECT_EQ(bad.diags[0].location.column, 3);
}

TEST(Parser, NestedArgumentsBuildTheAst) {
  std::vector<Diagnostic> diags;
  DiagnosticSink sink(diags, "t");
  const std::string text =
      "filter f {\n  blocker moments(uniform(m: 5))\n  moments linear(layers: 3,\n    split: explicit(0, 0.2, 0.5, "
      "1))\n"
      "  depth\n}\n";
  const File file = parse(lex(text, sink), sink);
  ASSERT_TRUE(diags.empty());
  ASSERT_TRUE(file.hasFilter);
  EXPECT_EQ(file.filter.name, "f");
  ASSERT_EQ(file.filter.settings.size(), 3u);
  const Setting& blocker = file.filter.settings[0];
  EXPECT_EQ(blocker.keyword, "blocker");
  ASSERT_EQ(blocker.value.arguments.size(), 1u);
  const Value& uniform = blocker.value.arguments[0].value;
  EXPECT_EQ(uniform.text, "uniform");
  ASSERT_EQ(uniform.arguments.size(), 1u);
  EXPECT_EQ(uniform.arguments[0].name, "m");
  EXPECT_DOUBLE_EQ(uniform.arguments[0].value.number, 5);
  const Value& split = file.filter.settings[1].value.arguments[1].value;
  EXPECT_EQ(split.text, "explicit");
  EXPECT_EQ(split.arguments.size(), 4u);
  EXPECT_FALSE(file.filter.settings[2].hasValue);
}

TEST(Parser, RecoversAtTheNextLine) {
  std::vector<Diagnostic> diags;
  DiagnosticSink sink(diags, "t");
  const File file =
      parse(lex("filter f {\n  kernel quadtree(height: 3\n  depth\n  bias ) x\n  mips on\n}\n", sink), sink);
  ASSERT_EQ(diags.size(), 2u);
  EXPECT_EQ(diags[0].code, "E0206");
  EXPECT_EQ(diags[1].code, "E0211");
  ASSERT_EQ(file.filter.settings.size(), 2u);  // depth, mips: the broken ones are dropped
  EXPECT_EQ(file.filter.settings[0].keyword, "depth");
  EXPECT_EQ(file.filter.settings[1].keyword, "mips");
}

TEST(Diagnostics, EditDistanceAndSuggestions) {
  EXPECT_EQ(support::editDistance("quadtre", "quadtree"), 1u);
  EXPECT_EQ(support::editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(support::closestMatch("quadtre", {"fixed", "penumbra", "uniform", "quadtree"}), "quadtree");
  EXPECT_EQ(support::closestMatch("xyz", {"fixed", "penumbra"}), "");
  // One suggester for the language and the scene loader: case-insensitive, at most |word|/3 edits.
  EXPECT_EQ(support::closestMatch("Quadtree", {"uniform", "quadtree"}), "quadtree");
  EXPECT_EQ(support::closestMatch("sise", std::vector<std::string>{"type", "size"}), "size");
  EXPECT_EQ(support::closestMatch("pxnxmbra", {"penumbra"}), "penumbra");  // 2 edits of 8: a typo
  EXPECT_EQ(support::closestMatch("pxnxmxra", {"penumbra"}), "");          // 3 edits of 8: another word
}

TEST(Diagnostics, CodesAreUniqueAndGrouped) {
  std::set<std::string> seen;
  for (int i = 0; i <= static_cast<int>(DiagId::firstSetHere); ++i) {
    const DiagInfo& info = diagInfo(static_cast<DiagId>(i));
    EXPECT_TRUE(seen.insert(info.code).second) << info.code;
    const char group = info.code[0];
    if (info.severity == Severity::Error) {
      EXPECT_EQ(group, 'E') << info.code;
    }
    if (info.severity == Severity::Warning) {
      EXPECT_EQ(group, 'W') << info.code;
    }
  }
}

TEST(Diagnostics, GlslcFormat) {
  LoadResult r;
  r.source = "filter f {\n\tkernel quadtre\n}\n";
  r.diagnostics.push_back(
      Diagnostic{Severity::Error, "E0302", {"f.shadow", 2, 9}, 7, "unknown value", "did you mean 'quadtree'?"});
  r.diagnostics.push_back(Diagnostic{Severity::Warning, "W0502", {"f.shadow", 1, 1}, 6, "w", ""});
  EXPECT_EQ(formatDiagnostics(r),
            "f.shadow:2:9: error: unknown value [E0302]\n"
            "\tkernel quadtre\n"
            "\t       ^~~~~~~\n"
            "note: did you mean 'quadtree'?\n"
            "f.shadow:1:1: warning: w [W0502]\n"
            "filter f {\n"
            "^~~~~~\n"
            "1 warning and 1 error generated.\n");
}

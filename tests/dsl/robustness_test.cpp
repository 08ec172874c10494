// Hostile input: empty, binary, huge, deeply nested. Each must end quickly with a bounded,
// small number of errors (never a crash, never thousands of lines).
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "dsl/diagnostics.h"
#include "spec/load_filter.h"
#include "support/test_support.h"

using namespace shadowc;

TEST(Robustness, EmptyFileIsOneError) {
  const LoadResult r = loadFilterSource("", "empty.shadow");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "E0210");
  EXPECT_EQ(r.diagnostics[0].location.line, 1);
  EXPECT_EQ(r.diagnostics[0].location.column, 1);
  EXPECT_FALSE(r.spec);
}

TEST(Robustness, RandomBinaryIsOneError) {
  std::mt19937 rng(1234);
  std::string junk(64 * 1024, '\0');
  for (char& c : junk) c = static_cast<char>(rng() & 0xFF);
  junk[100] = '\0';  // make sure there is a NUL
  const LoadResult r = loadFilterSource(junk, "junk.bin");
  ASSERT_EQ(r.diagnostics.size(), 1u) << formatDiagnostics(r);
  EXPECT_EQ(r.diagnostics[0].code, "E0102");
  // The snippet must not echo raw control bytes to the terminal.
  const std::string text = formatDiagnostics(r);
  EXPECT_EQ(text.find('\0'), std::string::npos);
}

TEST(Robustness, TenMegabyteFileIsRejectedBounded) {
  const auto dir = test::freshTempDir("dsl-10mb");
  const auto path = dir / "huge.shadow";
  {
    std::ofstream out(path, std::ios::binary);
    const std::string line = "    kernel quadtree(height: 3)   # filler line to make the file large\n";
    out << "filter huge {\n";
    for (size_t written = 0; written < 10u * 1024 * 1024; written += line.size()) out << line;
    out << "}\n";
  }
  const LoadResult r = loadFilterFile(path.string());
  ASSERT_EQ(r.errorCount(), 1) << formatDiagnostics(r);
  EXPECT_EQ(r.diagnostics[0].code, "E0002");
}

TEST(Robustness, LargeJunkTextUnderTheCapIsBounded) {
  // 900 KB of junk tokens: the lexer and parser run over all of it; the report stays capped.
  std::string text = "filter junk {\n";
  while (text.size() < 900 * 1024) text += "  ;;; @@ kernel quadtree(height: 3 ,, ) ) ( 1.2.3 3x }\n";
  const LoadResult r = loadFilterSource(text, "junk.shadow");
  EXPECT_LE(r.errorCount(), dsl::kMaxErrors + 1);
  EXPECT_GT(r.errorCount(), 0);
  EXPECT_EQ(r.diagnostics.back().code, "E0003");
}

TEST(Robustness, DeepNestingDoesNotRecurse) {
  std::string text = "filter deep {\n  kernel ";
  for (int i = 0; i < 200000; ++i) text += "a(";
  text += "1";
  for (int i = 0; i < 200000; ++i) text += ")";
  text += "\n}\n";
  const LoadResult r = loadFilterSource(text, "deep.shadow");
  ASSERT_EQ(r.errorCount(), 1) << formatDiagnostics(r);
  EXPECT_EQ(r.diagnostics[0].code, "E0207");
}

TEST(Robustness, LongLineSnippetIsWindowed) {
  std::string text = "filter f {\n  depth " + std::string(5000, ' ') + "@\n}\n";
  const LoadResult r = loadFilterSource(text, "long.shadow");
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].code, "E0101");
  EXPECT_LT(formatDiagnostics(r).size(), 800u);
}

TEST(Robustness, MissingFileIsOneError) {
  const LoadResult r = loadFilterFile("/nonexistent/dir/x.shadow");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "E0001");
  EXPECT_EQ(formatDiagnostics(r),
            "/nonexistent/dir/x.shadow: error: cannot read file: no such file or not readable [E0001]\n"
            "1 error generated.\n");
}

TEST(Robustness, DirectoryIsNotAFile) {
  const LoadResult r = loadFilterFile(test::freshTempDir("dsl-dir").string());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "E0001");
}

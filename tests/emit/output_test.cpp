// Output side of the emitter: atomic writes, the content hash, make dependency rules.
#include <gtest/gtest.h>

#include <fstream>

#include "emit/content_hash.h"
#include "emit/depfile.h"
#include "emit/output_writer.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

TEST(OutputWriter, WritesEveryFileAndLeavesNoTempFiles) {
  const auto dir = test::freshTempDir("writer") / "nested" / "out";
  ASSERT_EQ(writeFilesAtomically(dir, {{"a.glsl", "A"}, {"b.spv", std::string("\0\1\2", 3)}}), "");
  EXPECT_EQ(test::readFile(dir / "a.glsl"), "A");
  EXPECT_EQ(test::readFile(dir / "b.spv"), std::string("\0\1\2", 3));
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  EXPECT_EQ(n, 2);
}

TEST(OutputWriter, ReplacesExistingFiles) {
  const auto dir = test::freshTempDir("writer-replace");
  { std::ofstream(dir / "a.glsl") << "old contents, longer than the new"; }
  ASSERT_EQ(writeFilesAtomically(dir, {{"a.glsl", "new"}}), "");
  EXPECT_EQ(test::readFile(dir / "a.glsl"), "new");
}

TEST(OutputWriter, UnwritableDirectoryIsOneClearErrorAndWritesNothing) {
  const auto base = test::freshTempDir("writer-bad");
  { std::ofstream(base / "file") << "x"; }  // a regular file where a directory is needed
  const std::string err = writeFilesAtomically(base / "file" / "out", {{"a.glsl", "A"}});
  EXPECT_NE(err.find("cannot create output directory"), std::string::npos) << err;
  EXPECT_EQ(err.find('\n'), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(base / "file" / "out"));
}

TEST(ContentHash, NamesTheAlgorithmAndIgnoresTheManifest) {
  const std::string h = contentHash({{"a.glsl", "A"}, {"manifest.json", "{}"}});
  EXPECT_EQ(h.rfind("xxh3-128:", 0), 0u);
  EXPECT_EQ(h.size(), 9u + 32u);
  EXPECT_EQ(h, contentHash({{"a.glsl", "A"}, {"manifest.json", "{\"other\": 1}"}}));
}

TEST(ContentHash, AnyChangeOfNameOrBytesChangesIt) {
  const std::string h = contentHash({{"a.glsl", "A"}, {"b.spv", "B"}});
  EXPECT_EQ(h, contentHash({{"b.spv", "B"}, {"a.glsl", "A"}}));  // order-independent
  EXPECT_NE(h, contentHash({{"a.glsl", "A"}, {"b.spv", "C"}}));
  EXPECT_NE(h, contentHash({{"a.glsl", "A"}, {"c.spv", "B"}}));
  EXPECT_NE(h, contentHash({{"a.glsl", "AB"}, {"b.spv", ""}}));  // sizes delimit the files
}

TEST(Depfile, OutputsDependOnTheInputWithMakeEscapes) {
  EXPECT_EQ(makeDependencyRule({"out/a.spv", "out/b c.glsl"}, "my filter.shadow"),
            "out/a.spv out/b\\ c.glsl: my\\ filter.shadow\n");
}

}  // namespace
}  // namespace shadowc

#include "emit/glsl_tidy.h"

#include <gtest/gtest.h>

namespace shadowc {
namespace {

TEST(GlslTidy, BlankRunsBecomeLineDirectivesWithTheRightNumber) {
  // Lines: 1 a, 2-4 blank, 5 b, 6 blank, 7 c
  const std::string in = "a\n\n\n\nb\n\nc\n";
  EXPECT_EQ(tidyPreprocessed(in), "a\n#line 5\nb\n\nc\n");
}

TEST(GlslTidy, LineDirectivesResetTheCount) {
  const std::string in = "#line 10 \"x.glsl\"\na\n\n\nb\n\n\n";
  EXPECT_EQ(tidyPreprocessed(in), "#line 10 \"x.glsl\"\na\n#line 13\nb\n");
}

TEST(GlslTidy, ARunBeforeALineDirectiveIsDropped) {
  EXPECT_EQ(tidyPreprocessed("a\n\n\n#line 40\nb\n"), "a\n#line 40\nb\n");
}

TEST(GlslTidy, StripLineDirectivesRemovesThemAndCollapsesBlanks) {
  EXPECT_EQ(stripLineDirectives("#line 1 \"f\"\na\n\n\n#line 9\nb  \n"), "a\n\nb\n");
}

}  // namespace
}  // namespace shadowc

namespace shadowc {
namespace {

TEST(GlslTidy, ADirectiveOverriddenByTheNextIsDropped) {
  EXPECT_EQ(tidyPreprocessed("a\n#line 4\n#line 1 \"f.glsl\"\nb\n"), "a\n#line 1 \"f.glsl\"\nb\n");
}

}  // namespace
}  // namespace shadowc

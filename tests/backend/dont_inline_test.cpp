// DontInline marking (backend/dont_inline.h): a kept function survives the -O recipe's
// exhaustive inliner as a call; the sibling without the mark shows the inliner removes it.
#include "backend/dont_inline.h"

#include <gtest/gtest.h>

#include <string>

#include "backend/spirv_backend.h"

namespace shadowc {
namespace {

constexpr const char* kShader = R"(#version 460
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, r32f) uniform image2D img;
float node(ivec3 n) { return imageLoad(img, n.xy).r * float(n.z); }
void main() {
  float s = node(ivec3(0, 0, 1)) + node(ivec3(1, 0, 2)) + node(ivec3(0, 1, 4));
  imageStore(img, ivec2(0), vec4(s));
}
)";

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(DontInline, KeptFunctionStaysACallAfterTheRecipe) {
  BackendOptions o;
  o.keepCalls = {"node"};
  const SpirvResult r = compileGlsl(kShader, ShaderStage::Compute, "keep.comp", {}, o);
  ASSERT_TRUE(r.ok) << r.log;
  const std::string dis = disassembleSpirv(r.words);
  EXPECT_EQ(count(dis, "OpFunctionCall"), 3) << dis;
  EXPECT_NE(dis.find("DontInline"), std::string::npos);
}

TEST(DontInline, WithoutTheMarkTheRecipeInlinesEverything) {
  const SpirvResult r = compileGlsl(kShader, ShaderStage::Compute, "inline.comp", {}, BackendOptions{});
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_EQ(count(disassembleSpirv(r.words), "OpFunctionCall"), 0);
}

TEST(DontInline, MarksOnlyTheNamedFunctionAndNotAPrefixOfItsName) {
  const SpirvResult r = compileGlsl(kShader, ShaderStage::Compute, "raw.comp", {}, BackendOptions{false, true, {}});
  ASSERT_TRUE(r.ok) << r.log;
  std::vector<uint32_t> words = r.words;
  EXPECT_EQ(markDontInline(words, {"nod"}), 0);  // "nod(" is no function; "node(" is
  EXPECT_EQ(markDontInline(words, {"node"}), 1);
  EXPECT_EQ(validateSpirv(words), "");
}

}  // namespace
}  // namespace shadowc

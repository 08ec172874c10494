// The in-process backend: glslang -> spirv-opt recipe -> spirv-val, and the preprocessor the
// emitter relies on to fold constants and strip unused code.
#include "backend/spirv_backend.h"

#include <gtest/gtest.h>

namespace shadowc {
namespace {

constexpr const char* kShader = R"(#version 460
#define N 4
layout(local_size_x = 8) in;
layout(set = 0, binding = 0, r32f) writeonly uniform image2D img;
void main() {
  float s = 0.0;
  for (int i = 0; i < N; ++i) s += float(i);
#if N > 8
  s = -1.0;
#endif
  imageStore(img, ivec2(gl_GlobalInvocationID.xy), vec4(s));
}
)";

TEST(Backend, CompilesAndValidatesAtBothLevels) {
  for (bool optimize : {true, false}) {
    const SpirvResult r = compileGlsl(kShader, ShaderStage::Compute, "t.comp", {}, {optimize, true});
    ASSERT_TRUE(r.ok) << r.log;
    EXPECT_EQ(validateSpirv(r.words), "");
    EXPECT_EQ(r.words.at(0), 0x07230203u);  // SPIR-V magic
  }
}

// The recipe's --loop-unroll only unrolls loops marked [[unroll]] (spirv-opt semantics), so the
// check is on what it does for every shader: locals promoted to SSA, a smaller module.
TEST(Backend, TheRecipeRemovesFunctionLocalLoadsAndShrinksTheModule) {
  const SpirvResult o = compileGlsl(kShader, ShaderStage::Compute, "t.comp", {}, {true, true});
  const SpirvResult o0 = compileGlsl(kShader, ShaderStage::Compute, "t.comp", {}, {false, true});
  ASSERT_TRUE(o.ok && o0.ok);
  EXPECT_NE(disassembleSpirv(o0.words).find("OpVariable %_ptr_Function"), std::string::npos);
  EXPECT_EQ(disassembleSpirv(o.words).find("OpVariable %_ptr_Function"), std::string::npos);
  EXPECT_LT(o.words.size(), o0.words.size());
}

TEST(Backend, ErrorsNameFileAndLine) {
  const SpirvResult r = compileGlsl("#version 460\nlayout(local_size_x = 1) in;\nvoid main() { undefined_x = 1; }\n",
                                    ShaderStage::Compute, "bad.comp", {}, {});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.log.find("bad.comp:3"), std::string::npos) << r.log;
}

TEST(Backend, PreprocessorFoldsDefinesAndDropsDeadBranches) {
  std::string out;
  const SpirvResult r = preprocessGlsl(kShader, ShaderStage::Compute, "t.comp", {}, out);
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_EQ(out.find("#define"), std::string::npos);
  EXPECT_EQ(out.find("-1.0"), std::string::npos);
  EXPECT_NE(out.find("i < 4"), std::string::npos);
}

TEST(Backend, IncludesResolveThroughTheResolver) {
  const std::string src =
      "#version 460\n#extension GL_GOOGLE_include_directive : require\n#include \"k.glsl\"\n"
      "layout(local_size_x = 1) in;\nlayout(set=0, binding=0, r32f) writeonly uniform image2D o;\n"
      "void main() { imageStore(o, ivec2(0), vec4(K)); }\n";
  const IncludeResolver resolver = [](const std::string& n) -> std::optional<std::string> {
    if (n == "k.glsl") return std::string("const float K = 2.0;\n");
    return std::nullopt;
  };
  EXPECT_TRUE(compileGlsl(src, ShaderStage::Compute, "i.comp", resolver, {}).ok);
  EXPECT_FALSE(compileGlsl(src, ShaderStage::Compute, "i.comp", {}, {}).ok);  // sibling: unresolved
}

TEST(Backend, ValidatorRejectsGarbage) {
  EXPECT_NE(validateSpirv({0x07230203u, 0x00010500u, 0u, 1u}), "");
  EXPECT_NE(validateSpirv({}), "");
}

TEST(Backend, RecipeIsNonEmptySpirvOptFlags) {
  ASSERT_FALSE(optimizationRecipe().empty());
  for (const auto& f : optimizationRecipe()) EXPECT_EQ(f.rfind("--", 0), 0u) << f;
}

}  // namespace
}  // namespace shadowc

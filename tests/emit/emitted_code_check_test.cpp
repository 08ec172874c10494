// CHECK-style assertions on emitted code, where a whole golden file would be brittle: each
// states one property of specialization (absent features, unrolled loops, folded constants).
#include <gtest/gtest.h>

#include "emit/emit_support.h"
#include "emit/filter_emitter.h"  // lookupFileName
#include "plan/test_specs.h"

namespace shadowc {
namespace {

std::string file(const driver::Result& r, const std::string& name) { return test::artifactFile(r, name); }

// The body of `void name(...) { ... }` in GLSL text (brace matching).
std::string functionBody(const std::string& glsl, const std::string& name) {
  const size_t at = glsl.find("void " + name + "(");
  if (at == std::string::npos) return {};
  size_t i = glsl.find('{', at), depth = 0;
  const size_t start = i;
  for (; i < glsl.size(); ++i) {
    if (glsl[i] == '{') ++depth;
    if (glsl[i] == '}' && --depth == 0) break;
  }
  return glsl.substr(start, i - start + 1);
}

FilterSpec vssmTraversal(QuadtreeTraversal t) {
  FilterSpec s = test::vssmInt32Spec();
  s.earlyOutMinMax = false;
  s.kernel.traversal = t;
  return s;
}

TEST(EmittedCode, DepthPcfShadeHasNoMomentsOrSatCode) {
  const driver::Result r = driver::compileSpec(test::pcfSpec());
  ASSERT_TRUE(r.ok) << r.log;
  const std::string shade = file(r, "shade.glsl");
  ASSERT_FALSE(shade.empty());
  for (const char* absent :
       {"usampler2DArray", "sampler2DArray", "summedArea", "chebyshev", "binding = 5", "binding = 6", "binding = 7"})
    EXPECT_EQ(shade.find(absent), std::string::npos) << "PCF shade must not contain '" << absent << "'";
  EXPECT_NE(shade.find("binding = 4"), std::string::npos);  // shadow_depth
}

TEST(EmittedCode, VssmShadeReadsTheIntegerSat) {
  const driver::Result r = driver::compileSpec(test::vssmInt32Spec());
  ASSERT_TRUE(r.ok) << r.log;
  EXPECT_NE(file(r, "shade.glsl").find("usampler2DArray"), std::string::npos);
}

TEST(EmittedCode, UnrolledQuadtreeTraversalHasNoLoop) {
  const driver::Result r = driver::compileSpec(vssmTraversal(QuadtreeTraversal::Unrolled));
  ASSERT_TRUE(r.ok) << r.log;
  const std::string shade = file(r, "shade.glsl");
  const std::string body = functionBody(shade, "shadowc_qtUnrolledKernel");
  ASSERT_FALSE(body.empty()) << "unrolled traversal function missing";
  EXPECT_EQ(body.find("for"), std::string::npos);
  EXPECT_EQ(body.find("while"), std::string::npos);
  EXPECT_EQ(shade.find("shadowc_qtNext"), std::string::npos) << "no Next table when unrolled";
}

// The computed walk derives Next/Child from the node in a loop and carries no table: neither a
// const array (lavapipe lowers a dynamically indexed one to an if-ladder per read) nor the buffer.
TEST(EmittedCode, ComputedQuadtreeTraversalIsALoopWithoutTables) {
  const driver::Result r = driver::compileSpec(vssmTraversal(QuadtreeTraversal::Computed));
  ASSERT_TRUE(r.ok) << r.log;
  const std::string shade = file(r, "shade.glsl");
  EXPECT_NE(shade.find(": shadowc_qtNextNode(n);"), std::string::npos);  // Next, computed from the node
  EXPECT_EQ(shade.find("shadowc_qtTable"), std::string::npos);
  EXPECT_EQ(shade.find("const ivec"), std::string::npos);
  EXPECT_EQ(shade.find("shadowc_qtUnrolledKernel"), std::string::npos);
  EXPECT_TRUE(r.artifact->manifest.buffers.empty());
}

// Sibling: the table walk reads Child and Next from the read-only buffer (Algorithm 2), and
// computes neither.
TEST(EmittedCode, TableQuadtreeTraversalReadsChildAndNextFromTheBuffer) {
  const driver::Result r = driver::compileSpec(vssmTraversal(QuadtreeTraversal::Table));
  ASSERT_TRUE(r.ok) << r.log;
  const std::string shade = file(r, "shade.glsl");
  EXPECT_NE(shade.find("readonly buffer shadowc_QuadtreeTable"), std::string::npos);
  EXPECT_NE(shade.find("ivec4 t = shadowc_qtTable[i];"), std::string::npos);
  EXPECT_NE(shade.find("? t . z : t . w;"), std::string::npos);  // Child : Next
  EXPECT_EQ(shade.find("shadowc_qtNextNode"), std::string::npos);
  EXPECT_EQ(shade.find("const ivec"), std::string::npos);
  ASSERT_EQ(r.artifact->manifest.buffers.size(), 1u);
}

TEST(EmittedCode, EmittedGlslIsPreprocessed) {
  for (const FilterSpec& spec : {test::vssmInt32Spec(), test::layeredEvsmSpec(), test::blurMipSpec()}) {
    const driver::Result r = driver::compileSpec(spec);
    ASSERT_TRUE(r.ok) << r.log;
    for (const auto& f : r.artifact->files) {
      if (!f.name.ends_with(".glsl")) continue;
      // The lookup keeps one directive on purpose: its frame block is guarded so that an engine
      // can supply the frame itself (emit/lookup_interface.h).
      std::string text = f.bytes;
      if (f.name == lookupFileName(spec.name)) {
        const size_t guard = text.find("#ifndef SHADOWC_FRAME_EXTERNAL\n");
        ASSERT_NE(guard, std::string::npos) << f.name;
        text.erase(guard, text.find('\n', guard) - guard);
      }
      for (const char* absent : {"#define", "#ifdef", "#ifndef", "#if ", "#include", "@shadowc:specialize"})
        EXPECT_EQ(text.find(absent), std::string::npos) << spec.name << "/" << f.name << " contains " << absent;
    }
  }
}

TEST(EmittedCode, LookupFileIsIncludableAndDescribedInTheManifest) {
  const FilterSpec spec = test::vssmInt32Spec();
  const driver::Result r = driver::compileSpec(spec);
  ASSERT_TRUE(r.ok) << r.log;
  const std::string lookup = file(r, lookupFileName(spec.name));
  EXPECT_EQ(lookup.find("\n#version"), std::string::npos);  // directives start lines
  EXPECT_EQ(lookup.find("\n#line"), std::string::npos);
  EXPECT_NE(lookup.find(r.artifact->manifest.shade.signature), std::string::npos)
      << r.artifact->manifest.shade.signature;
  EXPECT_EQ(r.artifact->manifest.shade.glsl, lookupFileName(spec.name));
  for (const Binding& b : r.artifact->manifest.shade.bindings)
    EXPECT_TRUE(b.binding == 0 || b.binding >= 4) << b.binding;
}

TEST(EmittedCode, OptimizationLevelChangesSpirvAndTheHashButNotTheGlsl) {
  const FilterSpec spec = test::vssmInt32Spec();
  const driver::Result a = driver::compileSpec(spec), b = driver::compileSpec(spec, test::optimizeOption(false));
  ASSERT_TRUE(a.ok && b.ok) << a.log << b.log;
  EXPECT_EQ(file(a, "shade.glsl"), file(b, "shade.glsl"));
  EXPECT_NE(file(a, "shade.spv"), file(b, "shade.spv"));
  EXPECT_LT(file(a, "shade.spv").size(), file(b, "shade.spv").size()) << "the -O recipe should shrink the module";
  EXPECT_NE(a.artifact->manifest.contentHash, b.artifact->manifest.contentHash);
}

}  // namespace
}  // namespace shadowc

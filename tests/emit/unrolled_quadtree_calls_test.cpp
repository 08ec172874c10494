// The unrolled quadtree's shade shader keeps its node callbacks as calls through the -O recipe
// (inlined 85 times at height 3 the recipe took 1.2-2.6 s; backend/dont_inline.h).
// Sibling: the loop walks (table and computed), which call them from one loop, are inlined completely.
#include <gtest/gtest.h>

#include <string>

#include "backend/spirv_backend.h"
#include "driver/shader_compile.h"
#include "plan/planner.h"
#include "plan/test_specs.h"

namespace shadowc {
namespace {

std::string shadeDisassembly(QuadtreeTraversal traversal) {
  FilterSpec spec = test::vssmInt32Spec();
  spec.kernel.quadtreeHeight = 2;  // small: the wiring, not the size, is under test
  spec.kernel.traversal = traversal;
  const PassGraph g = planPasses(spec);
  const PassSource* shade = shadeSource(g);
  if (!shade) return "no shade pass";
  const driver::CompiledShader sh = driver::compileShader(shade->templatePath, shade->values, {});
  if (!sh.ok) return "failed: " + sh.log;
  EXPECT_EQ(validateSpirv(sh.spirv), "");
  return disassembleSpirv(sh.spirv);
}

TEST(UnrolledQuadtreeCalls, NodeCallbacksStayCallsAtO) {
  const std::string dis = shadeDisassembly(QuadtreeTraversal::Unrolled);
  EXPECT_NE(dis.find("DontInline"), std::string::npos) << dis.substr(0, 400);
  EXPECT_NE(dis.find("OpFunctionCall"), std::string::npos);
}

TEST(UnrolledQuadtreeCalls, TheLoopWalksAreInlinedCompletely) {
  for (QuadtreeTraversal t : {QuadtreeTraversal::Table, QuadtreeTraversal::Computed}) {
    const std::string dis = shadeDisassembly(t);
    EXPECT_EQ(dis.find("DontInline"), std::string::npos);
    EXPECT_EQ(dis.find("OpFunctionCall"), std::string::npos) << dis.substr(0, 400);
  }
}

}  // namespace
}  // namespace shadowc

// `shadowc compile --print-plan` (plan/plan_printer.h), matched with CHECK-style lines
// (SPIRV-Tools' habit): each CHECK must match a later line than the one before, CHECK-NEXT the
// very next line, CHECK-NOT no line between the two CHECKs around it.
#include "plan/plan_printer.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "plan/planner.h"
#include "plan/test_specs.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

// Returns "" when `text` satisfies every directive ("CHECK: x", "CHECK-NEXT: x", "CHECK-NOT: x";
// x is a substring of a line), else the first directive that failed.
std::string fileCheck(const std::string& text, const std::vector<std::string>& directives) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  size_t next = 0;  // first line a CHECK may match
  std::vector<std::string> pendingNot;
  for (const std::string& d : directives) {
    const size_t colon = d.find(": ");
    const std::string kind = d.substr(0, colon), what = d.substr(colon + 2);
    if (kind == "CHECK-NOT") {
      pendingNot.push_back(what);
      continue;
    }
    size_t at = next;
    if (kind == "CHECK-NEXT") {
      if (at >= lines.size() || lines[at].find(what) == std::string::npos)
        return d + "  (next line: '" + (at < lines.size() ? lines[at] : "") + "')";
    } else {
      while (at < lines.size() && lines[at].find(what) == std::string::npos) ++at;
      if (at == lines.size()) return d + "  (no later line matches)";
    }
    for (const std::string& n : pendingNot)
      for (size_t i = next; i < at; ++i)
        if (lines[i].find(n) != std::string::npos) return "CHECK-NOT: " + n + "  (line '" + lines[i] + "')";
    pendingNot.clear();
    next = at + 1;
  }
  for (const std::string& n : pendingNot)
    for (size_t i = next; i < lines.size(); ++i)
      if (lines[i].find(n) != std::string::npos) return "CHECK-NOT: " + n + "  (line '" + lines[i] + "')";
  return "";
}

std::string sample(const std::string& name) {
  return (test::sourceDir() / "samples" / "filters" / (name + ".shadow")).string();
}

// samples/filters/vssm_adaptive.shadow: int32 SAT, moments blocker, quadtree(height: 3) kernel,
// min-max early out, PCF fallback and contact path.
const std::vector<std::string> kVssmChecks = {
    "CHECK: ; shadowc pass graph, filter vssm_adaptive: 6 images, 7 passes",
    "CHECK: image shadow_depth r32f size map levels 1 layers 1 role input_depth",
    // The fused prefilter: no moments image, the SAT row scan warps the depth.
    "CHECK-NEXT: image sat rg32ui size map levels 1 layers 1 role internal",
    // A SAT kernel's max defaults to the whole map: the pyramid stops at level 8 (planner.h).
    "CHECK-NEXT: image minmax rg32f size map levels 9 layers 1 role internal",
    // Algorithm 2's Next/Child tables for height 3 (traversal: table), (ix | iy << 16, 2^level,
    // Child, Next) per node in pre-order: the root, its first child, whose Next is node 22.
    "CHECK-NEXT: buffer quadtree_table int32x4[85] (0 1 1 -1) (0 2 2 22) (0 4 3 7) (0 8 -1 4) (1 8 -1 5)",
    "CHECK-NEXT: pass 0 sat_rows kind sat",
    "CHECK-NEXT:   template passes/sat_rows.comp stem sat_rows",
    "CHECK-NEXT:   local 64x1x1 dispatch rows map",
    "CHECK: binding 0 shadow_depth sampled",
    "CHECK: value SHADOWC_WARP enum SHADOWC_WARP_LINEAR (0)",
    "CHECK: value SHADOWC_SPLITS real[2] 0, 1",
    "CHECK: value SHADOWC_SAT_KIND enum SHADOWC_SAT_INT32 (1)",
    "CHECK-NEXT: value SHADOWC_SAT_FORMAT format rg32ui",
    "CHECK-NEXT: value SHADOWC_SAT_FROM_DEPTH bool 1",
    "CHECK: pass 1 sat_columns kind sat",
    "CHECK: pass 2 minmax012 kind minmax",
    "CHECK: template passes/minmax.comp stem minmax_depth_two",
    "CHECK: dispatch texels map>>2",
    "CHECK: value SHADOWC_MINMAX_LEVEL0 bool 1",
    "CHECK: pass 4 minmax56 kind minmax",
    "CHECK: template passes/minmax.comp stem minmax_two",
    "CHECK: dispatch texels map>>6",
    "CHECK: value SHADOWC_MINMAX_LEVEL0 bool 0",
    "CHECK-NEXT: value SHADOWC_MINMAX_TWO bool 1",
    "CHECK: pass 5 minmax78 kind minmax",
    "CHECK-NOT: pass 7",
    "CHECK: pass 6 shade kind shade",
    "CHECK: binding 6 sat sampled",
    "CHECK: binding 10 quadtree_table storage_buffer_read",
    "CHECK: value SHADOWC_TECHNIQUE enum SHADOWC_TECHNIQUE_VSSM (3)",
    "CHECK: value SHADOWC_LIGHT_WIDTH real 0.04",
    // Boxes up to the whole map: the int32 SAT sums them in pieces of 255 (sat.glsl).
    "CHECK: value SHADOWC_KERNEL_MAX_TEXELS real 4096",
    "CHECK-NEXT: value SHADOWC_SAT_PIECES int 17",
    "CHECK: value SHADOWC_KERNEL_SUBDIVISION enum SHADOWC_SUBDIV_QUADTREE (2)",
    "CHECK: value SHADOWC_KERNEL_HEIGHT int 3",
    "CHECK: value SHADOWC_BLOCKER_KIND enum SHADOWC_BLOCKER_MOMENTS (2)",
    "CHECK: value SHADOWC_BLEEDING real 0.2",
    "CHECK: value SHADOWC_FALLBACK_PCF bool 1",
    "CHECK: value SHADOWC_CONTACT_EPSILON real 0.01",
    "CHECK: value SHADOWC_QT_NODES int 85",  // (4^4 - 1) / 3
    "CHECK-NEXT: value SHADOWC_QT_TABLE bool 1",
    // The tables are the buffer's, not a GLSL table.
    "CHECK-NOT: table shadowc_qt",
};

TEST(PrintPlan, VssmSampleMatchesItsChecks) {
  const test::CliResult r = test::runShadowc("compile " + sample("vssm_adaptive") + " --print-plan");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(fileCheck(r.out, kVssmChecks), "") << r.out;
}

// The sibling: the same checks fail on another filter's plan, and each directive kind can fail.
TEST(PrintPlan, ChecksFailOnAnotherPlan) {
  const test::CliResult r = test::runShadowc("compile " + sample("vssm_quadtree_unrolled") + " --print-plan");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(fileCheck(r.out, kVssmChecks), "");
  EXPECT_NE(r.out.find("table shadowc_qtUnrolledKernel unrolled_quadtree height"), std::string::npos) << r.out;
  const std::string text = "a\nb\nc\n";
  EXPECT_EQ(fileCheck(text, {"CHECK: a", "CHECK-NEXT: b", "CHECK-NOT: x", "CHECK: c"}), "");
  EXPECT_NE(fileCheck(text, {"CHECK: b", "CHECK: a"}), "");                  // order matters
  EXPECT_NE(fileCheck(text, {"CHECK: a", "CHECK-NEXT: c"}), "");             // NEXT is the next line
  EXPECT_NE(fileCheck(text, {"CHECK: a", "CHECK-NOT: b", "CHECK: c"}), "");  // NOT between
}

TEST(PrintPlan, PrintsEveryValueOfEveryPassAndIsDeterministic) {
  for (const FilterSpec& spec :
       {test::vssmInt32Spec(), test::layeredEvsmSpec(), test::blurMipSpec(), test::pcfSpec()}) {
    const PassGraph g = planPasses(spec);
    const std::string text = printPassGraph(g);
    EXPECT_EQ(text, printPassGraph(planPasses(spec)));
    size_t at = 0;
    for (size_t i = 0; i < g.sources.size(); ++i) {
      at = text.find("pass " + std::to_string(i) + " " + g.manifest.passes[i].name, at);
      ASSERT_NE(at, std::string::npos) << spec.name << " pass " << i;
      for (const Constant& c : g.sources[i].values.constants) {
        at = text.find("  value " + c.name + " " + printValue(c.value) + "\n", at);
        ASSERT_NE(at, std::string::npos) << spec.name << " " << c.name;
      }
    }
  }
}

TEST(PrintPlan, ValuesOfEachKind) {
  EXPECT_EQ(printValue(SpecValue{3LL}), "int 3");
  EXPECT_EQ(printValue(SpecValue{true}), "bool 1");
  EXPECT_EQ(printValue(SpecValue{Real{0.1}}), "real 0.1");
  EXPECT_EQ(printValue(SpecValue{Real{static_cast<double>(0.1f)}}), "real 0.10000000149011612");  // fp32-rounded
  EXPECT_EQ(printValue(SpecValue{warpCode(Warp::Evsm2)}), "enum SHADOWC_WARP_EVSM2 (2)");
  EXPECT_EQ(printValue(SpecValue{ImageFormat::RGBA16Unorm}), "format rgba16");
  EXPECT_EQ(printValue(SpecValue{RealList{{0.0, 0.5, 1.0}}}), "real[3] 0, 0.5, 1");
}

TEST(PrintPlan, WithOutputDirectoryItAlsoCompiles) {
  const auto dir = test::freshTempDir("print-plan");
  const test::CliResult r =
      test::runShadowc("compile " + sample("pcf_poisson16") + " --print-plan -o " + (dir / "o").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("table shadowc_poissonPcf point[16] ("), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "o" / "manifest.json"));
}

}  // namespace
}  // namespace shadowc

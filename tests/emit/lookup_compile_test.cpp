// Every lookup variant shadowc supports must specialize, preprocess and compile to valid SPIR-V
// (glslang + spirv-opt + spirv-val in process), inserted into templates/shade.comp the way the
// emitter does it. CHECK-style assertions on the preprocessed text make sure that unused
// features are absent and that the quadtree variants have the shape they claim.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "backend/spirv_backend.h"
#include "embed/embedded_file.h"
#include "emit/specialization_block.h"
#include "plan/internal_error.h"
#include "plan/shade_plan.h"
#include "spec/filter_spec.h"

namespace shadowc {
namespace {

struct Variant {
  std::string name;
  FilterSpec spec;
};

FilterSpec momentsSpec() {
  FilterSpec s;
  s.representation = Representation::Moments;
  s.moments.warp = Warp::Linear;
  s.kernel.size = KernelSize::Fixed;
  s.kernel.fixedTexels = 5;
  return s;
}

FilterSpec vssmSpec() {
  FilterSpec s = momentsSpec();
  s.storage.sat = SatKind::Int32;
  s.blocker.kind = BlockerKind::Moments;
  s.blocker.subdivision = Subdivision::Uniform;
  s.blocker.uniformM = 5;
  s.kernel.size = KernelSize::Penumbra;
  s.kernel.subdivision = Subdivision::Quadtree;
  s.kernel.quadtreeHeight = 3;
  s.fallback.pcf = true;
  s.light.sizeFromScene = false;
  s.light.size = 0.04;
  return s;
}

std::vector<Variant> variants() {
  std::vector<Variant> v;
  {
    FilterSpec s;  // hard shadows: 1x1 PCF
    s.kernel.size = KernelSize::Fixed;
    s.kernel.fixedTexels = 1;
    s.sampling.gridN = 1;
    v.push_back({"pcf_hard", s});
  }
  {
    FilterSpec s;
    s.kernel.size = KernelSize::Fixed;
    s.sampling.pattern = PcfPattern::Grid;
    v.push_back({"pcf_grid", s});
    s.sampling.pattern = PcfPattern::Bilinear;
    s.bias.kind = BiasKind::SlopeScaled;
    v.push_back({"pcf_bilinear_slope_bias", s});
    s.sampling.pattern = PcfPattern::Poisson;
    s.bias.kind = BiasKind::NormalOffset;
    s.bias.normalOffset = 1.5;
    v.push_back({"pcf_poisson_normal_offset", s});
    s.sampling.rotation = Rotation::None;
    s.earlyOutMinMax = true;
    v.push_back({"pcf_poisson_unrotated_early_out", s});
  }
  {
    FilterSpec s;
    s.blocker.kind = BlockerKind::Search;
    s.blocker.pattern = SamplePattern::Poisson;
    s.sampling.pattern = PcfPattern::Poisson;
    v.push_back({"pcss_poisson", s});
    s.blocker.pattern = SamplePattern::Grid;
    s.sampling.pattern = PcfPattern::Grid;
    s.sampling.gridN = 7;
    s.light.sizeFromScene = false;
    s.light.size = 0.1;
    s.earlyOutMinMax = true;
    v.push_back({"pcss_grid_folded_light_early_out", s});
  }
  {
    FilterSpec s = momentsSpec();
    v.push_back({"vsm", s});
    s.moments.bleedingReduction = 0.2;
    s.prefilter.mips = true;
    v.push_back({"vsm_mips_bleeding", s});
    s.storage.sat = SatKind::Fp32Centered;
    v.push_back({"vsm_sat_centered", s});
    s.storage.sat = SatKind::Fp32Naive;
    v.push_back({"vsm_sat_naive", s});
    s.storage.sat = SatKind::Int32;
    s.kernel.size = KernelSize::Penumbra;
    s.blocker.kind = BlockerKind::Search;
    v.push_back({"vsm_sat_int32_pcss_search", s});
  }
  {
    FilterSpec s = momentsSpec();
    s.moments.warp = Warp::Exp;
    v.push_back({"esm", s});
    s.moments.warp = Warp::Evsm2;
    v.push_back({"evsm2", s});
    s.moments.warp = Warp::Evsm4;
    s.moments.bleedingReduction = 0.1;
    v.push_back({"evsm4", s});
    s.storage.sat = SatKind::Fp32Centered;
    v.push_back({"evsm4_sat", s});
    s.moments.warp = Warp::PowerCdf;
    s.storage.sat = SatKind::None;
    v.push_back({"power_cdf", s});
  }
  {
    FilterSpec s = momentsSpec();
    s.moments.layers = 4;
    s.moments.splits = {0.0, 0.2, 0.5, 0.7, 1.0};
    s.moments.overlap = 0.02;
    s.moments.split = SplitPlacement::Explicit;
    v.push_back({"layered_explicit_overlap", s});
    s.moments.split = SplitPlacement::Lloyd;
    s.moments.overlap = 0.0;
    v.push_back({"layered_lloyd", s});
    s.moments.split = SplitPlacement::Uniform;
    s.moments.splits = {0.0, 0.25, 0.5, 0.75, 1.0};  // uniform, as normalization writes it
    s.moments.overlap = 0.01;
    s.moments.warp = Warp::PowerCdf;
    v.push_back({"power_cdf_layered", s});
    s.moments.warp = Warp::Evsm2;
    s.storage.sat = SatKind::Fp32Centered;
    v.push_back({"evsm2_layered_sat", s});
  }
  {
    FilterSpec s = vssmSpec();
    v.push_back({"vssm_mixed_qt_table", s});
    s.kernel.traversal = QuadtreeTraversal::Computed;
    v.push_back({"vssm_mixed_qt_computed", s});
    s.kernel.traversal = QuadtreeTraversal::Unrolled;
    v.push_back({"vssm_mixed_qt_unrolled", s});
    s.contact.enabled = true;
    s.earlyOutMinMax = true;
    s.moments.bleedingReduction = 0.2;
    v.push_back({"vssm_paper_example", s});
    s.blocker.subdivision = Subdivision::Quadtree;
    s.blocker.quadtreeHeight = 2;
    v.push_back({"vssm_qt_blocker_unrolled", s});
    s.kernel.traversal = QuadtreeTraversal::Table;
    s.kernel.quadtreeHeight = 4;
    v.push_back({"vssm_qt_blocker_table_h4", s});
    s.kernel.subdivision = Subdivision::Uniform;
    s.kernel.uniformN = 8;
    s.blocker.subdivision = Subdivision::Uniform;
    s.fallback.pcf = false;
    v.push_back({"vssm_uniform_no_fallback", s});
    s.kernel.subdivision = Subdivision::None;
    s.blocker.subdivision = Subdivision::None;
    s.storage.sat = SatKind::Fp32Centered;
    v.push_back({"vssm_no_subdivision", s});
    s.storage.sat = SatKind::None;
    s.prefilter.mips = true;
    v.push_back({"vssm_mips_no_sat", s});
  }
  {
    // Receiver-plane bias (bias.glsl): every technique with depth taps, spot and sun.
    FilterSpec s;
    s.bias.kind = BiasKind::ReceiverPlane;
    s.kernel.size = KernelSize::Fixed;
    v.push_back({"pcf_grid_receiver_plane", s});
    s.sampling.pattern = PcfPattern::Bilinear;
    s.earlyOutMinMax = true;
    v.push_back({"pcf_bilinear_receiver_plane_early_out", s});
    s.light.type = LightType::Sun;
    v.push_back({"pcf_bilinear_receiver_plane_sun", s});
    FilterSpec p;
    p.bias.kind = BiasKind::ReceiverPlane;
    p.blocker.kind = BlockerKind::Search;
    p.blocker.pattern = SamplePattern::Poisson;
    p.sampling.pattern = PcfPattern::Poisson;
    v.push_back({"pcss_poisson_receiver_plane", p});
    p.blocker.pattern = SamplePattern::Grid;
    v.push_back({"pcss_grid_search_receiver_plane", p});
    FilterSpec q = vssmSpec();
    q.bias.kind = BiasKind::ReceiverPlane;
    q.contact.enabled = true;
    q.earlyOutMinMax = true;
    v.push_back({"vssm_fallback_contact_receiver_plane", q});
  }
  return v;
}

std::optional<std::string> resolveTemplate(const std::string& name) {
  std::string_view text = templates::find(name);
  if (text.empty()) return std::nullopt;
  return std::string(text);
}

std::string shadeText(const FilterSpec& spec) {
  std::string_view shade = templates::find("shade.comp");
  EXPECT_FALSE(shade.empty());
  return insertSpecialization(std::string(shade), planShadeSpecialization(spec));
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string preprocessed(const Variant& v) {
  std::string out;
  SpirvResult r = preprocessGlsl(shadeText(v.spec), ShaderStage::Compute, v.name + ".comp", resolveTemplate, out);
  EXPECT_TRUE(r.ok) << v.name << ":\n" << r.log;
  // Debug aid: SHADOWC_LOOKUP_DUMP=<dir> writes every preprocessed variant there.
  if (const char* dir = std::getenv("SHADOWC_LOOKUP_DUMP"))
    std::ofstream(std::string(dir) + "/" + v.name + ".comp") << out;
  return out;
}

Variant find(const std::string& name) {
  for (auto& v : variants())
    if (v.name == name) return v;
  ADD_FAILURE() << "no variant " << name;
  return {};
}

class LookupCompile : public ::testing::TestWithParam<Variant> {};

TEST_P(LookupCompile, SpecializesPreprocessesAndCompilesToValidSpirv) {
  const Variant& v = GetParam();
  ASSERT_EQ(shadeText(v.spec).find(kSpecializeMarker), std::string::npos) << "marker not replaced";
  // Compile the preprocessed text (what the emitter ships; the same tokens as the source).
  const std::string pre = preprocessed(v);
  SpirvResult r = compileGlsl(pre, ShaderStage::Compute, v.name + ".comp", resolveTemplate, BackendOptions{});
  ASSERT_TRUE(r.ok) << v.name << ":\n" << r.log;
  EXPECT_EQ(validateSpirv(r.words), "");
  EXPECT_EQ(pre.find("#include"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(AllVariants, LookupCompile, ::testing::ValuesIn(variants()),
                         [](const ::testing::TestParamInfo<Variant>& i) { return i.param.name; });

TEST(LookupCompileChecks, TemplateCompilesOnItsOwnWithDefaults) {
  std::string_view shade = templates::find("shade.comp");
  ASSERT_FALSE(shade.empty());
  SpirvResult r = compileGlsl(shade, ShaderStage::Compute, "shade.comp", resolveTemplate, BackendOptions{});
  EXPECT_TRUE(r.ok) << r.log;
}

TEST(LookupCompileChecks, PcfOnlyHasNoMomentsOrSummedAreaTable) {
  const std::string pre = lower(preprocessed(find("pcf_grid")));
  EXPECT_EQ(pre.find("sat"), std::string::npos);
  EXPECT_EQ(pre.find("moments"), std::string::npos);
  EXPECT_EQ(pre.find("minmax"), std::string::npos);
  EXPECT_NE(pre.find("shadowc_visibility"), std::string::npos);
  // Constants are folded: no SHADOWC_ macro names survive preprocessing.
  EXPECT_EQ(pre.find("shadowc_pcf_n"), std::string::npos);
}

TEST(LookupCompileChecks, ReceiverPlaneTapsOnlyWithThatBias) {
  // The per-tap plane depth is in the receiver-plane variants only; the others keep one d.
  for (const char* name :
       {"pcf_grid_receiver_plane", "pcss_poisson_receiver_plane", "vssm_fallback_contact_receiver_plane"})
    EXPECT_NE(preprocessed(find(name)).find("shadowc_tapDepth"), std::string::npos) << name;
  for (const char* name : {"pcf_grid", "pcss_poisson", "vssm_paper_example"})
    EXPECT_EQ(preprocessed(find(name)).find("shadowc_tapDepth"), std::string::npos) << name;
}

TEST(LookupCompileChecks, SiblingSatVariantDoesMentionTheTable) {
  // Proves the check above can fail: the same search finds the SAT in a SAT variant.
  const std::string pre = lower(preprocessed(find("vsm_sat_centered")));
  EXPECT_NE(pre.find("sat"), std::string::npos);
  EXPECT_NE(pre.find("moments"), std::string::npos);
}

TEST(LookupCompileChecks, UnrolledQuadtreeHasNoLoopInItsTraversal) {
  const std::string pre = preprocessed(find("vssm_mixed_qt_unrolled"));
  const size_t start = pre.find("void shadowc_qtUnrolledKernel()");
  ASSERT_NE(start, std::string::npos);
  const size_t end = pre.find("\n}", start);
  const std::string body = pre.substr(start, end - start);
  EXPECT_EQ(body.find("for("), std::string::npos);  // glslang prints `for(` / `while(`
  EXPECT_EQ(body.find("while("), std::string::npos);
  EXPECT_NE(pre.find("for("), std::string::npos);  // sibling: loops elsewhere are found
  EXPECT_EQ(pre.find("shadowc_qtNext"), std::string::npos);
  EXPECT_EQ(pre.find("shadowc_qtChild"), std::string::npos);
  // 85 nodes for H = 3: 21 internal visits and 64 leaves.
  size_t visits = 0, leaves = 0;
  for (size_t p = body.find("shadowc_qtVisit("); p != std::string::npos; p = body.find("shadowc_qtVisit(", p + 1))
    ++visits;
  for (size_t p = body.find("shadowc_qtLeaf("); p != std::string::npos; p = body.find("shadowc_qtLeaf(", p + 1))
    ++leaves;
  EXPECT_EQ(visits, 21u);
  EXPECT_EQ(leaves, 64u);
}

TEST(LookupCompileChecks, LoopQuadtreeWalksAreBoundedByTheNodeCount) {
  for (const char* name : {"vssm_mixed_qt_table", "vssm_mixed_qt_computed"}) {
    const std::string pre = preprocessed(find(name));
    EXPECT_NE(pre.find("step < 85"), std::string::npos) << name;   // height 3: (4^4 - 1) / 3 nodes
    EXPECT_EQ(pre.find("const ivec"), std::string::npos) << name;  // no const table
    EXPECT_EQ(pre.find("shadowc_qtUnrolled"), std::string::npos) << name;
  }
  // The table walk reads the buffer; the computed one has none.
  EXPECT_NE(preprocessed(find("vssm_mixed_qt_table")).find("shadowc_qtTable[i]"), std::string::npos);
  EXPECT_EQ(preprocessed(find("vssm_mixed_qt_computed")).find("shadowc_qtTable"), std::string::npos);
}

TEST(LookupCompileChecks, FoldedLightWidthReplacesTheFrameValue) {
  const std::string folded = preprocessed(find("pcss_grid_folded_light_early_out"));
  EXPECT_EQ(folded.find("lightParams . w"), std::string::npos);
  const std::string fromScene = preprocessed(find("pcss_poisson"));
  EXPECT_NE(fromScene.find("lightParams . w"), std::string::npos);
}

TEST(LookupCompileChecks, SpecializationIsDeterministicAndKeepsLineNumbers) {
  const FilterSpec s = find("vssm_paper_example").spec;
  EXPECT_EQ(shadeText(s), shadeText(s));
  const std::string src = shadeText(s);
  EXPECT_NE(src.find("#line 4\n"), std::string::npos);  // marker is line 3 of shade.comp
}

TEST(LookupCompileChecks, ImpossibleCombinationsAreRejected) {
  // The checker rejects both first (E0417, E0411): reaching the planner with them is a shadowc bug.
  FilterSpec s = vssmSpec();
  s.moments.warp = Warp::Evsm4;
  EXPECT_THROW(planShadeSpecialization(s), InternalError);
  FilterSpec p = momentsSpec();
  p.moments.warp = Warp::PowerCdf;
  p.storage.sat = SatKind::Int32;
  EXPECT_THROW(planShadeSpecialization(p), InternalError);
}

}  // namespace
}  // namespace shadowc

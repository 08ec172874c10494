#include "plan/planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "embed/embedded_file.h"
#include "plan/test_specs.h"

namespace shadowc {
namespace {

std::vector<std::string> passNames(const PassGraph& g) {
  std::vector<std::string> n;
  for (const auto& p : g.manifest.passes) n.push_back(p.name);
  return n;
}

const ImageDesc* image(const PassGraph& g, const std::string& name) {
  for (const auto& im : g.manifest.images)
    if (im.name == name) return &im;
  return nullptr;
}

const Pass& pass(const PassGraph& g, const std::string& name) {
  for (const auto& p : g.manifest.passes)
    if (p.name == name) return p;
  throw std::runtime_error("no pass " + name);
}

TEST(Planner, DepthPcfPlansOnlyTheShadePass) {
  const PassGraph g = planPasses(test::pcfSpec());
  EXPECT_EQ(passNames(g), std::vector<std::string>{"shade"});
  EXPECT_EQ(g.manifest.images.size(), 4u);  // the fixed interface only
  EXPECT_EQ(image(g, "moments"), nullptr);
  const Pass& s = pass(g, "shade");
  ASSERT_EQ(s.bindings.size(), 5u);
  for (uint32_t b = 0; b < 5; ++b) EXPECT_EQ(s.bindings[b].binding, b);
  EXPECT_EQ(s.bindings[0].image, "frame");
  EXPECT_EQ(s.bindings[4].image, "shadow_depth");
  EXPECT_EQ(s.dispatch.size.domain, SizeDomain::Screen);
}

// The fused prefilter: the SAT row scan reads the light depth, no moments pass or
// image exists; the min-max pyramid takes one dispatch per two levels.
TEST(Planner, VssmInt32PlansFusedSatMinMaxShadeInOrder) {
  const FilterSpec spec = test::vssmInt32Spec();
  const PassGraph g = planPasses(spec);
  ASSERT_EQ(pyramidLevels(spec), 7);  // default max 64 texels: ceil(log2 64) + 1
  EXPECT_EQ(passNames(g),
            (std::vector<std::string>{"sat_rows", "sat_columns", "minmax012", "minmax34", "minmax56", "shade"}));
  EXPECT_EQ(image(g, "moments"), nullptr);
  ASSERT_NE(image(g, "sat"), nullptr);
  EXPECT_EQ(image(g, "sat")->format, ImageFormat::RG32UI);
  EXPECT_EQ(image(g, "minmax")->format, ImageFormat::RG32F);
  EXPECT_EQ(image(g, "minmax")->mipLevels, pyramidLevels(spec));
  const Pass& rows = pass(g, "sat_rows");
  EXPECT_EQ(rows.dispatch.mode, DispatchMode::Rows);
  ASSERT_EQ(rows.bindings.size(), 2u);
  EXPECT_EQ(rows.bindings[0].image, "shadow_depth");
  EXPECT_EQ(rows.bindings[0].access, Access::Sampled);
  EXPECT_EQ(pass(g, "sat_columns").dispatch.mode, DispatchMode::Columns);
  EXPECT_EQ(pass(g, "sat_columns").bindings.at(0).access, Access::StorageReadWrite);
  // The first min-max dispatch reads the depth, writes level 0 (binding 2), 1 (binding 3, the
  // middle) and 2 (binding 1), over level 2's extent; the next reads 2 and writes 3 and 4.
  const Pass& m012 = pass(g, "minmax012");
  EXPECT_EQ(m012.bindings.at(0).image, "shadow_depth");
  EXPECT_EQ(m012.bindings.at(1).level, 2);
  EXPECT_EQ(m012.bindings.at(2).level, 0);
  EXPECT_EQ(m012.bindings.at(3).level, 1);
  EXPECT_EQ(m012.dispatch.size.shift, 2);
  const Pass& m34 = pass(g, "minmax34");
  EXPECT_EQ(m34.bindings.size(), 3u);
  EXPECT_EQ(m34.bindings.at(0).level, 2);
  EXPECT_EQ(m34.bindings.at(1).level, 4);
  EXPECT_EQ(m34.bindings.at(2).binding, 3u);
  EXPECT_EQ(m34.bindings.at(2).level, 3);
  EXPECT_EQ(m34.dispatch.size.shift, 4);
  EXPECT_EQ(m34.spirv, pass(g, "minmax56").spirv);  // the same shader for every middle pair
  // Shade binds 6 sat, 7 minmax and 10 the quadtree's Next/Child tables (traversal: table); with
  // a SAT the moments are never bound.
  const Pass& s = pass(g, "shade");
  ASSERT_EQ(s.bindings.size(), 8u);
  EXPECT_EQ(s.bindings[5].image, "sat");
  EXPECT_EQ(s.bindings[5].binding, 6u);
  EXPECT_EQ(s.bindings[6].image, "minmax");
  EXPECT_EQ(s.bindings[7].image, "quadtree_table");
  EXPECT_EQ(s.bindings[7].binding, 10u);
  EXPECT_EQ(s.bindings[7].access, Access::StorageBufferRead);
}

// A pyramid of an odd level count ends with a single-level dispatch; of two levels, one
// dispatch from the depth.
TEST(Planner, MinMaxPyramidEndsWithASingleLevelWhenTheCountIsEven) {
  FilterSpec spec = test::vssmInt32Spec();
  spec.kernel.maxTexels = 128;  // 8 levels: 0-2, 3-4, 5-6, 7
  std::vector<std::string> minmax;
  for (const Pass& p : planPasses(spec).manifest.passes)
    if (p.kind == "minmax") minmax.push_back(p.name);
  EXPECT_EQ(minmax, (std::vector<std::string>{"minmax012", "minmax34", "minmax56", "minmax7"}));
  EXPECT_EQ(pass(planPasses(spec), "minmax7").bindings.size(), 2u);
  spec.kernel.maxTexels = 2;
  minmax.clear();
  for (const Pass& p : planPasses(spec).manifest.passes)
    if (p.kind == "minmax") minmax.push_back(p.name);
  EXPECT_EQ(minmax, (std::vector<std::string>{"minmax01"}));
}

// A blur between the moments and the SAT keeps the moments pass and image; the SAT rows read
// them (unfused), and the shade still binds only the table.
TEST(Planner, SatAfterABlurReadsTheMomentsImage) {
  FilterSpec spec = test::vssmInt32Spec();
  spec.prefilter.blur = BlurKind::Box;
  spec.prefilter.blurRadius = 2;
  const PassGraph g = planPasses(spec);
  EXPECT_EQ(g.manifest.passes.at(0).name, "moments");
  ASSERT_NE(image(g, "moments"), nullptr);
  EXPECT_EQ(pass(g, "sat_rows").bindings.at(0).image, "moments");
  for (const Binding& b : pass(g, "shade").bindings) EXPECT_NE(b.image, "moments");
}

TEST(Planner, FpSatKindsUseFloatFormats) {
  FilterSpec spec = test::vssmInt32Spec();
  spec.storage.sat = SatKind::Fp32Centered;
  EXPECT_EQ(image(planPasses(spec), "sat")->format, ImageFormat::RG32F);
  spec.moments.warp = Warp::Evsm4;  // an EVSM4 SAT: a filtered-moments lookup (VSSM needs linear)
  spec.blocker.kind = BlockerKind::None;
  spec.kernel.subdivision = Subdivision::None;
  EXPECT_EQ(image(planPasses(spec), "sat")->format, ImageFormat::RGBA32F);
}

// `weights form_factor` reaches the shade pass as SHADOWC_WEIGHTED for a spot light only (the
// checker warns for the others, W0505); unweighted filters define nothing, so they emit what they did.
TEST(Planner, FormFactorWeightsAreDefinedForSpotLightsOnly) {
  auto weighted = [](FilterSpec s) {
    const PassGraph g = planPasses(s);
    const auto shade = std::find_if(g.manifest.passes.begin(), g.manifest.passes.end(),
                                    [](const Pass& p) { return p.kind == "shade"; });
    const auto& values = g.sources.at(size_t(shade - g.manifest.passes.begin())).values.constants;
    return std::any_of(values.begin(), values.end(), [](const Constant& c) { return c.name == "SHADOWC_WEIGHTED"; });
  };
  FilterSpec s = test::vssmInt32Spec();
  EXPECT_FALSE(weighted(s));
  s.formFactorWeights = true;
  EXPECT_TRUE(weighted(s));
  FilterSpec pcf = test::pcfSpec();
  pcf.formFactorWeights = true;
  EXPECT_TRUE(weighted(pcf));
  pcf.light.type = LightType::Sun;
  EXPECT_FALSE(weighted(pcf));
}

TEST(Planner, LayeredMomentsHaveOneArrayLayerPerLayerAndFoldedSplits) {
  const PassGraph g = planPasses(test::layeredEvsmSpec());
  const ImageDesc* m = image(g, "moments");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->layers, 3);
  EXPECT_EQ(m->format, ImageFormat::RGBA16F);  // evsm4 x fp16
  EXPECT_TRUE(m->linearFilter);
  const auto& values = g.sources.at(0).values.constants;
  auto value = [&](const std::string& n) -> SpecValue {
    for (const Constant& c : values)
      if (c.name == n) return c.value;
    return SpecValue{-1LL};  // missing
  };
  EXPECT_EQ(value("SHADOWC_LAYERS"), SpecValue{3LL});
  // The pass folds the fp32 values in: 0.6 is stored as float(0.6).
  const RealList splits{{0.0, 0.25, static_cast<double>(0.6f), 1.0}};
  EXPECT_EQ(value("SHADOWC_SPLITS"), SpecValue{splits});
  EXPECT_EQ(value("SHADOWC_WARP"), SpecValue{warpCode(Warp::Evsm4)});
  const EnumCode evsm4{"SHADOWC_WARP_EVSM4", 3};
  EXPECT_EQ(value("SHADOWC_WARP"), SpecValue{evsm4});
  EXPECT_EQ(value("SHADOWC_MOMENTS_FORMAT"), SpecValue{ImageFormat::RGBA16F});
}

TEST(Planner, BlurAndMipsPlanSeparablePassesAndOnePassPerLevel) {
  const FilterSpec spec = test::blurMipSpec();
  const PassGraph g = planPasses(spec);
  ASSERT_EQ(pyramidLevels(spec), 6);  // ceil(log2 32) + 1
  EXPECT_EQ(passNames(g),
            (std::vector<std::string>{"moments", "blur_h", "blur_v", "mip1", "mip2", "mip3", "mip4", "mip5", "shade"}));
  EXPECT_EQ(image(g, "moments")->mipLevels, 6);
  EXPECT_EQ(image(g, "moments")->format, ImageFormat::RGBA32F);  // power_cdf: 3 channels stored as 4
  EXPECT_EQ(pass(g, "blur_h").bindings.at(1).image, "moments_tmp");
  EXPECT_EQ(pass(g, "blur_v").bindings.at(1).image, "moments");
  EXPECT_EQ(pass(g, "mip4").bindings.at(0).level, 3);
  EXPECT_EQ(pass(g, "mip4").spirv, "mip.spv");  // every level runs the same shader
  EXPECT_EQ(pass(g, "mip4").dispatch.size.shift, 4);
}

TEST(Planner, UnormStorageUsesUnormFormats) {
  FilterSpec spec = test::blurMipSpec();
  spec.moments.warp = Warp::Linear;
  spec.storage.format = StorageFormat::Unorm16;
  EXPECT_EQ(image(planPasses(spec), "moments")->format, ImageFormat::RG16Unorm);
}

// Every binding names an image, or (a storage buffer) one of the manifest's buffers.
TEST(Planner, EveryPassSourceIsAnEmbeddedTemplateAndEveryBindingAnImage) {
  for (const FilterSpec& spec :
       {test::pcfSpec(), test::vssmInt32Spec(), test::layeredEvsmSpec(), test::blurMipSpec()}) {
    const PassGraph g = planPasses(spec);
    ASSERT_EQ(g.sources.size(), g.manifest.passes.size());
    for (const auto& s : g.sources) EXPECT_FALSE(templates::find(s.templatePath).empty()) << s.templatePath;
    for (const auto& p : g.manifest.passes)
      for (const auto& b : p.bindings) {
        if (b.access == Access::Uniform) continue;
        if (b.access == Access::StorageBufferRead) {
          const auto& bufs = g.manifest.buffers;
          EXPECT_TRUE(std::any_of(bufs.begin(), bufs.end(), [&](const auto& d) { return d.name == b.image; }))
              << p.name << " binds buffer " << b.image;
          continue;
        }
        EXPECT_NE(image(g, b.image), nullptr) << p.name << " binds " << b.image;
      }
  }
}

TEST(Planner, PyramidLevelsCoverTheWidestKernel) {
  FilterSpec s;
  s.kernel.maxTexels = 64;
  EXPECT_EQ(pyramidLevels(s), 7);
  s.kernel.maxTexels = 65;
  EXPECT_EQ(pyramidLevels(s), 8);
  s.kernel.maxTexels = 256;
  EXPECT_EQ(pyramidLevels(s), 9);
  s.kernel.maxTexels = 4096;       // a SAT kernel's default: the top level's cells are 256 wide
  EXPECT_EQ(pyramidLevels(s), 9);  // clamped (kMaxPyramidLevel), fits maps from 256^2 up
}

}  // namespace
}  // namespace shadowc

namespace shadowc {
namespace {

TEST(Planner, LloydPlacementRunsFirstAndFeedsMomentsAndShade) {
  FilterSpec spec = test::layeredEvsmSpec();
  spec.moments.split = SplitPlacement::Lloyd;
  spec.moments.lloydIterations = 5;
  const PassGraph g = planPasses(spec);
  ASSERT_GE(g.manifest.passes.size(), 3u);
  EXPECT_EQ(g.manifest.passes[0].name, "lloyd");
  EXPECT_EQ(g.manifest.passes[1].name, "moments");
  const ImageDesc* splits = image(g, "splits");
  ASSERT_NE(splits, nullptr);
  EXPECT_EQ(splits->format, ImageFormat::R32F);
  // Wide enough for layers + 1 = 4 texels on the smallest (64) map.
  EXPECT_GE(extentOf(splits->size, 64, 1, 1)[0], 4u);
  EXPECT_EQ(g.manifest.passes[1].bindings.at(2).image, "splits");
  EXPECT_EQ(pass(g, "shade").bindings.back().binding, 8u);
  EXPECT_EQ(pass(g, "shade").bindings.back().image, "splits");
  // One workgroup: a 1x1 extent at any map size.
  EXPECT_EQ(extentOf(g.manifest.passes[0].dispatch.size, 4096, 1, 1), (std::array<uint32_t, 2>{1, 1}));
}

TEST(Planner, LloydWithOneLayerPlansNothingExtra) {
  FilterSpec spec = test::layeredEvsmSpec();
  spec.moments.split = SplitPlacement::Lloyd;
  spec.moments.layers = 1;
  spec.moments.splits = {0.0, 1.0};
  EXPECT_EQ(image(planPasses(spec), "splits"), nullptr);
}

}  // namespace
}  // namespace shadowc

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

TEST(Planner, VssmInt32PlansMomentsSatMinMaxShadeInOrder) {
  const FilterSpec spec = test::vssmInt32Spec();
  const PassGraph g = planPasses(spec);
  std::vector<std::string> expected = {"moments", "sat_rows", "sat_columns", "minmax0"};
  for (int k = 1; k < pyramidLevels(spec); ++k) expected.push_back("minmax" + std::to_string(k));
  expected.push_back("shade");
  EXPECT_EQ(passNames(g), expected);
  ASSERT_NE(image(g, "sat"), nullptr);
  EXPECT_EQ(image(g, "sat")->format, ImageFormat::RG32UI);
  EXPECT_EQ(image(g, "moments")->format, ImageFormat::RG32F);
  EXPECT_EQ(image(g, "minmax")->format, ImageFormat::RG32F);
  EXPECT_EQ(image(g, "minmax")->mipLevels, pyramidLevels(spec));
  EXPECT_EQ(pass(g, "sat_rows").dispatch.mode, DispatchMode::Rows);
  EXPECT_EQ(pass(g, "sat_columns").dispatch.mode, DispatchMode::Columns);
  EXPECT_EQ(pass(g, "sat_columns").bindings.at(0).access, Access::StorageReadWrite);
  // minmaxK reads level K-1 and writes level K, dispatched over the level's extent.
  const Pass& m3 = pass(g, "minmax3");
  EXPECT_EQ(m3.bindings.at(0).level, 2);
  EXPECT_EQ(m3.bindings.at(1).level, 3);
  EXPECT_EQ(m3.dispatch.size.shift, 3);
  // Shade binds the fixed table: 5 moments, 6 sat, 7 minmax.
  const Pass& s = pass(g, "shade");
  ASSERT_EQ(s.bindings.size(), 8u);
  EXPECT_EQ(s.bindings[5].image, "moments");
  EXPECT_EQ(s.bindings[6].image, "sat");
  EXPECT_EQ(s.bindings[7].image, "minmax");
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

TEST(Planner, EveryPassSourceIsAnEmbeddedTemplateAndEveryBindingAnImage) {
  for (const FilterSpec& spec :
       {test::pcfSpec(), test::vssmInt32Spec(), test::layeredEvsmSpec(), test::blurMipSpec()}) {
    const PassGraph g = planPasses(spec);
    ASSERT_EQ(g.sources.size(), g.manifest.passes.size());
    for (const auto& s : g.sources) EXPECT_FALSE(templates::find(s.templatePath).empty()) << s.templatePath;
    for (const auto& p : g.manifest.passes)
      for (const auto& b : p.bindings) {
        if (b.access == Access::Uniform) continue;
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
  s.kernel.maxTexels = 1e9;
  EXPECT_EQ(pyramidLevels(s), 13);  // clamped
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

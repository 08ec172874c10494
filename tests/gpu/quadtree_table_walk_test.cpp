// `traversal: table` (Algorithm 2 of vssm-yang2010 with the planner's Next/Child tables, read
// from the manifest's buffer) computes the visibility of `traversal: computed` (Next/Child
// derived from the node): both walks visit the same nodes in the same order and do the same
// arithmetic on each, so the images are bit-identical (docs/dsl.md says so; no pixel may differ).
// The sibling's tolerance, RMSE 1e-6 (8 ulps of 1.0, 1.19e-7 each), is what "moved" means there.
// Two filters (the sample at height 3, whose PCF leaves are deferred; heights 5 / 4 for the
// kernel and the blocker, resolved in place and sharing the taller tree's table) on duck and
// two_planes (64x64 screen, 256 map; duck's curved occluder is where kernels descend, two_planes'
// flat one mostly has them accepted at the root; measured: bit-identical on all four). The sibling breaks the root's
// Child in the buffer the harness uploads and must move the image past the tolerance: the shader really walks the
// table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gpu/accuracy_harness.h"
#include "gpu/vulkan_fixture.h"
#include "plan/quadtree_tables.h"

namespace shadowc::test {
namespace {

using QuadtreeTableWalkTest = VulkanTest;

constexpr uint32_t kScreen = 64, kMap = 256;
constexpr double kTolerance = 1e-6;

struct Case {
  const char* label;
  std::string kernel, blocker;
};
std::vector<Case> cases() {
  return {{"h3", "quadtree(height: 3, traversal: {}, lit_threshold: 0.0001)", "moments"},
          {"h5", "quadtree(height: 5, traversal: {})", "moments(quadtree(height: 4))"}};
}

const CompiledFilter* compiled(const Case& c, const std::string& traversal) {
  std::string text =
      withSetting(sampleSource("vssm_quadtree_table"), "kernel", fmt::format(fmt::runtime(c.kernel), traversal));
  text = withSetting(text, "blocker", c.blocker);
  return compileFilterCached(fmt::format("qt_walk_{}_{}", c.label, traversal), text);
}

std::vector<float> visibility(rt::VulkanContext& ctx, const CompiledPasses& passes, const std::string& scene) {
  return rt::runOnScene(ctx, passes, sceneCase(ctx, scene, kMap, kScreen, 2)).outputs.visibility;
}

struct Difference {
  double rmse = 0;
  size_t differing = 0;
};
Difference compare(const std::vector<float>& a, const std::vector<float>& b) {
  Difference d;
  if (a.size() != b.size() || a.empty()) return {INFINITY, a.size()};
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double e = double(a[i]) - double(b[i]);
    sum += std::isnan(e) ? INFINITY : e * e;
    d.differing += a[i] != b[i];
  }
  d.rmse = std::sqrt(sum / double(a.size()));
  return d;
}

TEST_F(QuadtreeTableWalkTest, TableWalkImagesEqualTheComputedWalks) {
  for (const Case& c : cases()) {
    const CompiledFilter* table = compiled(c, "table");
    const CompiledFilter* computed = compiled(c, "computed");
    ASSERT_TRUE(table && computed);
    ASSERT_EQ(table->passes.manifest.buffers.size(), 1u) << c.label;  // the walk has its table
    ASSERT_TRUE(computed->passes.manifest.buffers.empty()) << c.label;
    for (const char* scene : {"duck", "two_planes"}) {
      const std::vector<float> vt = visibility(context(), table->passes, scene);
      const std::vector<float> vc = visibility(context(), computed->passes, scene);
      const Difference d = compare(vt, vc);
      fmt::print("{} on {}: table vs computed RMSE {:.3g}, {} of {} pixels differ\n", c.label, scene, d.rmse,
                 d.differing, vt.size());
      EXPECT_EQ(d.differing, 0u) << c.label << " on " << scene << ": the walks are not bit-identical";
      // Not a trivially lit frame: the walks see shadow.
      ASSERT_FALSE(vc.empty());
      EXPECT_LT(*std::min_element(vc.begin(), vc.end()), 0.5f) << c.label << " on " << scene;
    }
  }
}

// Sibling: the root's Child set to Null ends every walk that descends at the root, so a
// non-planar kernel adds nothing (visibility 1), which the image must show.
TEST_F(QuadtreeTableWalkTest, ABrokenChildInTheBufferChangesTheImage) {
  const Case c = cases()[0];
  const CompiledFilter* table = compiled(c, "table");
  ASSERT_TRUE(table);
  CompiledPasses broken = table->passes;
  ASSERT_EQ(broken.manifest.buffers.size(), 1u);
  BufferDesc& b = broken.manifest.buffers[0];
  ASSERT_EQ(b.name, kQuadtreeTableBuffer);
  ASSERT_GT(b.values.size(), 8u);
  b.values[2] = -1;  // node 0 (the root): its Child (node 1) becomes Null
  // duck: its curved occluder makes non-planar kernels (two_planes' flat ones are mostly accepted
  // at the root, where no Child is read).
  const Difference d = compare(visibility(context(), broken, "duck"), visibility(context(), table->passes, "duck"));
  fmt::print("broken Child: RMSE {:.3g}, {} pixels differ\n", d.rmse, d.differing);
  EXPECT_GT(d.rmse, kTolerance);
}

}  // namespace
}  // namespace shadowc::test

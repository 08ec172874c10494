// `shadowc analyze` / `shadowc plan` (planning/, docs/planning.md) on small screens and maps:
// the statistics against closed forms, the features each kind of scene plans to, pruning down
// to the manifest, GLSL and SPIR-V, the comments, and the three error cases.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/glm.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "driver/driver.h"
#include "planning/fresh_validate.h"
#include "planning/planner.h"
#include "runtime/images/atomic_file.h"
#include "runtime/vulkan/vulkan_context.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

constexpr uint32_t kScreen = 64, kMap = 256;
constexpr int kSamples = 8;

rt::VulkanContext& context() {
  static rt::VulkanContext ctx;
  return ctx;
}

// two_planes (one flat occluder at y = 2 over the floor, light at y = 6) with another light size.
std::string twoPlanesWithLight(double size, const std::string& tag) {
  nlohmann::json j = nlohmann::json::parse(rt::builtinSceneJson("two_planes"));
  j["light"]["size"] = size;
  j["name"] = "two_planes_light_" + tag;
  const auto path = test::freshTempDir("planning_" + tag) / "scene.json";
  rt::writeFileAtomically(path, j.dump(2));
  return path.string();
}

// The written plan validated afresh on `scene` at the planner's settings (fresh_validate.h).
double freshRmse(const planning::PlanResult& p, const std::string& scene) {
  const double rmse = test::validateWrittenPlan(context(), p.text, scene, kScreen, kMap, kSamples).rmse;
  fmt::print("{} on {}: fresh validate {:.5f}, the planner's measurement {:.5f}\n", p.chosen.name, scene, rmse,
             p.measured.worstRmse);
  return rmse;
}

planning::PlanResult planFor(const std::vector<std::string>& scenes, double maxRmse) {
  planning::PlanRequest r;
  r.scenes = scenes;
  r.maxRmse = maxRmse;
  r.screen = kScreen;
  r.map = kMap;
  r.samples = kSamples;
  r.warmup = 0;
  r.runs = 1;
  r.filterName = "planned_test";
  return planning::plan(context(), r, planning::loadModel());
}

driver::Artifact compiled(const std::string& text) {
  const driver::Result r = driver::compileSource(text, "planned.shadow");
  EXPECT_TRUE(r.artifact) << r.log << text;
  return *r.artifact;
}

bool anyFileHas(const driver::Artifact& a, const std::string& suffix, const std::string& needle) {
  for (const auto& f : a.files)
    if (f.name.size() >= suffix.size() && f.name.compare(f.name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
        f.bytes.find(needle) != std::string::npos)
      return true;
  return false;
}

// A 32-bit float constant in any .spv file (OpConstant words hold the value's bits).
bool spirvHoldsFloat(const driver::Artifact& a, float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, 4);
  for (const auto& f : a.files) {
    if (f.name.size() < 4 || f.name.substr(f.name.size() - 4) != ".spv") continue;
    for (size_t i = 20; i + 4 <= f.bytes.size(); i += 4) {
      uint32_t w;
      std::memcpy(&w, f.bytes.data() + i, 4);
      if (w == bits) return true;
    }
  }
  return false;
}

// A scene rasterized for analysis only (no Embree trace) at the test's sizes.
rt::SceneSettings analysisSettings(const std::string& scene) {
  rt::SceneSettings s;
  s.scene = scene;
  s.screen = kScreen;
  s.map = kMap;
  s.traceReference = false;
  return s;
}

TEST(Analysis, TwoPlanesPenumbraMatchesTheClosedForm) {
  const rt::SceneSettings s = analysisSettings("two_planes");
  const auto prepared = rt::prepareScene(context(), s);
  EXPECT_TRUE(prepared->reference.empty());  // analysis needs no reference
  const planning::SceneStats st = planning::analyzeScene(*prepared);
  // Occluder at view z 4, floor at z 6, light width 1: w = W (zr - zb) / (zb 2 zr tanHalfFov) uv.
  const double tanHalf = prepared->setup.frame.lightParams[0];
  const double expected = 1.0 * (6.0 - 4.0) / (4.0 * 2.0 * 6.0 * tanHalf) * kMap;
  ASSERT_GT(st.penumbra, 0u);
  EXPECT_NEAR(st.penumbraTexels.p50, expected, 0.01 * expected);
  EXPECT_EQ(st.contact, 0u);                     // the occluder is 2 units above the floor
  EXPECT_DOUBLE_EQ(st.multiDepthFraction(), 0);  // one flat occluder: one depth cluster
  // Sibling: twice the light, twice the penumbra (the check above can fail).
  const auto big = rt::prepareScene(context(), [&] {
    rt::SceneSettings b = s;
    b.scene = twoPlanesWithLight(2.0, "double");
    return b;
  }());
  EXPECT_NEAR(planning::analyzeScene(*big).penumbraTexels.p50, 2 * expected, 0.02 * expected);
  EXPECT_GT(std::abs(planning::analyzeScene(*big).penumbraTexels.p50 - expected), 0.5 * expected);
}

// sun_two_planes: a 4-degree sun straight down over an edge 1 above the floor. The orthographic
// form (frame_ortho.glsl): penumbra = (z_r - z_b) 2 tan(angle / 2) world units = 1 * 2 tan(2 deg),
// over a texel of 2 halfExtent / map. The perspective formula read this scene's halfExtent as a
// tan(fov / 2) and gave widths off by orders of magnitude.
TEST(Analysis, SunPenumbraTakesTheOrthographicForm) {
  const rt::SceneSettings s = analysisSettings("sun_two_planes");
  const auto prepared = rt::prepareScene(context(), s);
  ASSERT_TRUE(prepared->setup.orthographic);
  const planning::SceneStats st = planning::analyzeScene(*prepared);
  const double halfExtent = prepared->setup.halfExtent;
  const double expected = 1.0 * 2 * std::tan(glm::radians(2.0)) / (2 * halfExtent) * kMap;
  ASSERT_GT(st.penumbra, 0u);
  EXPECT_EQ(st.lightShape, "sun");
  EXPECT_NEAR(st.penumbraTexels.p50, expected, 0.05 * expected);
  EXPECT_EQ(st.contact, 0u);  // the edge is 1 above the floor
  EXPECT_NE(planning::formatSummary(st).find("sun angle 4 deg"), std::string::npos) << planning::formatSummary(st);
  // Sibling: an 8-degree sun, twice the slope (tan 4 / tan 2 = 2.003), twice the penumbra.
  nlohmann::json j = nlohmann::json::parse(rt::builtinSceneJson("sun_two_planes"));
  j["light"]["angle"] = 8.0;
  j["name"] = "sun_two_planes_8deg";
  const auto path = test::freshTempDir("planning_sun8") / "scene.json";
  rt::writeFileAtomically(path, j.dump(2));
  rt::SceneSettings wide = s;
  wide.scene = path.string();
  const double p50 = planning::analyzeScene(*rt::prepareScene(context(), wide)).penumbraTexels.p50;
  EXPECT_NEAR(p50, 2.003 * expected, 0.1 * expected);
  EXPECT_GT(std::abs(p50 - expected), 0.5 * expected);
}

// small_penumbra's penumbrae are a fraction of a texel at 256^2; the analysis names the map size at
// which the 10th percentile spans 2 texels, and that is a claim about a measurement: analyzed
// again at that size the p10 is 2 texels or more, and at half of it less (the least such
// doubling). Sibling: two_planes' penumbrae are wide already, so its answer is its own map.
TEST(Analysis, SmallPenumbraNamesTheMapSizeThatResolvesIt) {
  const planning::SceneStats st =
      planning::analyzeScene(*rt::prepareScene(context(), analysisSettings("small_penumbra")));
  ASSERT_GT(st.penumbra, 20u) << "too few penumbra receivers to have a 10th percentile";
  ASSERT_LT(st.penumbraTexels.p10, 2.0);
  const uint32_t wanted = st.mapForPenumbraTexels();
  ASSERT_GT(wanted, kMap);
  auto p10At = [&](uint32_t map) {
    rt::SceneSettings s = analysisSettings("small_penumbra");
    s.map = map;
    return planning::analyzeScene(*rt::prepareScene(context(), s)).penumbraTexels.p10;
  };
  EXPECT_GE(p10At(wanted), 2.0) << "analyzed at the named " << wanted << "^2";
  EXPECT_LT(p10At(wanted / 2), 2.0) << "half of it already resolves the penumbra: not the least";
  EXPECT_NE(planning::formatSummary(st).find(fmt::format("a {}^2 map makes it 2 texels", wanted)), std::string::npos)
      << planning::formatSummary(st);
  EXPECT_EQ(planning::toJson(st)["map_for_p10_penumbra"]["map_size"].get<uint32_t>(), wanted);
  const planning::SceneStats wide =
      planning::analyzeScene(*rt::prepareScene(context(), analysisSettings("two_planes")));
  ASSERT_GE(wide.penumbraTexels.p10, 2.0);
  EXPECT_EQ(wide.mapForPenumbraTexels(), kMap);
}

TEST(Analysis, ContactSceneHasContactAndSeveralDepths) {
  const rt::SceneSettings s = analysisSettings("contact");
  const planning::SceneStats st = planning::analyzeScene(*rt::prepareScene(context(), s));
  EXPECT_GT(st.contactFraction(), 0.001);
  EXPECT_GT(st.multiDepthFraction(), 0.0);
  EXPECT_GT(st.slopeDegrees.max, 60.0);  // box sides
  const nlohmann::ordered_json j = planning::toJson(st);
  EXPECT_EQ(j["contact"]["receivers"].get<uint64_t>(), st.contact);
  EXPECT_NE(planning::formatSummary(st).find("% of penumbrae < 1.5 texels"), std::string::npos);
}

TEST(Plan, PointLikeLightHasNoBlockerSearchSatOrPenumbraKernel) {
  const std::string scene = twoPlanesWithLight(0.002, "point");
  const planning::PlanResult p = planFor({scene}, 0.2);
  EXPECT_FALSE(p.chosen.blocker);
  EXPECT_FALSE(p.chosen.sat);
  EXPECT_FALSE(p.chosen.penumbraKernel);
  EXPECT_LE(freshRmse(p, scene), 0.2);
  EXPECT_NE(p.text.find("# blocker search dropped: 100.0 % of penumbrae < 1.5 texels"), std::string::npos) << p.text;
  // Pruned down to the manifest: no representation passes, no SAT or moments image or binding.
  const driver::Artifact a = compiled(p.text);
  for (const Pass& pass : a.manifest.passes) EXPECT_EQ(pass.kind, "shade") << pass.name;
  for (const ImageDesc& image : a.manifest.images) {
    EXPECT_EQ(image.name.find("sat"), std::string::npos);
    EXPECT_EQ(image.name.find("moments"), std::string::npos);
  }
  EXPECT_FALSE(anyFileHas(a, ".glsl", "shadowc_summedArea"));
  EXPECT_FALSE(anyFileHas(a, ".spv", "shadowc_summedArea"));
  // Sibling: everything on has those passes and that code, so the checks above can fail.
  const driver::Artifact all = compiled(planning::describeCandidate(planning::everythingOn(), {}));
  EXPECT_GT(all.manifest.passes.size(), 1u);
  EXPECT_TRUE(anyFileHas(all, ".glsl", "shadowc_summedArea"));
  EXPECT_TRUE(anyFileHas(all, ".spv", "shadowc_summedArea"));
}

// A sun scene plans to a `light sun` filter that meets its bound (measured at these settings:
// pcf_grid3 0.043 at 64^2 / 512^2; at 256^2 the hard shadow misses 0.05 with 0.075), and the
// written description compiles with the orthographic frame.
TEST(Plan, SunScenePlansASunFilterWithinTheBound) {
  const planning::PlanResult p = planFor({"sun_two_planes"}, 0.06);
  EXPECT_LE(freshRmse(p, "sun_two_planes"), 0.06);
  EXPECT_NE(p.text.find("light      sun(angle: scene)"), std::string::npos) << p.text;
  EXPECT_TRUE(anyFileHas(compiled(p.text), ".glsl", "shadowc_worldToUV"));  // only frame_ortho.glsl has it
  // Sibling: a bound below what any variant reaches there is refused, so the check above is real.
  EXPECT_THROW(planFor({"sun_two_planes"}, 1e-4), std::exception);
}

TEST(Plan, RaisingTheLightSizeChangesThePlan) {
  const planning::PlanResult small = planFor({twoPlanesWithLight(0.002, "small")}, 0.2);
  const planning::PlanResult large = planFor({twoPlanesWithLight(1.0, "large")}, 0.05);
  EXPECT_FALSE(small.chosen.blocker);
  EXPECT_TRUE(large.chosen.blocker) << large.chosen.name;
  EXPECT_NE(small.chosen.name, large.chosen.name);
  EXPECT_NE(large.text.find("# blocker search kept: "), std::string::npos) << large.text;
}

// large_penumbra: one flat occluder close to a 4-unit light, nothing within the contact distance;
// PCSS's taps cannot follow its penumbrae, so the plan is a VSSM variant (where a contact path
// and a fallback could exist).
// Bound: a little above the best reachable RMSE there (0.066 at these settings, measured against
// the shadowing-term reference, docs/scenes.md "Ground truth").
TEST(Plan, NoContactNoLayersNoFallbackOnOneFlatOccluder) {
  const planning::PlanResult p = planFor({"large_penumbra"}, 0.075);
  EXPECT_FALSE(p.chosen.contact);
  EXPECT_FALSE(p.chosen.fallback);
  EXPECT_EQ(p.chosen.layers, 1);
  EXPECT_LE(freshRmse(p, "large_penumbra"), 0.075);
  EXPECT_NE(p.text.find("# contact path dropped: 0.00 % of receivers within 0.01 of a blocker"), std::string::npos)
      << p.text;
  EXPECT_NE(
      p.text.find("# PCF fallback dropped: 0.0 % of penumbra kernel regions hold occluders at >= 2 distinct depths"),
      std::string::npos)
      << p.text;
  EXPECT_NE(p.text.find("# layers dropped: 0.0 %"), std::string::npos) << p.text;
  // One comment per feature, each naming its feature once (but cascades: a spot light has none).
  size_t comments = 0;
  for (size_t pos = p.text.find("\n    # "); pos != std::string::npos; pos = p.text.find("\n    # ", pos + 1))
    ++comments;
  EXPECT_EQ(comments, std::size(planning::kFeatures) - 1);
  EXPECT_EQ(p.text.find("# cascades "), std::string::npos) << p.text;
  for (planning::Feature f : planning::kFeatures)
    if (f != planning::Feature::Cascades) {
      EXPECT_NE(p.text.find(std::string("# ") + planning::featureName(f) + " "), std::string::npos)
          << planning::featureName(f);
    }
  // No contact code in the GLSL or SPIR-V; the sibling with the contact path has it, so the
  // checks can fail.
  const driver::Artifact planned = compiled(p.text);
  ASSERT_TRUE(p.chosen.sat) << p.chosen.name;  // a VSSM plan, where a contact path could exist
  std::string withContact = p.text;
  const size_t at = withContact.find("    contact    none\n");
  ASSERT_NE(at, std::string::npos) << p.text;
  withContact.replace(at, 19, "    contact    pcf(size: 3x3, epsilon: 0.0123)\n");
  const driver::Artifact contact = compiled(withContact);
  EXPECT_FALSE(anyFileHas(planned, ".glsl", "SHADOWC_CONTACT_EPSILON"));
  EXPECT_FALSE(anyFileHas(planned, ".glsl", "shadowc_pcfBilinearGrid"));
  EXPECT_TRUE(anyFileHas(contact, ".glsl", "shadowc_pcfBilinearGrid"));
  EXPECT_FALSE(spirvHoldsFloat(planned, 0.0123f));
  EXPECT_TRUE(spirvHoldsFloat(contact, 0.0123f));
  EXPECT_LT(planned.file("shade.spv")->size(), contact.file("shade.spv")->size());
}

TEST(Plan, SeveralScenesPlanOneFilterThatServesAll) {
  const std::string small = twoPlanesWithLight(0.002, "multi_small");
  const planning::PlanResult p = planFor({small, "two_planes"}, 0.05);
  EXPECT_LE(freshRmse(p, small), 0.05);
  EXPECT_LE(freshRmse(p, "two_planes"), 0.05);
  EXPECT_TRUE(p.chosen.blocker);  // the big light needs it even though the small one does not
  EXPECT_NE(p.text.find("(worst scene: two_planes)"), std::string::npos) << p.text;
}

TEST(PlanCli, WritesACheckedDescription) {
  const auto dir = test::freshTempDir("plan_cli");
  const auto out = dir / "two planes.shadow";
  const test::CliResult r = test::runShadowc(
      "plan --scene two_planes --max-rmse 0.05 --screen 64 --map 256 --samples 8 --runs 1 --warmup 0 -o '" +
      out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const test::CliResult check = test::runShadowc("check '" + out.string() + "'");
  EXPECT_EQ(check.code, 0) << check.err;
  EXPECT_NE(test::readFile(out).find("filter two_planes {"), std::string::npos);
}

// With a cost profile the confirmations are timed by its prediction from their exact work counts
// (docs/cost.md): two runs print the same predicted times and write the same plan whatever the
// machine's load; the sibling, a profile that prices every fetch ten times higher, predicts more.
TEST(PlanCli, CostProfileTimesByThePredictionAndRepeats) {
  const auto dir = test::freshTempDir("plan_cost");
  const std::string profile = (test::sourceDir() / "samples/cost/lavapipe.json").string();
  auto plan = [&](const std::string& prof, const std::string& name) {
    return test::runShadowc(
        "plan --scene two_planes --max-rmse 0.05 --screen 64 --map 256 --samples 4 --runs 1 "
        "--warmup 0 --cost-profile " +
        prof + " -o " + (dir / name).string());
  };
  auto predictedLine = [](const std::string& out) {
    const size_t at = out.find("worst scene's time");
    return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
  };
  const test::CliResult a = plan(profile, "a.shadow"), b = plan(profile, "b.shadow");
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_NE(a.out.find("predicted on lavapipe"), std::string::npos) << a.out;
  EXPECT_EQ(predictedLine(a.out), predictedLine(b.out));
  // The same plan: every line but the first (the command, which names its own -o) and the filter
  // name (the file's stem).
  auto body = [&](const std::string& name) {
    std::string t = test::readFile(dir / name);
    t = t.substr(t.find('\n') + 1);
    const size_t f = t.find("filter ");
    return t.substr(0, f) + t.substr(t.find(' ', f + 7));
  };
  EXPECT_EQ(body("a.shadow"), body("b.shadow"));
  nlohmann::json costly = nlohmann::json::parse(test::readFile(profile));
  for (auto& [field, c] : costly["shade"]["ms_per_mcount"].items()) c = c.get<double>() * 10 + 1;
  const auto costlyPath = dir / "costly.json";
  std::ofstream(costlyPath) << costly.dump();
  const test::CliResult c = plan(costlyPath.string(), "c.shadow");
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_FALSE(predictedLine(c.out).empty());
  EXPECT_NE(predictedLine(c.out), predictedLine(a.out)) << c.out;
}

TEST(PlanCli, UnreachableBoundNamesTheBestReachable) {
  const test::CliResult r = test::runShadowc(
      "plan --scene two_planes --max-rmse 0.00001 --screen 64 --map 256 --samples 8 --runs 1 --warmup 0 -o "
      "/tmp/x.shadow");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--max-rmse 1e-05 is unreachable on two_planes: the best reachable bound is "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("(variant "), std::string::npos) << r.err;
  // two_planes' penumbrae are wide at 256^2: no map size is named (the sibling of the test below).
  EXPECT_EQ(r.err.find("10th-percentile penumbra"), std::string::npos) << r.err;
}

// On small_penumbra the bound is out of reach because the penumbrae are a fraction of a texel:
// the message says which map size would resolve them (the analysis's, checked against a second
// analysis in Analysis.SmallPenumbraNamesTheMapSizeThatResolvesIt). Sibling: the two_planes
// message of the test above, whose penumbrae the map resolves, names no map size.
TEST(PlanCli, UnreachableBoundNamesTheMapSizeThatResolvesThePenumbra) {
  const test::CliResult r = test::runShadowc(
      "plan --scene small_penumbra --max-rmse 0.00001 --screen 64 --map 256 --samples 4 --runs 1 --warmup 0 -o "
      "/tmp/x.shadow");
  EXPECT_EQ(r.code, 1);
  const std::regex hint(R"(the 10th-percentile penumbra on small_penumbra is [0-9.]+ texels at 256\^2, narrower )"
                        R"(than any filter can shape: a (\d+)\^2 map makes it 2 texels \(plan with --map \1\))");
  std::smatch m;
  EXPECT_TRUE(std::regex_search(r.err, m, hint)) << r.err;
}

// Map size as a planned resource (docs/planning.md "Map size"): tiny_penumbra's penumbrae are a third
// of a texel at 512^2, so no filter meets 0.04 there; with --max-map the plan moves to a larger map,
// writes it as the filter's `resolution`, and validate renders that map by itself and meets the bound.
// Siblings: the same file rendered at 512^2 misses it (the map, not the filter, made the difference),
// and without --max-map the plan fails naming the map size.
TEST(PlanCli, MaxMapPlansTheLargerMapThatMeetsTheBound) {
  const auto dir = test::freshTempDir("plan_max_map");
  const std::string out = (dir / "tiny.shadow").string();
  // 0.04 and 2048^2 rather than the 0.03 and 4096^2 docs/planning.md measures at full size: the same
  // search on a quarter of the texels (under ASan this test is among the slowest).
  const std::string common =
      " --scene tiny_penumbra --max-rmse 0.04 --screen 128 --map 512 --samples 8 --runs 1 --warmup 0";
  const test::CliResult r = test::runShadowc("plan" + common + " --max-map 2048 -o " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = test::readFile(out);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(\n    resolution (\d+)\n)"))) << text;
  const int planned = std::stoi(m[1]);
  EXPECT_GT(planned, 512);
  EXPECT_LE(planned, 2048);
  EXPECT_NE(text.find("no variant met the bound at 512^2"), std::string::npos) << text;
  auto validate = [&](const std::string& extra) {
    const std::string json = (dir / "v.json").string();
    const test::CliResult v = test::runShadowc("validate " + out +
                                               " --scene tiny_penumbra --screen 128 --samples 8 --runs 1 --warmup 0 "
                                               "--json " +
                                               json + extra);
    EXPECT_EQ(v.code, 0) << v.err;
    return nlohmann::json::parse(test::readFile(json));
  };
  const nlohmann::json atPlanned = validate("");
  EXPECT_EQ(atPlanned["map_size"], planned);
  EXPECT_LE(atPlanned["metrics"]["rmse"].get<double>(), 0.04);
  EXPECT_GT(validate(" --map 512")["metrics"]["rmse"].get<double>(), 0.04);
  const test::CliResult without = test::runShadowc("plan" + common + " -o " + out);
  EXPECT_EQ(without.code, 1);
  EXPECT_NE(without.err.find("(plan with --map "), std::string::npos) << without.err;
}

TEST(PlanCli, MaxMapBelowTheMapIsOneMessageBeforeAnyWork) {
  const test::CliResult r =
      test::runShadowc("plan --scene tiny_penumbra --max-rmse 0.03 --map 1024 --max-map 512 -o /tmp/x.shadow");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--max-map 512 must be at least --map 1024"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("preparing the scenes"), std::string::npos) << r.err;
}

TEST(PlanCli, UnknownSceneIsOneMessage) {
  const test::CliResult r = test::runShadowc("plan --scene no_such_scene --max-rmse 0.1 -o /tmp/x.shadow");
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("no_such_scene"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(PlanCli, BudgetNoVariantMeets) {
  const test::CliResult r = test::runShadowc(
      "plan --scene two_planes --budget-ms 0.000001 --screen 64 --map 256 --samples 8 --runs 1 --warmup 0 -o "
      "/tmp/x.shadow");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no variant meets --budget-ms 1e-06 on two_planes: the fastest is "), std::string::npos)
      << r.err;
}

TEST(AnalyzeCli, PrintsAndWritesJson) {
  const auto json = test::freshTempDir("analyze_cli") / "stats.json";
  const test::CliResult r =
      test::runShadowc("analyze --scene two_planes --screen 64 --map 256 --json '" + json.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("penumbra width, texels"), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(test::readFile(json));
  EXPECT_EQ(j["scene"], "two_planes");
  EXPECT_GT(j["penumbra_texels"]["p50"].get<double>(), 1.0);
}

}  // namespace
}  // namespace shadowc

// Normalization: every default explicit, defaults that depend on other settings, splits,
// precision limits (both sides of each boundary), and the JSON's fixed key order.
#include <gtest/gtest.h>

#include <cmath>

#include "spec/load_filter.h"
#include "spec/precision.h"
#include "spec/print_filter.h"
#include "support/test_support.h"

using namespace shadowc;

namespace {
FilterSpec load(const std::string& body) {
  const LoadResult r = loadFilterSource("filter t {\n" + body + "\n}\n", "t.shadow");
  EXPECT_EQ(r.errorCount(), 0) << formatDiagnostics(r);
  return r.spec.value_or(FilterSpec{});
}
std::vector<std::string> codes(const std::string& body, bool werror = false) {
  LoadOptions o;
  o.warningsAsErrors = werror;
  const LoadResult r = loadFilterSource("filter t {\n" + body + "\n}\n", "t.shadow", o);
  std::vector<std::string> out;
  for (const Diagnostic& d : r.diagnostics) out.push_back(d.code);
  return out;
}
using Codes = std::vector<std::string>;
}  // namespace

TEST(Normalize, EmptyFilterIsAHardShadow) {
  const FilterSpec s = load("");
  EXPECT_EQ(s.representation, Representation::Depth);
  EXPECT_EQ(s.light.shape, LightShape::Rect);
  EXPECT_TRUE(s.light.sizeFromScene);
  EXPECT_EQ(s.kernel.size, KernelSize::Fixed);
  EXPECT_EQ(s.kernel.fixedTexels, 1);
  EXPECT_EQ(s.sampling.pattern, PcfPattern::Grid);
  EXPECT_EQ(s.sampling.gridN, 1);
  EXPECT_EQ(s.moments.splits, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(s.mapSize, 2048);
}

TEST(Normalize, KernelAndSamplingDefaultsFollowTheBlocker) {
  const FilterSpec pcss = load("blocker search(16)");
  EXPECT_EQ(pcss.kernel.size, KernelSize::Penumbra);
  EXPECT_EQ(pcss.sampling.pattern, PcfPattern::Poisson);
  EXPECT_EQ(pcss.sampling.rotation, Rotation::Stable);
  const FilterSpec pcf = load("sampling grid(4x4)");
  EXPECT_EQ(pcf.kernel.fixedTexels, 5);  // 4 rounded up to odd
  const FilterSpec fixed = load("kernel fixed(7)");
  EXPECT_EQ(fixed.sampling.gridN, 7);
}

TEST(Normalize, OrderOfSettingsDoesNotMatter) {
  const std::string a = "moments linear\nstorage sat(int32)\nblocker moments\nkernel quadtree(3)\nlight disk(0.1)";
  const std::string b = "light disk(0.1)\nkernel quadtree(3)\nblocker moments\nstorage sat(int32)\nmoments linear";
  EXPECT_EQ(specToJson(load(a)).dump(), specToJson(load(b)).dump());
}

TEST(Normalize, UniformSplitsAreComputed) {
  const FilterSpec s = load("moments linear(layers: 4)");
  EXPECT_EQ(s.moments.splits, (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
  const FilterSpec l = load("moments linear(layers: 3, split: lloyd)");
  EXPECT_EQ(l.moments.split, SplitPlacement::Lloyd);
  ASSERT_EQ(l.moments.splits.size(), 4u);  // initial guess, refined by the planner
  EXPECT_DOUBLE_EQ(l.moments.splits[1], 1.0 / 3.0);
  const FilterSpec e = load("moments linear(layers: 2, split: explicit(0, 0.1, 1))");
  EXPECT_EQ(e.moments.splits, (std::vector<double>{0.0, 0.1, 1.0}));
}

TEST(Normalize, ExponentDefaultsFollowStoragePrecision) {
  EXPECT_DOUBLE_EQ(load("moments evsm2").moments.positiveExponent, 40.0);
  EXPECT_DOUBLE_EQ(load("moments evsm2\nstorage fp16").moments.positiveExponent, 5.5);
  EXPECT_DOUBLE_EQ(load("moments linear\nstorage fp16").moments.minVariance, 5e-4);
  EXPECT_DOUBLE_EQ(load("moments linear").moments.minVariance, 1e-5);
}

TEST(Precision, LimitsMatchFacts) {
  EXPECT_NEAR(spec::warpExponentLimit({StorageFormat::Fp16, SatKind::None}, 2048).maxExponent, 5.545, 1e-3);
  EXPECT_DOUBLE_EQ(spec::warpExponentLimit({StorageFormat::Fp32, SatKind::None}, 2048).maxExponent, 42.0);
  // An fp32 SAT of W^2 texels: 42 - ln(W^2)/2.
  EXPECT_NEAR(spec::warpExponentLimit({StorageFormat::Fp32, SatKind::Fp32Centered}, 4096).maxExponent,
              42.0 - std::log(4096.0), 1e-9);
}

TEST(Precision, BothSidesOfTheFp16Boundary) {
  EXPECT_EQ(codes("moments evsm2(exponent: 5.5)\nstorage fp16"), Codes{});
  EXPECT_EQ(codes("moments evsm2(exponent: 5.6)\nstorage fp16"), Codes{"E0404"});
}

TEST(Precision, ExponentialWarpsInAnFp32SatAreRejectedAtAnyExponent) {
  // Below the overflow limit (34.38 at 2048^2) small boxes still cancel (the
  // stability suite's exponent_limit_evsm4_sat_fp32_centered errs 1.0), so E0420 replaces E0404.
  const std::string fixed = "\nkernel fixed(5)";
  for (const char* sat : {"\nstorage sat(fp32_centered)", "\nstorage sat(fp32)"}) {
    const Codes naive =
        std::string(sat).find("centered") == std::string::npos ? Codes{"E0420", "W0504"} : Codes{"E0420"};
    EXPECT_EQ(codes("moments exp(exponent: 1)" + std::string(sat) + fixed), naive) << sat;
    EXPECT_EQ(codes("moments evsm2(exponent: 34)" + std::string(sat) + fixed), naive) << sat;
    EXPECT_EQ(codes("moments evsm4(exponent: 40, negative_exponent: 40)" + std::string(sat) + fixed), naive) << sat;
  }
  // Siblings: the same warps in an int32 SAT within its limit, and linear moments in an fp32 SAT.
  EXPECT_EQ(codes("moments exp(exponent: 5)\nstorage sat(int32)" + fixed), Codes{});
  EXPECT_EQ(codes("moments evsm2(exponent: 5)\nstorage sat(int32)" + fixed), Codes{});
  EXPECT_EQ(codes("moments linear\nstorage sat(fp32_centered)" + fixed), Codes{});
  EXPECT_EQ(codes("moments exp(exponent: 6)\nstorage sat(int32)" + fixed), Codes{"E0404"});
}

TEST(Normalize, VssmFallbackDefaultsToPcf2x2) {
  // Non-planar sub-kernels default to the paper's option 2 (sec. 5.1), PCF.
  const std::string vssm = "moments linear\nstorage sat(int32)\nblocker moments\n";
  // The blocker walk is subdivided by default (uniform m = 5), so even a penumbra kernel has leaves.
  for (const char* kernel : {"kernel uniform(4)", "kernel quadtree(height: 2)", "kernel penumbra(max: 64)"}) {
    const FilterSpec s = load(vssm + kernel);
    EXPECT_TRUE(s.fallback.pcf) << kernel;
    EXPECT_EQ(s.fallback.n, 2) << kernel;
  }
  // No subdivision anywhere: the whole box is the only "leaf"; 2x2 PCF there measured worse than lit.
  EXPECT_FALSE(load(vssm.substr(0, vssm.size() - 1) + "(none)\nkernel penumbra(max: 64)").fallback.pcf);
  // Option 1 stays reachable, and a size is kept.
  EXPECT_FALSE(load(vssm + "kernel uniform(4)\nfallback none").fallback.pcf);
  EXPECT_EQ(load(vssm + "kernel uniform(4)\nfallback pcf(3x3)").fallback.n, 3);
  // Not VSSM: nothing to fall back from, so no default and a written one warns.
  EXPECT_FALSE(load("moments linear\nstorage sat(int32)\nkernel fixed(5)").fallback.pcf);
  EXPECT_EQ(codes("moments linear\nstorage sat(int32)\nkernel fixed(5)\nfallback pcf(2x2)"), Codes{"W0505"});
  EXPECT_EQ(codes(vssm + "kernel penumbra(max: 64)\nfallback pcf(2x2)"), Codes{});
}

TEST(Combinations, UniformSubdivideOption) {
  // Algorithm 1 subdivides only non-planar kernels; `subdivide: nonplanar`
  // (kernel and blocker walks), default `always`. Before, the argument was unknown (E0303).
  const std::string base = "moments linear\nstorage sat(int32)\n";
  const FilterSpec s =
      load(base + "blocker moments(uniform(m: 5, subdivide: nonplanar))\nkernel uniform(4, subdivide: nonplanar)");
  EXPECT_TRUE(s.kernel.uniformNonPlanarOnly);
  EXPECT_TRUE(s.blocker.uniformNonPlanarOnly);
  const FilterSpec d = load(base + "blocker moments\nkernel uniform(4)");
  EXPECT_FALSE(d.kernel.uniformNonPlanarOnly);
  EXPECT_FALSE(d.blocker.uniformNonPlanarOnly);
  EXPECT_EQ(codes(base + "blocker moments\nkernel uniform(4, subdivide: sometimes)"), Codes{"E0302"});
  // A 1 x 1 walk is never subdivided: the option has no effect.
  EXPECT_EQ(codes(base + "blocker moments\nkernel uniform(1, subdivide: nonplanar)"), Codes{"W0505"});
  EXPECT_EQ(codes(base + "blocker moments(uniform(m: 1, subdivide: nonplanar))\nkernel uniform(4)"), Codes{"W0505"});
  // The printed form round-trips (the driver re-checks built specs through it).
  EXPECT_NE(printFilter(s).find("subdivide: nonplanar"), std::string::npos);
}

TEST(Combinations, SatCornersOption) {
  // `sat(K, corners: bilinear)`; default whole texels.
  EXPECT_TRUE(load("moments linear\nstorage sat(int32, corners: bilinear)\nkernel fixed(5)").storage.fractionalCorners);
  EXPECT_FALSE(load("moments linear\nstorage sat(int32)\nkernel fixed(5)").storage.fractionalCorners);
  EXPECT_EQ(codes("moments linear\nstorage sat(int32, corners: round)\nkernel fixed(5)"), Codes{"E0302"});
  EXPECT_NE(printFilter(load("moments linear\nstorage sat(int32, corners: bilinear)")).find("corners: bilinear"),
            std::string::npos);
}

TEST(Combinations, Int32SatServesKernelsUpToTheMap) {
  // An int32 SAT sums boxes wider than 255 texels in exact pieces (sat.glsl),
  // so E0412 (max <= 255) is retired and any max up to 4096 is accepted.
  const std::string base = "moments linear\nstorage sat(int32)\nblocker moments\n";
  EXPECT_EQ(codes(base + "kernel uniform(4, max: 255)"), Codes{});
  EXPECT_EQ(codes(base + "kernel uniform(4, max: 256)"), Codes{});
  EXPECT_EQ(codes(base + "kernel uniform(4, max: 4096)"), Codes{});
  EXPECT_EQ(codes(base + "kernel uniform(4, max: 4097)"), Codes{"E0304"});
  EXPECT_EQ(spec::int32SatPieces(255), 1);
  EXPECT_EQ(spec::int32SatPieces(256), 2);
  EXPECT_EQ(spec::int32SatPieces(1024), 5);
  EXPECT_EQ(spec::int32SatPieces(4096), 17);
}

TEST(Normalize, BackfaceDefaultsToTheShadowingTerm) {
  // `backface shadowed`: the whole light behind the tangent plane gives 0 (shadowc_lookup.glsl);
  // `filtered` keeps filtering such receivers. Printed and written to the spec JSON both ways.
  EXPECT_TRUE(load("").backfaceShadowed);
  const FilterSpec filtered = load("backface filtered");
  EXPECT_FALSE(filtered.backfaceShadowed);
  EXPECT_EQ(specToJson(filtered)["backface"], "filtered");
  EXPECT_EQ(specToJson(load(""))["backface"], "shadowed");
  EXPECT_NE(printFilter(filtered).find("filtered"), std::string::npos);
  const LoadResult back = loadFilterSource(printFilter(filtered), "printed.shadow");
  ASSERT_TRUE(back.spec) << formatDiagnostics(back);
  EXPECT_FALSE(back.spec->backfaceShadowed);
  EXPECT_EQ(codes("backface culled"), Codes{"E0302"});
}

TEST(Normalize, WeightsDefaultToUniformAndFormFactorIsKeptWhereItActs) {
  // `weights form_factor` (docs/dsl.md "weights"): written to the spec JSON and the printed filter
  // only when on, so every other manifest stays byte-identical; it round-trips through printing.
  EXPECT_FALSE(load("").formFactorWeights);
  EXPECT_FALSE(specToJson(load("")).contains("weights"));
  EXPECT_EQ(printFilter(load("")).find("weights"), std::string::npos);
  const std::string vssm = "moments linear\nstorage sat(int32)\nblocker moments\nkernel uniform(4)\n";
  const FilterSpec weighted = load(vssm + "weights form_factor");
  EXPECT_TRUE(weighted.formFactorWeights);
  EXPECT_EQ(specToJson(weighted)["weights"], "form_factor");
  const LoadResult back = loadFilterSource(printFilter(weighted), "printed.shadow");
  ASSERT_TRUE(back.spec) << formatDiagnostics(back);
  EXPECT_TRUE(back.spec->formFactorWeights);
  EXPECT_FALSE(load(vssm + "weights uniform").formFactorWeights);
  EXPECT_EQ(codes(vssm + "weights form_factor"), Codes{});
  EXPECT_EQ(codes("kernel penumbra\nblocker search(16)\nweights form_factor"), Codes{});  // PCSS taps
  // Where nothing stands for a part of the light, or the light is not a spot: no effect (W0505).
  EXPECT_EQ(codes("moments linear\nblur box(2)\nweights form_factor"), Codes{"W0505"});
  EXPECT_EQ(codes("moments linear\nstorage sat(int32)\nblocker moments(none)\nkernel penumbra\nweights form_factor"),
            Codes{"W0505"});
  EXPECT_EQ(codes("light sun(angle: 0.5)\nkernel penumbra\nblocker search(16)\nweights form_factor"), Codes{"W0505"});
  EXPECT_EQ(codes("weights cosine"), Codes{"E0302"});
}

TEST(Normalize, DepthInputDefaultsToLinearAndHardwareFormatsRoundTrip) {
  // `depth_input` (docs/dsl.md): linear by default and then absent from the JSON and the print;
  // a hardware format with its Z direction is kept, printed and read back.
  EXPECT_EQ(load("").depthInput, DepthInputSpec{});
  EXPECT_FALSE(specToJson(load("")).contains("depth_input"));
  EXPECT_EQ(printFilter(load("")).find("depth_input"), std::string::npos);
  EXPECT_EQ(load("depth_input linear").depthInput, DepthInputSpec{});
  const FilterSpec d24 = load("depth_input d24");
  EXPECT_EQ(d24.depthInput, (DepthInputSpec{DepthInputFormat::D24, false}));
  EXPECT_EQ(specToJson(d24)["depth_input"].dump(), R"({"format":"d24","z":"standard"})");
  const FilterSpec rev = load("light sun\ndepth_input d32(z: reverse)");
  EXPECT_EQ(rev.depthInput, (DepthInputSpec{DepthInputFormat::D32, true}));
  for (const FilterSpec& s : {d24, rev}) {
    const LoadResult back = loadFilterSource(printFilter(s), "printed.shadow");
    ASSERT_TRUE(back.spec) << formatDiagnostics(back);
    EXPECT_EQ(back.spec->depthInput, s.depthInput);
  }
  EXPECT_EQ(codes("depth_input d16"), Codes{"E0302"});
  EXPECT_EQ(codes("light sun\ncascades 4\ndepth_input d32"), Codes{"E0452"});  // not verified for the atlas
  EXPECT_EQ(codes("light sun\ncascades 4\ndepth_input linear"), Codes{});
  EXPECT_EQ(codes("depth_input d32(z: inverted)"), Codes{"E0302"});
}

TEST(Normalize, ResolutionIsThePlannedMapAndRaisesTheDefaultMapSize) {
  // `resolution N` (docs/dsl.md): absent by default and then absent from the JSON and the print;
  // above the default map_size it raises it; above an explicit one it is E0460.
  EXPECT_EQ(load("").resolution, 0);
  EXPECT_FALSE(specToJson(load("")).contains("resolution"));
  const FilterSpec planned = load("resolution 4096");
  EXPECT_EQ(planned.resolution, 4096);
  EXPECT_EQ(planned.mapSize, 4096);
  EXPECT_EQ(specToJson(planned)["resolution"], 4096);
  EXPECT_EQ(load("resolution 512").mapSize, 2048);  // the default stays when it is larger
  const LoadResult back = loadFilterSource(printFilter(planned), "printed.shadow");
  ASSERT_TRUE(back.spec) << formatDiagnostics(back);
  EXPECT_EQ(back.spec->resolution, 4096);
  EXPECT_EQ(codes("resolution 4096\nmap_size 1024"), Codes{"E0460"});
  EXPECT_EQ(codes("resolution 4096\nmap_size 4096"), Codes{});
  EXPECT_EQ(codes("resolution 8"), Codes{"E0304"});
}

TEST(Normalize, KernelMaxDefaultsToWhatTheStorageServes) {
  // A SAT answers any box at the same cost: its penumbra kernels default to the whole map; depth
  // taps, mips and the min-max pyramid keep 64; an explicit max is kept.
  EXPECT_EQ(load("moments linear\nstorage sat(int32)\nblocker moments").kernel.maxTexels, spec::kMaxKernelTexels);
  EXPECT_EQ(load("moments linear\nstorage sat(fp32_centered)\nblocker moments").kernel.maxTexels,
            spec::kMaxKernelTexels);
  EXPECT_EQ(
      load("moments linear\nstorage sat(int32)\nblocker moments\nkernel quadtree(height: 2, max: 96)").kernel.maxTexels,
      96);
  EXPECT_EQ(load("blocker search(16)").kernel.maxTexels, 64);
  EXPECT_EQ(load("moments linear\nmips on").kernel.maxTexels, 64);
}

TEST(Combinations, UnrolledQuadtreeHeightLimit) {
  // Measured in docs/performance.md ("Pipeline creation"): the unrolled traversal is one copy of
  // the sub-kernel test per node; the table walk of the same height is a loop.
  const std::string base = "moments linear\nstorage sat(int32)\nblocker moments\n";
  EXPECT_EQ(codes(base + "kernel quadtree(height: 2, traversal: unrolled)"), Codes{});
  EXPECT_EQ(codes(base + "kernel quadtree(height: 3, traversal: unrolled)"), Codes{"W0510"});
  EXPECT_EQ(codes(base + "kernel quadtree(height: 4, traversal: unrolled)"), Codes{"E0419"});
  EXPECT_EQ(codes(base + "kernel quadtree(height: 5, traversal: table)"), Codes{});
  // The blocker walk is unrolled with the kernel's traversal too.
  EXPECT_EQ(codes("moments linear\nstorage sat(int32)\nblocker moments(quadtree(height: 5))\n"
                  "kernel quadtree(height: 1, traversal: unrolled)"),
            Codes{"E0419"});
}

TEST(Combinations, WerrorTurnsWarningsIntoErrors) {
  const std::string body = "moments linear\nstorage sat(fp32)";
  LoadOptions o;
  const LoadResult warn = loadFilterSource("filter t {\n" + body + "\n}\n", "t");
  EXPECT_EQ(warn.errorCount(), 0);
  EXPECT_EQ(warn.warningCount(), 1);
  EXPECT_TRUE(warn.spec);
  o.warningsAsErrors = true;
  const LoadResult err = loadFilterSource("filter t {\n" + body + "\n}\n", "t", o);
  EXPECT_EQ(err.errorCount(), 1);
  EXPECT_EQ(err.diagnostics[0].code, "W0504");  // the code stays; the severity changes
  EXPECT_FALSE(err.spec);
}

TEST(SpecJson, FixedKeyOrderAndEveryField) {
  const nlohmann::ordered_json j =
      specToJson(load("moments linear\nstorage sat(int32)\nblocker moments"
                      "\nkernel quadtree(3)"));
  std::vector<std::string> keys;
  for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
  const std::vector<std::string> expected = {"name",      "light",   "representation",   "moments",  "storage",
                                             "prefilter", "blocker", "kernel",           "sampling", "bias",
                                             "fallback",  "contact", "early_out_minmax", "backface", "map_size"};
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(j["moments"].size(), 10u);
  EXPECT_EQ(j["kernel"].size(), 8u);
  EXPECT_EQ(j["blocker"].size(), 6u);
  EXPECT_EQ(j["moments"]["splits"].dump(), "[0.0,1.0]");  // VSSM is one layer (E0418)
  EXPECT_EQ(j["kernel"]["subdivision"], "quadtree");
  EXPECT_EQ(j["storage"]["sat"], "int32");
}

TEST(SpecJson, GoldenForTheDesignExample) {
  const LoadResult r = loadFilterFile((test::sourceDir() / "samples/filters/vssm_adaptive.shadow").string());
  ASSERT_TRUE(r.spec);
  const std::string golden = (test::sourceDir() / "tests/spec/golden/vssm_adaptive.spec.json").string();
  const std::string diff = test::compareGolden(golden, specToJson(*r.spec).dump(2) + "\n");
  EXPECT_TRUE(diff.empty()) << diff;
}

// Moment shadow maps (Peters & Klein 2015): the moment bias follows the storage's bits, only
// msm's spec JSON carries it, and an fp32 SAT is accepted only where its worst-case error of
// the smallest box mean stays below the bias (both sides of that boundary).
TEST(Msm, MomentBiasDefaultsFollowStorage) {
  EXPECT_EQ(load("moments msm").moments.momentBias, 3e-6);
  EXPECT_EQ(load("moments msm\nstorage unorm16").moments.momentBias, 3e-5);
  EXPECT_EQ(load("moments msm\nstorage sat(int32)\nkernel fixed(5)").moments.momentBias, 3e-5);
  EXPECT_EQ(load("moments msm(0.0001)\nstorage unorm16").moments.momentBias, 1e-4);
  EXPECT_EQ(load("moments msm").moments.warp, Warp::Msm);
}

TEST(Msm, OnlyMsmSpecJsonHasAMomentBias) {
  EXPECT_TRUE(specToJson(load("moments msm"))["moments"].contains("moment_bias"));
  EXPECT_FALSE(specToJson(load("moments linear"))["moments"].contains("moment_bias"));
}

TEST(Msm, CombinationRules) {
  EXPECT_EQ(codes("moments msm(layers: 2)"), Codes{"E0440"});
  EXPECT_EQ(codes("moments msm\nstorage fp16"), Codes{"E0441"});
  EXPECT_EQ(codes("moments msm\nstorage sat(int32)\nkernel fixed(5)"), Codes{});
  EXPECT_EQ(codes("moments msm(min_variance: 0.001)"), Codes{"E0303"});  // msm has a bias instead
  EXPECT_EQ(codes("moments msm(moment_bias: 0.000001)\nstorage unorm16"), Codes{"W0540"});
  EXPECT_EQ(codes("moments msm\nbleeding reduce(0.2)"), Codes{});  // linstep applies to the bound too
}

TEST(Msm, Fp32SatPrecisionBothSidesOfTheBound) {
  // Bound 2 * 2^-24 * W^3 / ((N + 1) / 2)^2: W = 16, N = 63 -> 4.9e-7 (< 3e-6 accepted);
  // N = 21 -> 4.1e-6 (rejected); W = 2048, any N -> far above.
  const std::string sat = "moments msm\nstorage sat(fp32_centered)\n";
  EXPECT_EQ(codes(sat + "map_size 16\nkernel fixed(63)"), Codes{});
  EXPECT_EQ(codes(sat + "map_size 16\nkernel fixed(21)"), Codes{"E0442"});
  EXPECT_EQ(codes(sat + "kernel fixed(63)"), Codes{"E0442"});
  FilterSpec s = load(sat + "map_size 16\nkernel fixed(63)");
  const spec::MsmSatPrecision p = spec::msmFp32SatPrecision(s);
  EXPECT_EQ(p.boxTexels, 32 * 32);
  EXPECT_NEAR(p.meanError, 2.0 * std::ldexp(1.0, -24) * 4096.0 / 1024.0, 1e-15);
}

TEST(Combinations, ReceiverPlaneBias) {
  // `bias receiver_plane(constant:, max_slope:)`, both optional.
  const FilterSpec d = load("depth\nbias receiver_plane");
  EXPECT_EQ(d.bias.kind, BiasKind::ReceiverPlane);
  EXPECT_DOUBLE_EQ(d.bias.constant, 1e-3);
  EXPECT_DOUBLE_EQ(d.bias.maxSlope, 50);
  // A BiasSpec made in code (the planner, tests) gets the same clamp as the language default
  // (the header said 10 while the reader set 50).
  EXPECT_DOUBLE_EQ(BiasSpec{}.maxSlope, d.bias.maxSlope);
  const FilterSpec s = load("depth\nbias receiver_plane(constant: 0.0005, max_slope: 4)");
  EXPECT_DOUBLE_EQ(s.bias.constant, 5e-4);
  EXPECT_DOUBLE_EQ(s.bias.maxSlope, 4);
  EXPECT_EQ(specToJson(s)["bias"]["kind"], "receiver_plane");
  EXPECT_EQ(specToJson(s)["bias"]["max_slope"], 4);
  // Other policies' JSON (and so their manifests) have no max_slope.
  EXPECT_FALSE(specToJson(load("depth\nbias slope(0.05)"))["bias"].contains("max_slope"));
  const LoadResult round = loadFilterSource(printFilter(s), "t.shadow");
  ASSERT_TRUE(round.spec.has_value()) << formatDiagnostics(round);
  EXPECT_EQ(specToJson(*round.spec), specToJson(s));
  // A slope clamp of 0 would drop the plane: out of range, like a negative one.
  EXPECT_FALSE(codes("depth\nbias receiver_plane(max_slope: 0)").empty());
  EXPECT_FALSE(codes("depth\nbias receiver_plane(max_slope: -1)").empty());
  EXPECT_FALSE(codes("depth\nbias receiver_plane(0.001)").empty());  // no positional argument
  // On moments only VSSM's fallback / contact PCF read depth taps; elsewhere it does nothing.
  EXPECT_EQ(codes("moments linear\nkernel fixed(5)\nbias receiver_plane"), Codes{"W0505"});
  const std::string vssm = "moments linear\nstorage sat(int32)\nblocker moments\nkernel quadtree(height: 2)\n";
  EXPECT_EQ(codes(vssm + "bias receiver_plane"), Codes{});  // fallback pcf(2x2) by default
  EXPECT_EQ(codes(vssm + "fallback none\nbias receiver_plane"), Codes{"W0505"});
  EXPECT_EQ(codes(vssm + "fallback none\ncontact pcf(3x3)\nbias receiver_plane"), Codes{});
}

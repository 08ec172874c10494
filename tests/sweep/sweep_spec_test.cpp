// The sweep description parser, the variant text edits and the expansion (docs/sweep.md).
#include "sweep/sweep_spec.h"

#include <gtest/gtest.h>

#include <set>

#include "sweep/expand.h"
#include "sweep/filter_text.h"

namespace shadowc::sweep {
namespace {

SweepSpec parse(const std::string& json) { return parseSweepSpec(json, "s.json", "."); }

std::string errorOf(const std::string& json) {
  try {
    expand(parse(json));
  } catch (const SweepSpecError& e) {
    return e.what();
  }
  return "";
}

const std::string kFilter = R"("text": "filter f {\n    depth\n    kernel fixed(${k})\n}\n")";

TEST(SweepSpec, RangesListsAndGeometric) {
  const SweepSpec s = parse(R"({"filters": [{)" + kFilter + R"(}], "scenes": ["two_planes"],
      "params": {"k": {"from": 1, "to": 5, "step": 2}, "t": {"from": 4, "to": 256, "factor": 4},
                 "b": {"from": 0, "to": 0.3, "step": 0.1}, "s": ["int32", 0.5]}})");
  ASSERT_EQ(s.params.size(), 4u);
  EXPECT_EQ(s.params[0].values, (std::vector<std::string>{"1", "3", "5"}));
  EXPECT_EQ(s.params[1].values, (std::vector<std::string>{"4", "16", "64", "256"}));
  EXPECT_EQ(s.params[2].values, (std::vector<std::string>{"0", "0.1", "0.2", "0.3"}));  // no drift
  EXPECT_EQ(s.params[3].values, (std::vector<std::string>{"int32", "0.5"}));
  EXPECT_EQ(s.screens, std::vector<uint32_t>{256});  // defaults
  EXPECT_EQ(s.runs.runs, 5);
  EXPECT_FALSE(s.runs.automatic);
}

TEST(SweepSpec, ErrorsNameTheField) {
  EXPECT_NE(errorOf(R"({"filters": [{)" + kFilter + R"(}], "scenes": ["two_planes"], "param": {}})")
                .find("s.json: error: param: unknown field (did you mean 'params'?)"),
            std::string::npos);
  EXPECT_NE(errorOf("{\n  \"filters\": [,]\n}").find("s.json:2:"), std::string::npos)
      << errorOf("{\n  \"filters\": [,]\n}");
  EXPECT_NE(errorOf(R"({"filters": [{)" + kFilter + R"(}], "scenes": ["two_planes"]})").find("${k} has no values"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"filters": [{)" + kFilter + R"(}], "scenes": ["two_planes"], "params": {"k": [1]},
                       "runs": 0})")
                .find("runs: 0 is out of range"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"filters": [{)" + kFilter + R"(}], "scenes": ["two_planes"], "params": {"k": [1]},
                       "shaders": ["generic", "fast"]})")
                .find("'fast' is not a shader kind"),
            std::string::npos);
  // The sibling: the same description without the fault parses and expands.
  EXPECT_EQ(errorOf(R"({"filters": [{)" + kFilter + R"(}], "scenes": ["two_planes"], "params": {"k": [1]}})"), "");
}

TEST(SweepSpec, SizesArePairsNotAProduct) {
  const std::string base = R"({"filters": [{)" + kFilter + R"(}], "scenes": ["two_planes"], "params": {"k": [1]}, )";
  const Expansion pairs = expand(parse(base + R"("sizes": [[128, 512], [256, 1024], [512, 2048]]})"));
  ASSERT_EQ(pairs.cases.size(), 3u);
  EXPECT_EQ(pairs.cases[0].label, "two_planes 128px map 512");
  EXPECT_EQ(pairs.cases[2].screen, 512u);
  EXPECT_EQ(pairs.cases[2].map, 2048u);
  // The sibling: the same sides as lists give their product.
  EXPECT_EQ(expand(parse(base + R"("screen": [128, 256, 512], "map": [512, 1024, 2048]})")).cases.size(), 9u);
  EXPECT_NE(errorOf(base + R"("sizes": [[128, 512]], "map": 1024})").find("sizes: give either"), std::string::npos);
  EXPECT_NE(errorOf(base + R"("sizes": [[128]]})").find("sizes[0]: expected a [screen, map] pair"), std::string::npos);
}

TEST(FilterText, SetReplacesAddsAndRemoves) {
  const std::string base =
      "# c\nfilter f {\n    moments linear(layers: 2,\n                   overlap: 0.1)   # spans lines\n"
      "    kernel fixed(3)\n}\n";
  const std::string replaced = setSetting(base, "moments", std::string("linear"));
  EXPECT_EQ(replaced, "# c\nfilter f {\n    moments linear\n    kernel fixed(3)\n}\n");
  EXPECT_EQ(setSetting(base, "depth", std::nullopt), "# c\nfilter f {\n    kernel fixed(3)\n}\n");  // one axis
  EXPECT_NE(setSetting(base, "bias", std::string("slope(0.005)")).find("    bias slope(0.005)\n}"), std::string::npos);
  EXPECT_NE(setSetting("filter f { depth }", "kernel", std::string("fixed(5)")).find("kernel fixed(5)\n}"),
            std::string::npos);
}

TEST(FilterText, Placeholders) {
  EXPECT_EQ(placeholders("a ${x} ${y} ${x}"), (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(fillPlaceholders("a ${x}${y}", {{"x", "1"}, {"y", "b"}}), "a 1b");
  EXPECT_THROW(fillPlaceholders("${z}", {}), std::out_of_range);
}

TEST(Expand, ProductOnlyOverUsedParametersInOrder) {
  const Expansion e = expand(parse(R"({"filters": [{)" + kFilter + R"(},
      {"name": "g", "text": "filter g {\n depth\n kernel fixed(${k})\n sampling poisson(${t})\n}", "params": {"k": [9]}}],
      "params": {"k": [1, 3], "t": [4, 8], "unused": [1]}, "scenes": ["two_planes", {"scene": "two_planes",
      "light_size": 2}], "screen": [64, 128], "map": 256, "shaders": ["specialized", "generic"]})"));
  std::vector<std::string> labels;
  for (const Variant& v : e.variants) labels.push_back(v.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"filter0[k=1]", "filter0[k=1] (generic)", "filter0[k=3]",
                                              "filter0[k=3] (generic)", "g[k=9,t=4]", "g[k=9,t=4] (generic)",
                                              "g[k=9,t=8]", "g[k=9,t=8] (generic)"}));
  EXPECT_NE(e.variants[4].text.find("kernel fixed(9)"), std::string::npos);  // the filter's own range wins
  ASSERT_EQ(e.cases.size(), 4u);
  EXPECT_EQ(e.cases[2].label, "two_planes_light2 64px map 256");
  ASSERT_EQ(e.warnings.size(), 1u);
  EXPECT_NE(e.warnings[0].find("'unused'"), std::string::npos);
}

TEST(Shard, SlicesPartitionTheJobs) {
  std::multiset<size_t> seen;
  for (int i = 0; i < 3; ++i) {
    const Shard s = parseShard(std::to_string(i) + "/3");
    for (size_t j = 0; j < 20; ++j)
      if (s.contains(j)) seen.insert(j);
  }
  EXPECT_EQ(seen.size(), 20u);
  for (size_t j = 0; j < 20; ++j) EXPECT_EQ(seen.count(j), 1u);
  EXPECT_THROW(parseShard("3/3"), std::invalid_argument);
  EXPECT_THROW(parseShard("1"), std::invalid_argument);
  EXPECT_THROW(parseShard("1/2x"), std::invalid_argument);
}

}  // namespace
}  // namespace shadowc::sweep

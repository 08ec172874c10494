// The includable lookup fits into someone else's shader (docs/integration.md "The lookup's
// interface"): an engine fragment shader (#version 450, no extensions) with its own `uniform … { … } frame;` at set 0,
// binding 0 includes <filter>_lookup.glsl compiled with --lookup-set 1 and passes spirv-val, with no two resources on
// one (set, binding) and the SPIR-V's bindings equal to the manifest's "shade" section; with SHADOWC_FRAME_EXTERNAL the
// frame values come from the engine's block. Siblings: the old form (instance `frame`, set 0 binding 0) fails both
// ways, and the prefix check catches an unprefixed global.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "backend/spirv_backend.h"
#include "emit/emit_support.h"

namespace shadowc {
namespace {

constexpr const char* kEngineHead = R"(#version 450
// The engine's own camera block, where engines usually put it.
layout(set = 0, binding = 0, std140) uniform Frame {
  mat4 viewProj;
  mat4 lightView;
  vec4 light;  // x tanHalfFov, y near, z far, w width
} frame;
layout(location = 0) in vec3 worldPos;
layout(location = 1) in vec3 worldNormal;
layout(location = 0) out vec4 color;
)";

constexpr const char* kEngineMain = R"(
void main() {
  vec3 n = normalize(worldNormal);
  float v = shadowc_visibility(worldPos, n);
  color = frame.viewProj * vec4(vec3(max(dot(n, vec3(0.0, 1.0, 0.0)), 0.0) * v), 1.0);
}
)";

constexpr const char* kExternalFrame = R"(
shadowc_Frame shadowc_frame() { return shadowc_Frame(frame.lightView, frame.light); }
)";

driver::Result compileWith(const std::string& sample, LookupPlacement placement) {
  driver::Options o;
  o.lookup = placement;
  return driver::compileFile(test::samplePath(sample).string(), o);
}

std::string lookupOf(const driver::Result& r) { return *r.artifact->file(r.artifact->manifest.shade.glsl); }

// Unoptimized, so that every declared resource is still in the module for the slot checks
// (spirv-opt drops the ones a filter declares but does not read); the optimized compile must
// work too.
SpirvResult compileFragment(const std::string& source) {
  const SpirvResult optimized = compileGlsl(source, ShaderStage::Fragment, "engine.frag", {}, {true, true});
  const SpirvResult r = compileGlsl(source, ShaderStage::Fragment, "engine.frag", {}, {false, true});
  EXPECT_EQ(optimized.ok, r.ok) << optimized.log;
  return r;
}

// (set, binding) of every decorated resource, from the disassembly.
std::vector<std::pair<uint32_t, uint32_t>> resourceSlots(const std::vector<uint32_t>& words) {
  std::map<std::string, uint32_t> set, binding;
  std::istringstream in(disassembleSpirv(words));
  static const std::regex re(R"(OpDecorate (%\S+) (DescriptorSet|Binding) (\d+))");
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, re)) (m[2] == "DescriptorSet" ? set : binding)[m[1]] = std::stoul(m[3]);
  }
  std::vector<std::pair<uint32_t, uint32_t>> slots;
  for (const auto& [id, b] : binding) slots.emplace_back(set.count(id) ? set.at(id) : 0, b);
  return slots;
}

std::string duplicateSlot(const std::vector<std::pair<uint32_t, uint32_t>>& slots) {
  std::set<std::pair<uint32_t, uint32_t>> seen;
  for (const auto& s : slots)
    if (!seen.insert(s).second) return "set " + std::to_string(s.first) + " binding " + std::to_string(s.second);
  return "";
}

// Names declared at file scope (functions, variables, structs, blocks and their instances).
// A small scanner over the preprocessed text: brace bodies, parameter lists, initializers and
// layout(...) are skipped; the identifier before `(`, `[`, `=`, `;` or `{` is a declared name.
std::set<std::string> fileScopeNames(const std::string& text) {
  std::set<std::string> names;
  static const std::regex token(R"([A-Za-z_]\w*|\S)");
  std::vector<std::string> t;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), token); it != std::sregex_iterator(); ++it)
    t.push_back(it->str());
  auto skip = [&](size_t i, const std::string& open, const std::string& close) {
    int depth = 0;
    for (; i < t.size(); ++i) {
      if (t[i] == open) ++depth;
      if (t[i] == close && --depth == 0) return i;
    }
    return i;
  };
  std::string last;
  for (size_t i = 0; i < t.size(); ++i) {
    const std::string& s = t[i];
    if (s == "layout") {
      i = skip(i + 1, "(", ")");
    } else if (s == "#") {
      last.clear();
    } else if (s == "(" || s == "[" || s == "=" || s == ";" || s == "{") {
      if (!last.empty()) names.insert(last);
      last.clear();
      if (s == "(") i = skip(i, "(", ")");
      if (s == "[") i = skip(i, "[", "]");
      if (s == "{") i = skip(i, "{", "}");
      if (s == "=") {
        while (i < t.size() && t[i] != ";") i = (t[i] == "(") ? skip(i, "(", ")") + 1 : i + 1;
      }
    } else if (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_') {
      last = s;
    }
  }
  return names;
}

// Comments are per line; the scanner above needs them gone first.
std::string withoutComments(const std::string& text) { return std::regex_replace(text, std::regex(R"(//[^\n]*)"), ""); }

std::vector<std::string> unprefixed(const std::string& lookup) {
  std::vector<std::string> bad;
  for (const std::string& n : fileScopeNames(withoutComments(lookup)))
    if (!n.starts_with("shadowc_")) bad.push_back(n);
  return bad;
}

class LookupInterface : public ::testing::TestWithParam<std::string> {};

TEST_P(LookupInterface, FitsAnEngineShaderWithItsOwnFrameBlockAtSet0Binding0) {
  const driver::Result r = compileWith(GetParam(), {1, 0});
  ASSERT_TRUE(r.ok) << r.log;
  const std::string lookup = lookupOf(r);
  EXPECT_EQ(withoutComments(lookup).find("#include"), std::string::npos);
  EXPECT_EQ(withoutComments(lookup).find("#extension"), std::string::npos);
  EXPECT_TRUE(unprefixed(lookup).empty()) << ::testing::PrintToString(unprefixed(lookup));

  const SpirvResult s = compileFragment(kEngineHead + lookup + kEngineMain);
  ASSERT_TRUE(s.ok) << s.log;
  EXPECT_EQ(validateSpirv(s.words), "");
  const auto slots = resourceSlots(s.words);
  EXPECT_EQ(duplicateSlot(slots), "");
  // Every binding the manifest lists for the lookup is in the SPIR-V, in set 1.
  const ShadeInterface& shade = r.artifact->manifest.shade;
  EXPECT_EQ(shade.set, 1u);
  for (const Binding& b : shade.bindings)
    EXPECT_TRUE(std::count(slots.begin(), slots.end(), std::pair{1u, b.binding}) == 1) << b.image << " " << b.binding;
  EXPECT_EQ(slots.size(), shade.bindings.size() + 1) << "the lookup's resources plus the engine's frame";
}

TEST_P(LookupInterface, TheEngineCanSupplyTheFrameFromItsOwnBlock) {
  const driver::Result r = compileWith(GetParam(), {0, 16});
  ASSERT_TRUE(r.ok) << r.log;
  const SpirvResult s = compileFragment(kEngineHead + std::string("#define SHADOWC_FRAME_EXTERNAL\n") + lookupOf(r) +
                                        kExternalFrame + kEngineMain);
  ASSERT_TRUE(s.ok) << s.log;
  EXPECT_EQ(validateSpirv(s.words), "");
  EXPECT_EQ(disassembleSpirv(s.words).find("shadowc_FrameBlock"), std::string::npos);
  EXPECT_EQ(duplicateSlot(resourceSlots(s.words)), "");
  for (const Binding& b : r.artifact->manifest.shade.bindings) EXPECT_GE(b.binding, 16u) << b.image;
}

INSTANTIATE_TEST_SUITE_P(Samples, LookupInterface, ::testing::ValuesIn(test::sampleFilterNames()),
                         [](const auto& info) { return info.param; });

// The old fixed form fails in the engine's shader: the default placement puts our frame block
// on the engine's (set 0, binding 0), and the old instance name `frame` does not compile at all.
TEST(LookupInterface, TheOldFixedFormFails) {
  const driver::Result r = compileWith("vssm_pcf_fallback", {});
  ASSERT_TRUE(r.ok) << r.log;
  const std::string lookup = lookupOf(r);
  const SpirvResult collides = compileFragment(kEngineHead + lookup + kEngineMain);
  ASSERT_TRUE(collides.ok) << collides.log;
  EXPECT_EQ(duplicateSlot(resourceSlots(collides.words)), "set 0 binding 0");

  const std::string old = std::regex_replace(lookup, std::regex(R"(\bshadowc_frameBlock\b)"), "frame");
  const SpirvResult clash = compileFragment(kEngineHead + old + kEngineMain);
  EXPECT_FALSE(clash.ok);
  EXPECT_NE(clash.log.find("redefinition"), std::string::npos) << clash.log;
}

TEST(LookupInterface, ThePrefixCheckCatchesAnUnprefixedGlobal) {
  const driver::Result r = compileWith("pcss_poisson", {});
  ASSERT_TRUE(r.ok) << r.log;
  const std::string lookup = lookupOf(r);
  ASSERT_TRUE(unprefixed(lookup).empty());
  const auto bad = unprefixed(lookup +
                              "\nstruct Receiver { float d; };\nconst float taps[2] = float[](1.0, 2.0);\n"
                              "float helper(float x) { return x; }\nuniform sampler2D shadowMap;\n");
  EXPECT_EQ(bad, (std::vector<std::string>{"Receiver", "helper", "shadowMap", "taps"}));
}

TEST(LookupInterface, TheShadePassKeepsItsOwnLayout) {
  const driver::Result r = compileWith("vssm_minmax_early_out", {3, 20});
  ASSERT_TRUE(r.ok) << r.log;
  const Manifest& m = r.artifact->manifest;
  // The placement moves the lookup file's resources only; the runtime's shade pass is unchanged.
  const Pass& shade = m.passes.back();
  ASSERT_EQ(shade.name, "shade");
  for (const Binding& b : shade.bindings) EXPECT_LT(b.binding, 9u) << b.image;
  for (const Binding& b : m.shade.bindings) {
    const auto same = std::find_if(shade.bindings.begin(), shade.bindings.end(),
                                   [&](const Binding& s) { return s.image == b.image; });
    ASSERT_NE(same, shade.bindings.end()) << b.image;
    EXPECT_EQ(b.binding, same->binding + 20) << b.image;
  }
}

// docs/integration.md: with `bias receiver_plane` a fragment shader passes the triangle's own
// plane (screen-space derivatives) instead of the shading normal. Sibling: the same call in a
// compute shader (the shade pass) does not compile, which is why the lookup takes a normal.
TEST(LookupInterface, TheReceiverPlaneCanComeFromScreenSpaceDerivatives) {
  driver::Options o;
  o.lookup = {1, 0};
  const driver::Result r = driver::compileSource(
      "filter rp {\n  depth\n  kernel fixed(5)\n  bias receiver_plane(constant: 0.0005)\n}\n", "rp.shadow", o);
  ASSERT_TRUE(r.ok) << r.log;
  const std::string lookup = lookupOf(r);
  ASSERT_NE(lookup.find("shadowc_tapDepth"), std::string::npos);
  const std::string main = R"(
void main() {
  vec3 face = normalize(cross(dFdx(worldPos), dFdy(worldPos)));
  face = dot(face, worldNormal) < 0.0 ? -face : face;
  float v = shadowc_visibility(worldPos, face);
  color = frame.viewProj * vec4(v);
}
)";
  const SpirvResult s = compileFragment(kEngineHead + lookup + main);
  ASSERT_TRUE(s.ok) << s.log;
  EXPECT_EQ(validateSpirv(s.words), "");
  const std::string computeHead = R"(#version 450
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, std140) uniform Frame { mat4 viewProj; mat4 lightView; vec4 light; } frame;
vec3 worldPos = vec3(0.0);
vec3 worldNormal = vec3(0.0, 1.0, 0.0);
vec4 color;
)";
  const SpirvResult c = compileGlsl(computeHead + lookup + main, ShaderStage::Compute, "shade.comp", {}, {false, true});
  EXPECT_FALSE(c.ok);
  EXPECT_NE(c.log.find("dFdx"), std::string::npos) << c.log;
}

TEST(LookupInterface, APlacementOutOfRangeIsOneMessage) {
  const test::CliResult c = test::runShadowc("compile " + test::samplePath("pcf_grid5x5").string() + " -o " +
                                             test::freshTempDir("lookup-range").string() + " --lookup-set 99");
  EXPECT_EQ(c.code, 1);
  EXPECT_NE(c.err.find("--lookup-set: at most 31"), std::string::npos) << c.err;
}

}  // namespace
}  // namespace shadowc

// --emit cpp: the generated <filter>.h compiles (the C++ compiler CMake uses, -fsyntax-only,
// -Wall -Wextra -Werror) and every value in it equals manifest.json's: the test writes a TU of
// static_asserts from the manifest as manifestFromJson reads it (not from the header emitter)
// and from the .spv bytes (an FNV-1a hash of every word), so a wrong value fails to compile.
// Sibling: one wrong expected value must make the TU fail.
#include "emit/cpp_header.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>

#include "emit/emit_support.h"
#include "emit/filter_emitter.h"
#include "support/test_support.h"

namespace shadowc {
namespace {

uint64_t fnv1a(const std::vector<uint32_t>& words) {
  uint64_t h = 1469598103934665603ull;
  for (uint32_t w : words) h = (h ^ w) * 1099511628211ull;
  return h;
}

std::string q(const std::string& s) { return "\"" + s + "\""; }

// static_asserts for every manifest value the header carries.
std::string expectations(const Manifest& m, const driver::Artifact& a) {
  const std::string ns = "shadowc_filters::" + m.filter;
  std::string t = fmt::format(
      "constexpr bool eq(const char* a, const char* b) {{ while (*a && *a == *b) {{ ++a; ++b; }} return *a == *b; }}\n"
      "constexpr unsigned long long fnv(const std::uint32_t* w, std::size_t n) {{\n"
      "  unsigned long long h = 1469598103934665603ull;\n"
      "  for (std::size_t i = 0; i < n; ++i) h = (h ^ w[i]) * 1099511628211ull;\n  return h;\n}}\n"
      "namespace f = {};\nusing namespace shadowc_filters;\n"
      "static_assert(eq(f::filter.name, {}) && eq(f::filter.contentHash, {}));\n"
      "static_assert(f::filter.imageCount == {} && f::filter.passCount == {});\n",
      ns, q(m.filter), q(m.contentHash), m.images.size(), m.passes.size());
  for (size_t i = 0; i < m.images.size(); ++i) {
    const ImageDesc& im = m.images[i];
    t += fmt::format(
        "static_assert(eq(f::images[{0}].name, {1}) && static_cast<int>(f::images[{0}].format) == {2} && "
        "static_cast<int>(f::images[{0}].size.domain) == {3} && f::images[{0}].size.shift == {4} && "
        "f::images[{0}].mipLevels == {5} && f::images[{0}].layers == {6} && "
        "static_cast<int>(f::images[{0}].role) == {7} && f::images[{0}].linearFilter == {8});\n",
        i, q(im.name), static_cast<int>(im.format), static_cast<int>(im.size.domain), im.size.shift, im.mipLevels,
        im.layers, static_cast<int>(im.role), im.linearFilter);
  }
  auto bindings = [&](const std::string& arr, const std::vector<Binding>& bs) {
    for (size_t j = 0; j < bs.size(); ++j)
      t += fmt::format(
          "static_assert({0}[{1}].binding == {2} && eq({0}[{1}].image, {3}) && "
          "static_cast<int>({0}[{1}].access) == {4} && {0}[{1}].level == {5});\n",
          arr, j, bs[j].binding, q(bs[j].image), static_cast<int>(bs[j].access), bs[j].level);
  };
  for (size_t i = 0; i < m.passes.size(); ++i) {
    const Pass& p = m.passes[i];
    const std::vector<uint32_t> words = test::spirvWords(*a.file(p.spirv));
    const std::string P = fmt::format("f::passes[{}]", i);
    t += fmt::format(
        "static_assert(eq({0}.name, {1}) && eq({0}.kind, {2}) && {0}.localSize[0] == {3} && {0}.localSize[1] == {4} "
        "&& {0}.localSize[2] == {5} && static_cast<int>({0}.dispatchSize.domain) == {6} && "
        "{0}.dispatchSize.shift == {7} && static_cast<int>({0}.dispatchMode) == {8} && {0}.bindingCount == {9} && "
        "{0}.pushConstantCount == {10});\n"
        "static_assert({0}.spirvWords == {11} && fnv({0}.spirv, {0}.spirvWords) == {12}ull);\n",
        P, q(p.name), q(p.kind), p.localSize[0], p.localSize[1], p.localSize[2],
        static_cast<int>(p.dispatch.size.domain), p.dispatch.size.shift, static_cast<int>(p.dispatch.mode),
        p.bindings.size(), p.pushConstants.size(), words.size(), fnv1a(words));
    bindings(P + ".bindings", p.bindings);
    for (size_t j = 0; j < p.pushConstants.size(); ++j)
      t += fmt::format(
          "static_assert(eq({0}.pushConstants[{1}].name, {2}) && {0}.pushConstants[{1}].offset == {3} && "
          "{0}.pushConstants[{1}].value == {4:.17g});\n",
          P, j, q(p.pushConstants[j].name), p.pushConstants[j].offset, p.pushConstants[j].value);
  }
  t += fmt::format(
      "static_assert(eq(f::filter.lookup.glsl, {}) && eq(f::filter.lookup.function, {}) && "
      "eq(f::filter.lookup.signature, {}) && f::filter.lookup.set == {} && f::filter.lookup.bindingCount == {});\n",
      q(m.shade.glsl), q(m.shade.function), q(m.shade.signature), m.shade.set, m.shade.bindings.size());
  bindings("f::filter.lookup.bindings", m.shade.bindings);
  // The planned map side (`resolution`, docs/dsl.md), 0 when the spec has none.
  t += fmt::format("static_assert(f::plannedMapSize == {});\n", m.spec.value("resolution", 0));
  const bool reversed = m.spec.contains("depth_input") && m.spec["depth_input"].value("z", "") == "reverse";
  t += fmt::format("static_assert(f::depthInputReversed == {});\n", reversed);
  t += fmt::format("static_assert(f::filter.bufferCount == {});\n", m.buffers.size());
  for (size_t i = 0; i < m.buffers.size(); ++i) {
    const BufferDesc& b = m.buffers[i];
    long long sum = 0;  // position-weighted, so a swapped pair of values is caught too
    for (size_t k = 0; k < b.values.size(); ++k) sum += (long long)(k + 1) * b.values[k];
    t += fmt::format(
        "constexpr long long weighted{0}() {{ long long s = 0; for (std::size_t k = 0; k < f::buffers[{0}].valueCount; "
        "++k) s += (long long)(k + 1) * f::buffers[{0}].values[k]; return s; }}\n"
        "static_assert(eq(f::buffers[{0}].name, {1}) && f::buffers[{0}].components == {2} && "
        "f::buffers[{0}].valueCount == {3} && weighted{0}() == {4}ll);\n",
        i, q(b.name), b.components, b.values.size(), sum);
  }
  return t;
}

// Compiles `tu` next to the header; returns the compiler's exit status (0 = compiled).
int compileTu(const std::filesystem::path& dir, const std::string& header, const std::string& headerText,
              const std::string& tu) {
  std::ofstream(dir / header, std::ios::binary) << headerText;
  std::ofstream(dir / "check.cpp", std::ios::binary) << "#include \"" << header << "\"\n" << tu;
  const std::string cmd = test::cxxCompiler() + " -std=c++20 -fsyntax-only -Wall -Wextra -Werror -I" +
                          (test::sourceDir() / "include").string() + " " + (dir / "check.cpp").string() + " 2>" +
                          (dir / "log.txt").string();
  return std::system(cmd.c_str());
}

class CppHeader : public ::testing::TestWithParam<std::string> {};

TEST_P(CppHeader, CompilesAndEveryValueEqualsTheManifest) {
  driver::Options o;
  o.engineOutputs = {driver::OutputKind::CppHeader};
  const driver::Result r = driver::compileFile(test::samplePath(GetParam()).string(), o);
  ASSERT_TRUE(r.ok) << r.log;
  const std::string name = cppHeaderFileName(GetParam());
  const std::string* header = r.artifact->file(name);
  ASSERT_TRUE(header);
  const Manifest m = manifestFromJson(nlohmann::json::parse(*r.artifact->file(kManifestFile)));
  const auto dir = test::freshTempDir("cpp-header");
  const std::string tu = expectations(m, *r.artifact);
  EXPECT_EQ(compileTu(dir, name, *header, tu), 0) << test::readFile(dir / "log.txt");
  // Sibling: the same checks with the first pass's local size off by one must not compile.
  const std::string wrong = "static_assert(" + fmt::format("shadowc_filters::{}::passes[0].localSize[0] == {});\n",
                                                           GetParam(), m.passes[0].localSize[0] + 1);
  EXPECT_NE(compileTu(dir, name, *header, tu + wrong), 0) << "a wrong expected value compiled";
  std::filesystem::remove_all(dir);
}

// Samples that between them use every manifest feature the header carries: several shared
// shaders (mip, minmax), layers, int32 SAT, Lloyd splits, push constants where any exist, the
// quadtree's table buffer.
// A planned filter's header carries its map side (`resolution`); a sibling with another value fails.
TEST(CppHeader, PlannedMapSizeIsTheResolution) {
  driver::Options o;
  o.engineOutputs = {driver::OutputKind::CppHeader};
  const std::string text = test::readFile(test::samplePath("pcf_grid5x5"));
  const driver::Result r =
      driver::compileSource(text.substr(0, text.rfind('}')) + "    resolution 4096\n}\n", "planned_map.shadow", o);
  ASSERT_TRUE(r.ok) << r.log;
  const std::string name = cppHeaderFileName("pcf_grid5x5");  // named after the filter, not the file
  const std::string* header = r.artifact->file(name);
  ASSERT_TRUE(header);
  const auto dir = test::freshTempDir("cpp-header-planned");
  const std::string ns = "shadowc_filters::pcf_grid5x5::plannedMapSize";
  EXPECT_EQ(compileTu(dir, name, *header, "static_assert(" + ns + " == 4096);\n"), 0)
      << test::readFile(dir / "log.txt");
  EXPECT_NE(compileTu(dir, name, *header, "static_assert(" + ns + " == 2048);\n"), 0);
  std::filesystem::remove_all(dir);
}

// A depth_input filter's header says which way its depth attachment runs; a sibling fails.
TEST(CppHeader, DepthInputReversedIsTheSpecs) {
  driver::Options o;
  o.engineOutputs = {driver::OutputKind::CppHeader};
  const std::string text = test::readFile(test::samplePath("pcf_grid5x5"));
  const std::string ns = "shadowc_filters::pcf_grid5x5::depthInputReversed";
  for (const auto& [line, reversed] : {std::pair{"depth_input d32(z: reverse)", true}, {"depth_input d24", false}}) {
    const driver::Result r =
        driver::compileSource(text.substr(0, text.rfind('}')) + "    " + line + "\n}\n", "depth.shadow", o);
    ASSERT_TRUE(r.ok) << r.log;
    const std::string name = cppHeaderFileName("pcf_grid5x5");
    const auto dir = test::freshTempDir("cpp-header-depth");
    EXPECT_EQ(compileTu(dir, name, *r.artifact->file(name), fmt::format("static_assert({} == {});\n", ns, reversed)), 0)
        << line << "\n"
        << test::readFile(dir / "log.txt");
    EXPECT_NE(compileTu(dir, name, *r.artifact->file(name), fmt::format("static_assert({} == {});\n", ns, !reversed)),
              0)
        << line;
    std::filesystem::remove_all(dir);
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, CppHeader,
                         ::testing::Values("vssm_pcf_fallback", "vsm_blur_mips_bleeding", "layered_vsm_lloyd",
                                           "vssm_minmax_early_out", "pcss_poisson", "vssm_quadtree_table"),
                         [](const auto& info) { return info.param; });

// --generic with --emit cpp: the header carries the shade pass's parameter block, its words
// equal to the bytes the run harness uploads (writeParameterBytes of the manifest as read back)
// and every member as the manifest lists it; a wrong word fails to compile. A header without a
// generic pass declares none of it.
TEST(CppHeader, TheGenericBlockIsTheManifestsParameters) {
  driver::Options o;
  o.engineOutputs = {driver::OutputKind::CppHeader};
  o.generic = true;
  for (const char* sample : {"pcss_poisson", "vssm_quadtree_table"}) {
    const driver::Result r = driver::compileFile(test::samplePath(sample).string(), o);
    ASSERT_TRUE(r.ok) << r.log;
    const std::string name = cppHeaderFileName(sample);
    const Manifest m = manifestFromJson(nlohmann::json::parse(*r.artifact->file(kManifestFile)));
    const Pass* shade = nullptr;
    for (const Pass& p : m.passes)
      if (p.parameters) shade = &p;
    ASSERT_TRUE(shade) << sample << ": a generic build has a parameter block";
    std::vector<uint8_t> bytes;
    writeParameterBytes(*shade->parameters, bytes);
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    const std::string ns = fmt::format("shadowc_filters::{}", sample);
    std::string tu = expectations(m, *r.artifact) +
                     fmt::format(
                         "static_assert(f::parameters.binding == {} && f::parameters.wordCount == {} && "
                         "f::parameters.memberCount == {});\n"
                         "static_assert(fnv(f::parameters.words, f::parameters.wordCount) == {}ull);\n",
                         shade->parameters->binding, words.size(), shade->parameters->members.size(), fnv1a(words));
    for (size_t i = 0; i < shade->parameters->members.size(); ++i) {
      const BlockMember& b = shade->parameters->members[i];
      tu += fmt::format(
          "static_assert(eq(f::parameter_members[{0}].name, {1}) && eq(f::parameter_members[{0}].option, {2}) && "
          "static_cast<int>(f::parameter_members[{0}].type) == {3} && f::parameter_members[{0}].offset == {4} && "
          "f::parameter_members[{0}].stride == {5} && f::parameter_members[{0}].count == {6} && "
          "f::parameter_members[{0}].components == {7});\n",
          i, q(b.name), q(b.macro), static_cast<int>(b.type), b.offset, b.stride, b.count, b.components);
    }
    const auto dir = test::freshTempDir("cpp-header-generic");
    EXPECT_EQ(compileTu(dir, name, *r.artifact->file(name), tu), 0) << test::readFile(dir / "log.txt");
    // Sibling: one word of the block off by one must not compile.
    const std::string wrong = fmt::format("static_assert({}::parameter_words[0] == {}u);\n", ns, words[0] + 1);
    EXPECT_NE(compileTu(dir, name, *r.artifact->file(name), tu + wrong), 0) << "a wrong block word compiled";
    std::filesystem::remove_all(dir);
    // The specialized build's header has no block.
    driver::Options plain = o;
    plain.generic = false;
    const driver::Result p = driver::compileFile(test::samplePath(sample).string(), plain);
    ASSERT_TRUE(p.ok) << p.log;
    EXPECT_EQ(p.artifact->file(name)->find("Parameters"), std::string::npos) << sample;
  }
}

TEST(CppHeader, TwoFilterHeadersShareOneTranslationUnit) {
  driver::Options o;
  o.engineOutputs = {driver::OutputKind::CppHeader};
  const auto dir = test::freshTempDir("cpp-header-two");
  std::string both;
  for (const char* s : {"pcf_grid5x5", "vssm_adaptive"}) {
    const driver::Result r = driver::compileFile(test::samplePath(s).string(), o);
    ASSERT_TRUE(r.ok) << r.log;
    std::ofstream(dir / cppHeaderFileName(s), std::ios::binary) << *r.artifact->file(cppHeaderFileName(s));
    both += "#include \"" + cppHeaderFileName(s) + "\"\n";
  }
  both += "static_assert(shadowc_filters::pcf_grid5x5::filter.passCount >= 1);\n";
  EXPECT_EQ(compileTu(dir, "both.h", both, ""), 0) << test::readFile(dir / "log.txt");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace shadowc

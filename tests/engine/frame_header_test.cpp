// The installed integration header include/shadowc/frame.h: it compiles alone with
// -Wall -Wextra -Werror (with and without GLM), every member's offset equals the std140 offset
// glslang gives the same member of templates/frame_block.glsl, and the `frameReads` list of a
// generated <filter>.h is exactly the set of block members the filter's shade pass reads
// (its SPIR-V's access chains into the block). docs/integration.md "The frame block".
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "backend/spirv_backend.h"
#include "emit/emit_support.h"
#include "emit/template_includes.h"
#include "manifest/frame_uniforms.h"
#include "shadowc_test_paths.h"

namespace shadowc {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("shadowc_frame_header_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Compiles `tu` (which includes <shadowc/frame.h>) against the source tree's include/ only.
int compileAlone(const std::string& name, const std::string& tu, const std::string& flags) {
  const fs::path dir = scratch(name);
  std::ofstream(dir / "check.cpp", std::ios::binary) << tu;
  const std::string cmd = std::string(SHADOWC_CXX_COMPILER) + " -fsyntax-only -Wall -Wextra -Werror -pedantic " +
                          flags + " -I" + (test::sourceDir() / "include").string() + " " +
                          (dir / "check.cpp").string() + " 2>" + (dir / "log.txt").string();
  return std::system(cmd.c_str());
}

TEST(FrameHeader, CompilesAloneWithWarningsAsErrors) {
  const std::string tu =
      "#include <shadowc/frame.h>\nint main() { shadowc::ShadowcFrame f{}; "
      "float v[16] = {}; shadowc::setSpotLight(f, v, 1.f, 1.f, 2.f, 0.5f, false); return 0; }\n";
  EXPECT_EQ(compileAlone("std17_noglm", tu, "-std=c++17 -DSHADOWC_FRAME_NO_GLM"), 0);
  EXPECT_EQ(compileAlone("std20_glm", tu, "-std=c++20"), 0);
  // The GLM overloads are there when GLM is (Debian's libglm-dev is a build dependency).
  const std::string glm =
      "#include <shadowc/frame.h>\nint main() { shadowc::ShadowcFrame f{}; "
      "shadowc::setSunLight(f, glm::mat4(1.f), 3.f, 1.f, 2.f, 0.01); return 0; }\n";
  EXPECT_EQ(compileAlone("glm_overload", glm, "-std=c++20"), 0);
}

// Sibling: the same compile rejects what it should (a wrong offset claim, GLM turned off).
TEST(FrameHeader, TheStandaloneCompileCanFail) {
  EXPECT_NE(compileAlone("bad_offset",
                         "#include <shadowc/frame.h>\n"
                         "static_assert(offsetof(shadowc::ShadowcFrame, mapInfo) == 112);\nint main() {}\n",
                         "-std=c++20"),
            0);
  EXPECT_NE(compileAlone("no_glm",
                         "#include <shadowc/frame.h>\nint main() { shadowc::ShadowcFrame f{}; "
                         "shadowc::setSunLight(f, glm::mat4(1.f), 3.f, 1.f, 2.f, 0.01); }\n",
                         "-std=c++20 -DSHADOWC_FRAME_NO_GLM"),
            0);
}

// member name -> std140 offset of shadowc_FrameBlock, from the SPIR-V glslang emits for it.
std::map<std::string, uint32_t> glslBlockOffsets(const std::string& shader) {
  const IncludeResolver templates = templateIncludes();
  BackendOptions o;
  o.optimize = false;
  const SpirvResult r = compileGlsl(shader, ShaderStage::Compute, "frame_block_probe.comp", templates, o);
  EXPECT_TRUE(r.ok) << r.log;
  const std::string dis = disassembleSpirv(r.words);
  std::smatch m;
  std::map<uint32_t, std::string> names;
  std::map<std::string, uint32_t> out;
  const std::regex name(R"re(OpMemberName %shadowc_FrameBlock (\d+) "(\w+)")re");
  const std::regex offset(R"(OpMemberDecorate %shadowc_FrameBlock (\d+) Offset (\d+))");
  for (auto it = std::sregex_iterator(dis.begin(), dis.end(), name); it != std::sregex_iterator(); ++it)
    names[uint32_t(std::stoul((*it)[1]))] = (*it)[2];
  for (auto it = std::sregex_iterator(dis.begin(), dis.end(), offset); it != std::sregex_iterator(); ++it)
    out[names.at(uint32_t(std::stoul((*it)[1])))] = uint32_t(std::stoul((*it)[2]));
  return out;
}

// A compute shader that declares the whole block (the cascaded form) and reads every member.
std::string blockProbe(const std::string& extraDefines) {
  return "#version 460\n#extension GL_GOOGLE_include_directive : require\n#define SHADOWC_CASCADES 4\n" + extraDefines +
         "#include \"frame.glsl\"\nlayout(local_size_x = 1) in;\nlayout(set = 1, binding = 0) buffer O { vec4 o; };\n"
         "void main() { o = shadowc_frameBlock.lightView[0] + shadowc_frameBlock.lightParams + "
         "shadowc_frameBlock.lightShape + shadowc_frameBlock.mapInfo + shadowc_frameBlock.screenInfo + "
         "shadowc_frameBlock.cascadeInfo + shadowc_frameBlock.cameraDepth + shadowc_frameBlock.cascades[1]; }\n";
}

TEST(FrameHeader, EveryOffsetEqualsTheGlslBlocks) {
  const auto glsl = glslBlockOffsets(blockProbe(""));
  ASSERT_EQ(glsl.size(), std::size(kFrameFields)) << "a member on one side only";
  for (const FrameField& f : kFrameFields) {
    ASSERT_TRUE(glsl.count(f.name)) << f.name << " is not in shadowc_FrameBlock";
    EXPECT_EQ(glsl.at(f.name), f.offset) << f.name;
  }
  // The block's size: the last member's offset plus its size is sizeof(ShadowcFrame).
  EXPECT_EQ(kFrameFields[std::size(kFrameFields) - 1].offset + kFrameFields[std::size(kFrameFields) - 1].size,
            sizeof(ShadowcFrame));
}

// Sibling: a block laid out differently (a member moved) is caught by the same comparison.
TEST(FrameHeader, TheOffsetComparisonCanFail) {
  std::string probe = blockProbe("");
  const std::map<std::string, uint32_t> glsl = glslBlockOffsets(probe);
  std::map<std::string, uint32_t> moved = glsl;
  std::swap(moved.at("mapInfo"), moved.at("screenInfo"));
  int differ = 0;
  for (const FrameField& f : kFrameFields) differ += moved.at(f.name) != f.offset;
  EXPECT_EQ(differ, 2);
}

// Members of shadowc_FrameBlock the shader's access chains reach (the first index after the block).
std::set<std::string> membersRead(const std::vector<uint32_t>& words) {
  const std::string dis = disassembleSpirv(words);
  std::map<uint32_t, std::string> names;
  std::map<std::string, uint32_t> constants;
  std::smatch m;
  std::istringstream in(dis);
  std::string blockVar;
  const std::regex memberName(R"re(OpMemberName %shadowc_FrameBlock (\d+) "(\w+)")re");
  const std::regex constant(R"((%\w+) = OpConstant %(?:int|uint) (\d+))");
  const std::regex variable(R"((%\w+) = OpVariable %_ptr_Uniform_shadowc_FrameBlock Uniform)");
  const std::regex chain(R"(OpAccessChain %\w+ (%\w+) (%\w+))");
  std::vector<std::pair<std::string, std::string>> chains;
  for (std::string line; std::getline(in, line);) {
    if (std::regex_search(line, m, memberName)) names[uint32_t(std::stoul(m[1]))] = m[2];
    if (std::regex_search(line, m, constant)) constants[m[1]] = uint32_t(std::stoul(m[2]));
    if (std::regex_search(line, m, variable)) blockVar = m[1];
    if (std::regex_search(line, m, chain)) chains.emplace_back(m[1], m[2]);
  }
  std::set<std::string> out;
  for (const auto& [base, index] : chains)
    if (base == blockVar && constants.count(index)) out.insert(names.at(constants.at(index)));
  return out;
}

// The generated header's frameReads, parsed back: "kFrameFields[i] /* name */".
std::set<std::string> headerReads(const std::string& header) {
  const size_t at = header.find("frameReads[] = {");
  EXPECT_NE(at, std::string::npos);
  const std::string line = header.substr(at, header.find('\n', at) - at);
  std::set<std::string> out;
  const std::regex entry(R"(kFrameFields\[(\d+)\] /\* (\w+) \*/)");
  for (auto it = std::sregex_iterator(line.begin(), line.end(), entry); it != std::sregex_iterator(); ++it) {
    EXPECT_EQ(kFrameFields[std::stoul((*it)[1])].name, (*it)[2].str());
    out.insert((*it)[2]);
  }
  return out;
}

// The header's list against the shade pass's reads for one filter text.
void expectHeaderListsTheReads(const std::string& text, const std::string& name) {
  driver::Options o;
  o.engineOutputs = {driver::OutputKind::CppHeader};
  o.optimize = false;  // names kept; the -O0 module reads what the lookup's code reads
  const driver::Result r = driver::compileSource(text, name, o);
  ASSERT_TRUE(r.ok) << r.log;
  const Manifest& man = r.artifact->manifest;
  const Pass* shade = nullptr;
  for (const Pass& p : man.passes)
    if (p.kind == "shade") shade = &p;
  ASSERT_NE(shade, nullptr);
  const std::set<std::string> read = membersRead(test::spirvWords(test::artifactFile(r, shade->spirv)));
  ASSERT_FALSE(read.empty()) << "no access chain into shadowc_FrameBlock found: nothing compared";
  EXPECT_EQ(headerReads(test::artifactFile(r, man.filter + ".h")), read) << name;
}

class FrameReads : public ::testing::TestWithParam<std::string> {};

TEST_P(FrameReads, TheHeaderListsExactlyTheMembersTheShadePassReads) {
  expectHeaderListsTheReads(test::readFile(test::samplePath(GetParam())), GetParam() + ".shadow");
}

// The other lights, and the cascaded sun whose block has the cascade fields (no sample uses them).
TEST(FrameReads, SunCascadedSunAndPointLight) {
  for (const char* sample : {"pcf_poisson16", "pcss_poisson"}) {
    const std::string text = test::readFile(test::samplePath(sample));
    const std::string sun = test::withLight(text, "light sun(angle: 0.53)");
    expectHeaderListsTheReads(sun, std::string(sample) + "_sun.shadow");
    const size_t close = sun.rfind('}');
    expectHeaderListsTheReads(sun.substr(0, close) + "    cascades 4\n" + sun.substr(close),
                              std::string(sample) + "_cascaded.shadow");
    expectHeaderListsTheReads(test::withLight(text, "light point(radius: 0.2)"), std::string(sample) + "_point.shadow");
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, FrameReads, ::testing::ValuesIn(test::sampleFilterNames()),
                         [](const auto& info) { return info.param; });

// Sibling: the access-chain reader sees a member read that the header would not list.
TEST(FrameReads, TheMemberReaderSeesEveryMemberAShaderReads) {
  const IncludeResolver templates = templateIncludes();
  BackendOptions o;
  o.optimize = false;
  const SpirvResult r = compileGlsl(blockProbe(""), ShaderStage::Compute, "probe.comp", templates, o);
  ASSERT_TRUE(r.ok) << r.log;
  std::set<std::string> all;
  for (const FrameField& f : kFrameFields) all.insert(f.name);
  EXPECT_EQ(membersRead(r.words), all);
}

}  // namespace
}  // namespace shadowc

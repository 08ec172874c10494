// The installed integration header include/shadowc/frame.h: it compiles alone with
// -Wall -Wextra -Werror (with and without GLM), every member's offset and size and the whole
// size equal the std140 layout glslang gives templates/frame_block.glsl (read back from its
// SPIR-V with SPIRV-Cross; planted copies with a member moved or resized fail), and the `frameReads` list of a
// generated <filter>.h is exactly the set of block members the filter's shade pass reads
// (its SPIR-V's access chains into the block). docs/integration.md "The frame block".
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <spirv_cross/spirv_cross.hpp>
#include <sstream>

#include "backend/spirv_backend.h"
#include "emit/emit_support.h"
#include "emit/template_includes.h"
#include "manifest/frame_uniforms.h"
#include "support/test_support.h"

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
  const std::string cmd = test::cxxCompiler() + " -fsyntax-only -Wall -Wextra -Werror -pedantic " + flags + " -I" +
                          (test::sourceDir() / "include").string() + " " + (dir / "check.cpp").string() + " 2>" +
                          (dir / "log.txt").string();
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

// shadowc_FrameBlock as glslang lays it out (std140) in the SPIR-V it emits, read back with
// SPIRV-Cross: each member's offset and declared size, and the block's size.
struct BlockLayout {
  std::map<std::string, std::pair<uint32_t, uint32_t>> members;  // name -> (offset, size)
  size_t size = 0;
};
BlockLayout glslBlock(const std::string& shader, const IncludeResolver& includes) {
  BackendOptions o;
  o.optimize = false;
  const SpirvResult r = compileGlsl(shader, ShaderStage::Compute, "frame_block_probe.comp", includes, o);
  EXPECT_TRUE(r.ok) << r.log;
  BlockLayout out;
  if (!r.ok) return out;
  const spirv_cross::Compiler reflect(r.words);
  for (const spirv_cross::Resource& ub : reflect.get_shader_resources().uniform_buffers) {
    const spirv_cross::SPIRType& type = reflect.get_type(ub.base_type_id);
    if (reflect.get_name(type.self) != "shadowc_FrameBlock") continue;
    out.size = reflect.get_declared_struct_size(type);
    for (uint32_t i = 0; i < type.member_types.size(); ++i)
      out.members[reflect.get_member_name(type.self, i)] = {reflect.type_struct_member_offset(type, i),
                                                            uint32_t(reflect.get_declared_struct_member_size(type, i))};
  }
  return out;
}

// Where the C++ struct and a GLSL block disagree, one line each; empty when they agree on every
// member's offset and size, the member set and the whole size.
std::vector<std::string> layoutMismatches(const BlockLayout& glsl) {
  std::vector<std::string> out;
  if (glsl.members.size() != std::size(kFrameFields))
    out.push_back(fmt::format("{} members in GLSL, {} in C++", glsl.members.size(), std::size(kFrameFields)));
  for (const FrameField& f : kFrameFields) {
    const auto it = glsl.members.find(f.name);
    if (it == glsl.members.end()) {
      out.push_back(std::string(f.name) + " is not in shadowc_FrameBlock");
      continue;
    }
    if (it->second.first != f.offset)
      out.push_back(fmt::format("{}: offset {} in GLSL, {} in C++", f.name, it->second.first, f.offset));
    if (it->second.second != f.size)
      out.push_back(fmt::format("{}: {} bytes in GLSL, {} in C++", f.name, it->second.second, f.size));
  }
  if (glsl.size != sizeof(ShadowcFrame))
    out.push_back(fmt::format("block: {} bytes in GLSL, sizeof(ShadowcFrame) {}", glsl.size, sizeof(ShadowcFrame)));
  return out;
}

// The template resolver with frame_block.glsl replaced by `text` (a planted copy of the block).
IncludeResolver withFrameBlock(const std::string& text) {
  return [base = templateIncludes(), text](const std::string& name) -> std::optional<std::string> {
    return name == "frame_block.glsl" ? std::optional<std::string>(text) : base(name);
  };
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
  const BlockLayout glsl = glslBlock(blockProbe(""), templateIncludes());
  ASSERT_FALSE(glsl.members.empty()) << "no shadowc_FrameBlock reflected: nothing compared";
  EXPECT_EQ(layoutMismatches(glsl), std::vector<std::string>{});
}

// Sibling: planted copies of templates/frame_block.glsl with a member moved (two swapped) and one
// resized (the last array shortened: every offset the same, only sizes tell) are each caught.
TEST(FrameHeader, TheOffsetComparisonCanFail) {
  const std::optional<std::string> real = templateIncludes()("frame_block.glsl");
  ASSERT_TRUE(real.has_value());
  const std::string mapLine = "  vec4 mapInfo;", screenLine = "  vec4 screenInfo;", arrayLine = "  vec4 cascades[8];";
  ASSERT_NE(real->find(mapLine), std::string::npos);
  ASSERT_NE(real->find(screenLine), std::string::npos);
  ASSERT_NE(real->find(arrayLine), std::string::npos);
  std::string moved = *real;
  moved.replace(moved.find(mapLine), mapLine.size(), "  vec4 SWAP;");
  moved.replace(moved.find(screenLine), screenLine.size(), mapLine);
  moved.replace(moved.find("  vec4 SWAP;"), 12, screenLine);
  const std::vector<std::string> m = layoutMismatches(glslBlock(blockProbe(""), withFrameBlock(moved)));
  EXPECT_EQ(m.size(), 2u) << fmt::format("{}", fmt::join(m, "\n"));
  std::string resized = *real;
  resized.replace(resized.find(arrayLine), arrayLine.size(), "  vec4 cascades[4];");
  const std::vector<std::string> r = layoutMismatches(glslBlock(blockProbe(""), withFrameBlock(resized)));
  EXPECT_EQ(r.size(), 2u) << fmt::format("{}", fmt::join(r, "\n"));  // cascades' size and the block's
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

// The C++ header output (cpp_header.h). Values are written from the Manifest model only, so the
// header and manifest.json cannot disagree (tests/emit/cpp_header_test.cpp compiles one and
// checks every value against the manifest with static_asserts).
#include "emit/cpp_header.h"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "emit/glsl_literal.h"
#include "manifest/frame_uniforms.h"

namespace shadowc {
namespace {

// C++ enumerator names of the generated types, indexed by the manifest enums' values.
constexpr std::array<const char*, 14> kFormatNames{"R32F",    "RG32F",    "RGBA32F",   "R16F",        "RG16F",
                                                   "RGBA16F", "R16Unorm", "RG16Unorm", "RGBA16Unorm", "R32UI",
                                                   "RG32UI",  "RGBA32UI", "D32F",      "D24"};
constexpr std::array<const char*, 6> kRoleNames{"Internal",    "InputDepth",       "InputPosition",
                                                "InputNormal", "OutputVisibility", "InputHardwareDepth"};
constexpr std::array<const char*, 6> kAccessNames{"Sampled",          "StorageRead", "StorageWrite",
                                                  "StorageReadWrite", "Uniform",     "StorageBufferRead"};
constexpr std::array<const char*, 3> kModeNames{"Texels", "Rows", "Columns"};
constexpr std::array<const char*, 3> kScalarNames{"U32", "I32", "F32"};
constexpr std::array<const char*, 2> kDomainNames{"Map", "Screen"};

template <size_t N, typename E>
const char* nameOf(const std::array<const char*, N>& table, E e) {
  const auto i = static_cast<size_t>(e);
  if (i >= N) throw std::invalid_argument("cpp header: enum value out of range");
  return table[i];
}

// The shared declarations; bump the guard's number with any change to them.
constexpr const char* kTypes = R"(#ifndef SHADOWC_GENERATED_TYPES_V3
#define SHADOWC_GENERATED_TYPES_V3
namespace shadowc_filters {
enum class Format : std::uint32_t { R32F, RG32F, RGBA32F, R16F, RG16F, RGBA16F, R16Unorm, RG16Unorm, RGBA16Unorm,
                                    R32UI, RG32UI, RGBA32UI,
                                    D32F, D24 };  // depth: the engine's depth attachment (depth_input)
enum class Role : std::uint32_t { Internal, InputDepth, InputPosition, InputNormal, OutputVisibility,
                                  InputHardwareDepth };
enum class Access : std::uint32_t { Sampled, StorageRead, StorageWrite, StorageReadWrite, Uniform,
                                    StorageBufferRead };
enum class Domain : std::uint32_t { Map, Screen };      // extent = max(1, domain extent >> shift)
enum class DispatchMode : std::uint32_t { Texels, Rows, Columns };
enum class Scalar : std::uint32_t { U32, I32, F32 };
struct SizeRule { Domain domain; int shift; };
struct Image {
  const char* name;
  Format format;
  SizeRule size;
  int mipLevels;  // 0 = full chain
  int layers;
  Role role;
  bool linearFilter;
};
struct Buffer {  // a read-only storage buffer: upload `values` once (little-endian int32)
  const char* name;
  std::uint32_t components;  // int32 per element
  const std::int32_t* values;
  std::size_t valueCount;
};
struct Binding {
  std::uint32_t binding;
  const char* image;  // image name, "frame" (the ShadowcFrame uniform buffer) or a buffer's name
  int imageIndex;     // index into images, or into buffers for StorageBufferRead; -1 for the frame
  Access access;
  int level;          // storage views: the mip level bound; -1 = level 0 / whole image
};
struct PushConstant { const char* name; std::uint32_t offset; Scalar type; double value; };
struct Pass {
  const char* name;
  const char* kind;
  const std::uint32_t* spirv;
  std::size_t spirvWords;
  std::uint32_t localSize[3];
  SizeRule dispatchSize;
  DispatchMode dispatchMode;
  const Binding* bindings;
  std::size_t bindingCount;
  const PushConstant* pushConstants;
  std::size_t pushConstantCount;
};
struct Lookup {  // the includable lookup (manifest "shade")
  const char* glsl;
  const char* function;
  const char* signature;
  std::uint32_t set;
  const Binding* bindings;
  std::size_t bindingCount;
};
struct Filter {
  const char* name;
  const char* compilerVersion;
  const char* contentHash;
  const Image* images;
  std::size_t imageCount;
  const Pass* passes;
  std::size_t passCount;
  Lookup lookup;
  const Buffer* buffers;
  std::size_t bufferCount;
};
}  // namespace shadowc_filters
#endif
)";

// The types of a generic shader's parameter block (`--generic`, manifest "parameters"), only in
// headers that have one, so every other header is unchanged; bump the guard with any change.
constexpr const char* kParameterTypes = R"(#ifndef SHADOWC_GENERATED_PARAMETER_TYPES_V1
#define SHADOWC_GENERATED_PARAMETER_TYPES_V1
namespace shadowc_filters {
struct ParameterMember {  // one member of the generic block (docs/manifest.md "parameters")
  const char* name;       // the GLSL member of shadowc_generic
  const char* option;     // the option or table of the template it replaces
  Scalar type;
  std::uint32_t offset;      // std140 byte offset in the block
  std::uint32_t stride;      // bytes between array elements; 0 for a scalar
  std::uint32_t count;       // declared array length (1 for a scalar)
  std::uint32_t components;  // scalars per element
};
struct Parameters {  // upload `words` into the uniform buffer the bindings name "parameters"
  std::uint32_t binding;  // in the shade pass's set 0 (the lookup's: its lookup binding "parameters")
  const std::uint32_t* words;  // the block's bytes as the manifest's values give them (std140)
  std::size_t wordCount;
  const ParameterMember* members;
  std::size_t memberCount;
};
}  // namespace shadowc_filters
#endif
)";

std::string identifier(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "_" + out;
  return out;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// Exact: %.17g round-trips every double; integers stay integers.
std::string doubleLiteral(double v) {
  std::string s = fmt::format("{:.17g}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string sizeRule(const SizeRule& r) {
  return fmt::format("{{Domain::{}, {}}}", nameOf(kDomainNames, r.domain), r.shift);
}

int imageIndex(const Manifest& m, const Binding& b) {
  if (b.access == Access::StorageBufferRead) {
    for (size_t i = 0; i < m.buffers.size(); ++i)
      if (m.buffers[i].name == b.image) return static_cast<int>(i);
    return -1;
  }
  for (size_t i = 0; i < m.images.size(); ++i)
    if (m.images[i].name == b.image) return static_cast<int>(i);
  return -1;
}

std::string bindingArray(const Manifest& m, const std::string& arrayName, const std::vector<Binding>& bindings) {
  if (bindings.empty()) return "";
  std::string out = fmt::format("inline constexpr Binding {}[] = {{\n", arrayName);
  for (const Binding& b : bindings)
    out += fmt::format("    {{{}, {}, {}, Access::{}, {}}},\n", b.binding, quoted(b.image), imageIndex(m, b),
                       nameOf(kAccessNames, b.access), b.level);
  return out + "};\n";
}

std::string wordArray(const std::string& arrayName, const std::string& bytes) {
  if (bytes.size() % 4 != 0) throw std::invalid_argument("cpp header: SPIR-V size is not a multiple of 4");
  std::string out = fmt::format("inline constexpr std::uint32_t {}[{}] = {{", arrayName, bytes.size() / 4);
  for (size_t i = 0; i < bytes.size() / 4; ++i) {
    uint32_t w = 0;
    for (int b = 0; b < 4; ++b) w |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[4 * i + b])) << (8 * b);
    out += fmt::format("{}0x{:08x}u", i % 8 == 0 ? "\n    " : " ", w);
    if (i + 1 < bytes.size() / 4) out += ",";
  }
  return out + "\n};\n";
}

// The members of ShadowcFrame (include/shadowc/frame.h) the lookup and the shade pass read:
// shadowc_frame()'s two for every filter, the cascade fields for a cascaded sun
// (tests/engine/frame_header_test.cpp checks the list against the block members each sample's
// shade pass SPIR-V reads).
std::string frameReads(const Manifest& m) {
  std::vector<int> fields{0, 1};  // lightView, lightParams: indices into shadowc::kFrameFields
  const bool cascaded = m.spec.is_object() && m.spec.contains("cascades");
  if (cascaded) fields.insert(fields.end(), {5, 6, 7});
  std::string out =
      "\n// What the lookup reads of the ShadowcFrame block (shadowc/frame.h): fill these members with\n"
      "// shadowc::set*Light (and setCascade*); frameBytes is the size of the block it declares.\n"
      "inline constexpr shadowc::FrameField frameReads[] = {";
  for (size_t i = 0; i < fields.size(); ++i)
    out += fmt::format("{}shadowc::kFrameFields[{}] /* {} */", i ? ", " : "", fields[i], kFrameFields[fields[i]].name);
  return out + fmt::format("}};\ninline constexpr std::size_t frameBytes = {};\n",
                           cascaded ? "sizeof(shadowc::ShadowcFrame)" : "shadowc::kFrameBaseSize");
}

// The generic shade pass's block (plan/generic_block.h): its bytes, as the run harness uploads
// them (writeParameterBytes), and its members, so an engine can rewrite a value at run time.
std::string parameterBlock(const Manifest& m) {
  const Pass* with = nullptr;
  for (const Pass& p : m.passes)
    if (p.parameters) {
      if (with) throw std::invalid_argument("cpp header: more than one pass has a parameter block");
      with = &p;
    }
  if (!with) return "";
  const ParameterBlock& block = *with->parameters;
  std::vector<uint8_t> bytes;
  writeParameterBytes(block, bytes);
  std::string out = fmt::format("\n// The generic block of pass '{}' (shadowc compile --generic).\n", with->name);
  out += wordArray("parameter_words", std::string(bytes.begin(), bytes.end()));
  out += "inline constexpr ParameterMember parameter_members[] = {\n";
  for (const BlockMember& b : block.members)
    out += fmt::format("    {{{}, {}, Scalar::{}, {}, {}, {}, {}}},\n", quoted(b.name), quoted(b.macro),
                       nameOf(kScalarNames, b.type), b.offset, b.stride, b.count, b.components);
  return out +
         fmt::format("}};\ninline constexpr Parameters parameters{{{}, parameter_words, {}, parameter_members, {}}};\n",
                     block.binding, bytes.size() / 4, block.members.size());
}

}  // namespace

std::string cppHeaderFileName(const std::string& filterName) { return filterName + ".h"; }

std::string cppHeader(const Manifest& m, const std::map<std::string, std::string>& spirv) {
  std::string out = fmt::format(
      "// {} - generated by shadowc {} from filter '{}' (content hash {}). Do not edit.\n"
      "// The filter's passes (SPIR-V) and manifest as constexpr data: docs/integration.md.\n"
      "#pragma once\n#include <shadowc/frame.h>\n\n#include <cstddef>\n#include <cstdint>\n\n",
      cppHeaderFileName(m.filter), m.compilerVersion, m.filter, m.contentHash);
  out += kTypes;
  const std::string parameters = parameterBlock(m);
  if (!parameters.empty()) out += kParameterTypes;
  out += fmt::format("\nnamespace shadowc_filters::{} {{\nusing namespace shadowc_filters;\n\n", identifier(m.filter));

  // SPIR-V, one array per distinct file (passes that share a shader share the array).
  std::map<std::string, std::string> arrayOf;
  for (const Pass& p : m.passes) {
    if (arrayOf.count(p.spirv)) continue;
    const auto it = spirv.find(p.spirv);
    if (it == spirv.end()) throw std::invalid_argument("cpp header: pass '" + p.name + "' names missing " + p.spirv);
    const std::string name = "spirv_" + identifier(p.spirv.substr(0, p.spirv.rfind('.')));
    arrayOf[p.spirv] = name;
    out += "// " + p.spirv + "\n" + wordArray(name, it->second);
  }

  out += "\ninline constexpr Image images[] = {\n";
  for (const ImageDesc& i : m.images)
    out += fmt::format("    {{{}, Format::{}, {}, {}, {}, Role::{}, {}}},\n", quoted(i.name),
                       nameOf(kFormatNames, i.format), sizeRule(i.size), i.mipLevels, i.layers,
                       nameOf(kRoleNames, i.role), i.linearFilter ? "true" : "false");
  out += "};\n\n";
  for (size_t i = 0; i < m.buffers.size(); ++i) {
    const BufferDesc& b = m.buffers[i];
    out += fmt::format("inline constexpr std::int32_t buffer{}_values[{}] = {{", i, b.values.size());
    for (size_t k = 0; k < b.values.size(); ++k)
      out += fmt::format("{}{}{}", k % 16 == 0 ? "\n    " : " ", b.values[k], k + 1 < b.values.size() ? "," : "");
    out += "\n};\n";
  }
  if (!m.buffers.empty()) {
    out += "inline constexpr Buffer buffers[] = {\n";
    for (size_t i = 0; i < m.buffers.size(); ++i)
      out += fmt::format("    {{{}, {}, buffer{}_values, {}}},\n", quoted(m.buffers[i].name), m.buffers[i].components,
                         i, m.buffers[i].values.size());
    out += "};\n\n";
  }

  for (size_t i = 0; i < m.passes.size(); ++i) {
    const Pass& p = m.passes[i];
    out += bindingArray(m, fmt::format("pass{}_bindings", i), p.bindings);
    if (!p.pushConstants.empty()) {
      out += fmt::format("inline constexpr PushConstant pass{}_push[] = {{\n", i);
      for (const PushConstant& c : p.pushConstants)
        out += fmt::format("    {{{}, {}, Scalar::{}, {}}},\n", quoted(c.name), c.offset, nameOf(kScalarNames, c.type),
                           doubleLiteral(c.value));
      out += "};\n";
    }
  }
  out += "\ninline constexpr Pass passes[] = {\n";
  for (size_t i = 0; i < m.passes.size(); ++i) {
    const Pass& p = m.passes[i];
    const std::string& arr = arrayOf.at(p.spirv);
    out +=
        fmt::format("    {{{}, {}, {}, sizeof {} / 4, {{{}, {}, {}}}, {}, DispatchMode::{},\n     {}, {}, {}, {}}},\n",
                    quoted(p.name), quoted(p.kind), arr, arr, p.localSize[0], p.localSize[1], p.localSize[2],
                    sizeRule(p.dispatch.size), nameOf(kModeNames, p.dispatch.mode),
                    p.bindings.empty() ? "nullptr" : fmt::format("pass{}_bindings", i), p.bindings.size(),
                    p.pushConstants.empty() ? "nullptr" : fmt::format("pass{}_push", i), p.pushConstants.size());
  }
  out += "};\n\n";
  out += bindingArray(m, "lookup_bindings", m.shade.bindings);
  out += frameReads(m);
  out += parameters;
  // The map side the filter is planned for (`resolution`, docs/dsl.md): what to allocate; 0 = the engine's choice.
  const int planned = m.spec.is_object() && m.spec.contains("resolution") ? m.spec["resolution"].get<int>() : 0;
  out += fmt::format("inline constexpr std::uint32_t plannedMapSize = {};\n", planned);
  // The depth attachment a depth_input filter reads (docs/dsl.md "depth_input"): reverse Z means
  // the light pass clears to 0 and keeps the greater depth; the format is its image's.
  const bool reversed = m.spec.is_object() && m.spec.contains("depth_input") &&
                        m.spec["depth_input"].value("z", std::string("standard")) == "reverse";
  out += fmt::format("inline constexpr bool depthInputReversed = {};\n", reversed ? "true" : "false");
  // The light views to render (`light_samples`, docs/integration.md "Light samples"): view i from
  // the light view translated by -width * lightViewOffsets[i], into tile (i % lightViewGrid,
  // i / lightViewGrid) of the light-depth atlas. Only with light samples, so other headers are unchanged.
  if (m.spec.is_object() && m.spec.contains("light_samples")) {
    const nlohmann::json& v = m.spec["light_samples"];
    out += fmt::format("inline constexpr std::uint32_t lightViewCount = {};\n", v["count"].get<int>());
    out += fmt::format("inline constexpr std::uint32_t lightViewGrid = {};\n", v["grid"].get<int>());
    out += "inline constexpr float lightViewOffsets[][2] = {";
    for (const nlohmann::json& o : v["offsets"])
      out += fmt::format("{{{}f, {}f}}, ", glslFloat(o[0].get<double>()), glslFloat(o[1].get<double>()));
    out += "};\n";
  }
  out += fmt::format(
      "\ninline constexpr Filter filter{{\n    {}, {}, {},\n    images, sizeof images / sizeof images[0],\n"
      "    passes, sizeof passes / sizeof passes[0],\n    {{{}, {}, {}, {}, {}, {}}},\n    {}, {}}};\n\n}}  // "
      "namespace "
      "shadowc_filters::{}\n",
      quoted(m.filter), quoted(m.compilerVersion), quoted(m.contentHash), quoted(m.shade.glsl),
      quoted(m.shade.function), quoted(m.shade.signature), m.shade.set,
      m.shade.bindings.empty() ? "nullptr" : "lookup_bindings", m.shade.bindings.size(),
      m.buffers.empty() ? "nullptr" : "buffers", m.buffers.size(), identifier(m.filter));
  return out;
}

}  // namespace shadowc

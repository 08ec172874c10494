#include "manifest/manifest.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

namespace shadowc {
namespace {

template <typename E, size_t N>
E parseEnum(const nlohmann::json& j, const char* field, const std::array<std::pair<E, const char*>, N>& table) {
  if (!j.contains(field) || !j.at(field).is_string())
    throw ManifestError(std::string("manifest: missing or non-string field '") + field + "'");
  const std::string v = j.at(field).get<std::string>();
  for (const auto& [e, name] : table)
    if (v == name) return e;
  throw ManifestError(std::string("manifest: unknown value '") + v + "' for field '" + field + "'");
}

constexpr std::array<std::pair<ImageFormat, const char*>, 14> kFormats{{{ImageFormat::R32F, "r32f"},
                                                                        {ImageFormat::RG32F, "rg32f"},
                                                                        {ImageFormat::RGBA32F, "rgba32f"},
                                                                        {ImageFormat::R16F, "r16f"},
                                                                        {ImageFormat::RG16F, "rg16f"},
                                                                        {ImageFormat::RGBA16F, "rgba16f"},
                                                                        {ImageFormat::R16Unorm, "r16"},
                                                                        {ImageFormat::RG16Unorm, "rg16"},
                                                                        {ImageFormat::RGBA16Unorm, "rgba16"},
                                                                        {ImageFormat::R32UI, "r32ui"},
                                                                        {ImageFormat::RG32UI, "rg32ui"},
                                                                        {ImageFormat::RGBA32UI, "rgba32ui"},
                                                                        {ImageFormat::D32F, "d32f"},
                                                                        {ImageFormat::D24, "d24"}}};
constexpr std::array<std::pair<ImageRole, const char*>, 6> kRoles{
    {{ImageRole::Internal, "internal"},
     {ImageRole::InputDepth, "input_depth"},
     {ImageRole::InputPosition, "input_position"},
     {ImageRole::InputNormal, "input_normal"},
     {ImageRole::OutputVisibility, "output_visibility"},
     {ImageRole::InputHardwareDepth, "input_hardware_depth"}}};
constexpr std::array<std::pair<Access, const char*>, 7> kAccess{
    {{Access::Sampled, "sampled"},
     {Access::StorageRead, "storage_read"},
     {Access::StorageWrite, "storage_write"},
     {Access::StorageReadWrite, "storage_read_write"},
     {Access::Uniform, "uniform"},
     {Access::StorageBufferRead, "storage_buffer_read"},
     {Access::StorageBufferReadWrite, "storage_buffer_read_write"}}};
constexpr std::array<std::pair<DispatchMode, const char*>, 5> kModes{{{DispatchMode::Texels, "texels"},
                                                                      {DispatchMode::Rows, "rows"},
                                                                      {DispatchMode::Columns, "columns"},
                                                                      {DispatchMode::RowGroups, "row_groups"},
                                                                      {DispatchMode::ColumnGroups, "column_groups"}}};
constexpr std::array<std::pair<FormDevice, const char*>, 3> kDevices{
    {{FormDevice::Any, "any"}, {FormDevice::Cpu, "cpu"}, {FormDevice::Gpu, "gpu"}}};
constexpr std::array<std::pair<ScalarType, const char*>, 3> kScalars{
    {{ScalarType::U32, "u32"}, {ScalarType::I32, "i32"}, {ScalarType::F32, "f32"}}};
constexpr std::array<std::pair<SizeDomain, const char*>, 2> kDomains{
    {{SizeDomain::Map, "map"}, {SizeDomain::Screen, "screen"}}};

template <typename E, size_t N>
const char* nameOf(E e, const std::array<std::pair<E, const char*>, N>& table) {
  for (const auto& [v, name] : table)
    if (v == e) return name;
  return "?";
}

const nlohmann::json& field(const nlohmann::json& j, const char* name) {
  if (!j.is_object() || !j.contains(name)) throw ManifestError(std::string("manifest: missing field '") + name + "'");
  return j.at(name);
}

template <typename T>
struct IsIntegerArray : std::false_type {};
template <typename T, size_t N>
struct IsIntegerArray<std::array<T, N>> : std::bool_constant<std::is_integral_v<T> && !std::is_same_v<T, bool>> {};

// A JSON integer that fits T (`wrong` names the field): nlohmann's get<T> would cast anything
// else, and a float cast out of range is undefined behaviour (fuzz_manifest found a 49-digit
// "shift", and later a huge float in "local_size").
template <typename T, typename Wrong>
T integer(const nlohmann::json& v, const Wrong& wrong) {
  if (!v.is_number_integer()) throw wrong("has the wrong type (an integer is expected)");
  const bool fits = v.is_number_unsigned() ? std::in_range<T>(v.get<uint64_t>()) : std::in_range<T>(v.get<int64_t>());
  if (!fits) throw wrong("is out of range");
  return v.get<T>();
}

template <typename T>
T get(const nlohmann::json& j, const char* name) {
  const nlohmann::json& v = field(j, name);
  const auto wrong = [&](const char* why) {
    return ManifestError(std::string("manifest: field '") + name + "' " + why);
  };
  // Integer fields and arrays of them go through integer(); doubles (the only floating fields)
  // cannot overflow a double.
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    return integer<T>(v, wrong);
  } else if constexpr (IsIntegerArray<T>::value) {
    T out{};
    if (!v.is_array() || v.size() != out.size())
      throw wrong(("has the wrong type (an array of " + std::to_string(out.size()) + " integers is expected)").c_str());
    for (size_t i = 0; i < out.size(); ++i) out[i] = integer<typename T::value_type>(v[i], wrong);
    return out;
  } else {
    try {
      return v.get<T>();
    } catch (const nlohmann::json::exception&) {
      throw wrong("has the wrong type");
    }
  }
}

nlohmann::ordered_json sizeJson(const SizeRule& s) {
  nlohmann::ordered_json j;
  j["domain"] = nameOf(s.domain, kDomains);
  j["shift"] = s.shift;
  return j;
}
SizeRule sizeFromJson(const nlohmann::json& j) {
  SizeRule s;
  s.domain = parseEnum(j, "domain", kDomains);
  s.shift = get<int>(j, "shift");
  if (s.shift < 0 || s.shift > 16) throw ManifestError("manifest: size shift out of range [0,16]");
  return s;
}

nlohmann::ordered_json bindingJson(const Binding& b) {
  nlohmann::ordered_json j;
  j["binding"] = b.binding;
  j["image"] = b.image;
  j["access"] = nameOf(b.access, kAccess);
  j["level"] = b.level;
  return j;
}
Binding bindingFromJson(const nlohmann::json& j) {
  Binding b;
  b.binding = get<uint32_t>(j, "binding");
  b.image = get<std::string>(j, "image");
  b.access = parseEnum(j, "access", kAccess);
  b.level = get<int>(j, "level");
  return b;
}

nlohmann::ordered_json parametersJson(const ParameterBlock& b) {
  nlohmann::ordered_json j;
  j["binding"] = b.binding;
  j["size"] = b.size;
  auto& ms = j["members"] = nlohmann::ordered_json::array();
  for (const BlockMember& m : b.members)
    ms.push_back({{"name", m.name},
                  {"macro", m.macro},
                  {"type", nameOf(m.type, kScalars)},
                  {"offset", m.offset},
                  {"stride", m.stride},
                  {"count", m.count},
                  {"components", m.components},
                  {"values", m.values}});
  return j;
}

// Every member must fit the block: the runtime writes these bytes without asking the shader.
ParameterBlock parametersFromJson(const nlohmann::json& j, const std::string& pass) {
  ParameterBlock b;
  b.binding = get<uint32_t>(j, "binding");
  b.size = get<uint32_t>(j, "size");
  if (b.size == 0 || b.size > 65536 || b.size % 16)
    throw ManifestError("manifest: pass '" + pass + "': parameter block size must be a multiple of 16 in [16, 65536]");
  for (const auto& e : field(j, "members")) {
    BlockMember m;
    m.name = get<std::string>(e, "name");
    m.macro = get<std::string>(e, "macro");
    m.type = parseEnum(e, "type", kScalars);
    m.offset = get<uint32_t>(e, "offset");
    m.stride = get<uint32_t>(e, "stride");
    m.count = get<uint32_t>(e, "count");
    m.components = get<uint32_t>(e, "components");
    m.values = get<std::vector<double>>(e, "values");
    const uint64_t elementBytes = 4ull * m.components;
    const uint64_t end = m.offset + uint64_t(m.count ? m.count - 1 : 0) * m.stride + elementBytes;
    if (m.count == 0 || m.components == 0 || m.components > 4 || m.offset % 4 ||
        (m.count > 1 && m.stride < elementBytes) || end > b.size || m.values.size() > uint64_t(m.count) * m.components)
      throw ManifestError("manifest: pass '" + pass + "': parameter '" + m.name + "' does not fit the block");
    b.members.push_back(std::move(m));
  }
  return b;
}

nlohmann::ordered_json needsJson(const FormNeeds& n) {
  nlohmann::ordered_json j;
  j["device"] = nameOf(n.device, kDevices);
  j["subgroup_size_min"] = n.subgroupSizeMin;
  j["subgroup_operations"] = n.subgroupOperations;
  return j;
}
FormNeeds needsFromJson(const nlohmann::json& j, const std::string& where) {
  FormNeeds n;
  n.device = parseEnum(j, "device", kDevices);
  n.subgroupSizeMin = get<uint32_t>(j, "subgroup_size_min");
  n.subgroupOperations = get<std::vector<std::string>>(j, "subgroup_operations");
  const auto& known = subgroupOperationNames();
  for (const std::string& op : n.subgroupOperations)
    if (std::find(known.begin(), known.end(), op) == known.end())
      throw ManifestError("manifest: " + where + ": unknown subgroup operation '" + op + "'");
  return n;
}

// The alternatives of a pass: each names a shader and how to dispatch it; the bindings are the pass's.
void formsFromJson(const nlohmann::json& e, Pass& p) {
  if (!e.contains("form")) {
    if (e.contains("forms") || e.contains("needs"))
      throw ManifestError("manifest: pass '" + p.name + "' lists forms but does not name its own ('form')");
    return;
  }
  p.form = get<std::string>(e, "form");
  p.formNeeds = needsFromJson(field(e, "needs"), "pass '" + p.name + "'");
  for (const auto& f : field(e, "forms")) {
    PassForm form;
    form.name = get<std::string>(f, "form");
    form.needs = needsFromJson(field(f, "needs"), "pass '" + p.name + "' form '" + form.name + "'");
    form.spirv = get<std::string>(f, "spirv");
    form.glsl = get<std::string>(f, "glsl");
    form.localSize = get<std::array<uint32_t, 3>>(f, "local_size");
    const auto& d = field(f, "dispatch");
    form.dispatch.size = sizeFromJson(field(d, "size"));
    form.dispatch.mode = parseEnum(d, "mode", kModes);
    p.forms.push_back(std::move(form));
  }
  std::vector<std::string> names;
  for (const PassForm& f : formsOf(p)) {
    if (f.name.empty() || std::find(names.begin(), names.end(), f.name) != names.end())
      throw ManifestError("manifest: pass '" + p.name + "': form names must be unique and non-empty ('" + f.name +
                          "')");
    names.push_back(f.name);
  }
}

// A buffer's values are whole elements, and the runtime uploads them as they are: at least one
// element, at most 1 MiB (a quadtree table of height 5 is 21,840 bytes).
BufferDesc bufferFromJson(const nlohmann::json& j) {
  BufferDesc b;
  b.name = get<std::string>(j, "name");
  b.components = get<uint32_t>(j, "components");
  const nlohmann::json& values = field(j, "values");
  if (!values.is_array()) throw ManifestError("manifest: buffer '" + b.name + "': field 'values' is not an array");
  const auto wrong = [&](const char* why) {
    return ManifestError("manifest: buffer '" + b.name + "': a value " + why);
  };
  for (const auto& v : values) b.values.push_back(integer<int32_t>(v, wrong));
  if (b.components == 0 || b.components > 4 || b.values.empty() || b.values.size() % b.components ||
      b.values.size() > (1u << 18))
    throw ManifestError("manifest: buffer '" + b.name + "' must hold whole elements of 1 to 4 int32 (" +
                        std::to_string(b.values.size()) + " values, " + std::to_string(b.components) +
                        " per element), at most 1 MiB");
  if (j.contains("fields")) {
    b.fields = get<std::vector<std::string>>(j, "fields");
    if (b.fields.empty() || b.fields.size() * b.components != b.values.size())
      throw ManifestError("manifest: buffer '" + b.name + "' names " + std::to_string(b.fields.size()) +
                          " fields for " + std::to_string(b.values.size() / b.components) + " elements");
  }
  return b;
}

}  // namespace

const std::vector<std::string>& passFormNames() {
  static const std::vector<std::string> names = {"serial", "parallel"};
  return names;
}

const std::vector<std::string>& subgroupOperationNames() {
  static const std::vector<std::string> names = {
      "basic", "vote", "arithmetic", "ballot", "shuffle", "shuffle_relative", "clustered", "quad"};
  return names;
}

std::vector<PassForm> formsOf(const Pass& pass) {
  std::vector<PassForm> out{{pass.form, pass.formNeeds, pass.spirv, pass.glsl, pass.localSize, pass.dispatch}};
  out.insert(out.end(), pass.forms.begin(), pass.forms.end());
  return out;
}

Pass withForm(Pass pass, const PassForm& form) {
  pass.form = form.name;
  pass.formNeeds = form.needs;
  pass.spirv = form.spirv;
  pass.glsl = form.glsl;
  pass.localSize = form.localSize;
  pass.dispatch = form.dispatch;
  pass.forms.clear();
  return pass;
}

void writeParameterBytes(const ParameterBlock& block, std::vector<uint8_t>& bytes) {
  bytes.assign(block.size, 0);
  for (const BlockMember& m : block.members)
    for (size_t i = 0; i < m.values.size(); ++i) {
      const size_t at = m.offset + (i / m.components) * m.stride + (i % m.components) * 4;
      if (at + 4 > bytes.size()) throw ManifestError("manifest: parameter '" + m.name + "' does not fit the block");
      uint32_t bits = 0;
      switch (m.type) {
        case ScalarType::U32:
          bits = uint32_t(m.values[i]);
          break;
        case ScalarType::I32:
          bits = std::bit_cast<uint32_t>(int32_t(m.values[i]));
          break;
        case ScalarType::F32:
          bits = std::bit_cast<uint32_t>(float(m.values[i]));
          break;
      }
      std::memcpy(bytes.data() + at, &bits, 4);
    }
}

const char* toString(ImageFormat f) { return nameOf(f, kFormats); }
const char* toString(ImageRole r) { return nameOf(r, kRoles); }
const char* toString(Access a) { return nameOf(a, kAccess); }
const char* toString(DispatchMode m) { return nameOf(m, kModes); }
const char* toString(ScalarType t) { return nameOf(t, kScalars); }
const char* toString(SizeDomain d) { return nameOf(d, kDomains); }
const char* toString(FormDevice d) { return nameOf(d, kDevices); }

uint32_t bytesPerTexel(ImageFormat f) {
  switch (f) {
    case ImageFormat::R32F:
    case ImageFormat::R32UI:
    case ImageFormat::D32F:
    case ImageFormat::D24:  // X8_D24: one 32-bit word, depth in the low 24 bits
      return 4;
    case ImageFormat::RG32F:
    case ImageFormat::RG32UI:
      return 8;
    case ImageFormat::RGBA32F:
    case ImageFormat::RGBA32UI:
      return 16;
    case ImageFormat::R16F:
    case ImageFormat::R16Unorm:
      return 2;
    case ImageFormat::RG16F:
    case ImageFormat::RG16Unorm:
      return 4;
    case ImageFormat::RGBA16F:
    case ImageFormat::RGBA16Unorm:
      return 8;
  }
  return 0;
}

std::array<uint32_t, 2> extentOf(const SizeRule& rule, uint32_t mapSize, uint32_t screenWidth, uint32_t screenHeight) {
  const uint32_t w = rule.domain == SizeDomain::Map ? mapSize : screenWidth;
  const uint32_t h = rule.domain == SizeDomain::Map ? mapSize : screenHeight;
  return {std::max(1u, w >> rule.shift), std::max(1u, h >> rule.shift)};
}

nlohmann::ordered_json toJson(const Manifest& m) {
  nlohmann::ordered_json j;
  j["format_version"] = m.formatVersion;
  j["compiler_version"] = m.compilerVersion;
  j["filter"] = m.filter;
  j["spec"] = m.spec;
  auto& images = j["images"] = nlohmann::ordered_json::array();
  for (const auto& im : m.images) {
    nlohmann::ordered_json e;
    e["name"] = im.name;
    e["format"] = toString(im.format);
    e["size"] = sizeJson(im.size);
    e["mip_levels"] = im.mipLevels;
    e["layers"] = im.layers;
    e["role"] = toString(im.role);
    e["linear_filter"] = im.linearFilter;
    images.push_back(std::move(e));
  }
  if (!m.buffers.empty()) {
    auto& buffers = j["buffers"] = nlohmann::ordered_json::array();
    for (const auto& b : m.buffers) {
      nlohmann::ordered_json e{{"name", b.name}, {"components", b.components}};
      if (!b.fields.empty()) e["fields"] = b.fields;
      e["values"] = b.values;
      buffers.push_back(std::move(e));
    }
  }
  auto& passes = j["passes"] = nlohmann::ordered_json::array();
  for (const auto& p : m.passes) {
    nlohmann::ordered_json e;
    e["name"] = p.name;
    e["kind"] = p.kind;
    e["spirv"] = p.spirv;
    e["glsl"] = p.glsl;
    e["local_size"] = p.localSize;
    e["dispatch"] = {{"size", sizeJson(p.dispatch.size)}, {"mode", toString(p.dispatch.mode)}};
    auto& bs = e["bindings"] = nlohmann::ordered_json::array();
    for (const auto& b : p.bindings) bs.push_back(bindingJson(b));
    auto& pcs = e["push_constants"] = nlohmann::ordered_json::array();
    for (const auto& pc : p.pushConstants)
      pcs.push_back({{"name", pc.name}, {"offset", pc.offset}, {"type", toString(pc.type)}, {"value", pc.value}});
    if (p.parameters) e["parameters"] = parametersJson(*p.parameters);
    if (!p.form.empty()) {
      e["form"] = p.form;
      e["needs"] = needsJson(p.formNeeds);
      auto& fs = e["forms"] = nlohmann::ordered_json::array();
      for (const PassForm& f : p.forms)
        fs.push_back({{"form", f.name},
                      {"needs", needsJson(f.needs)},
                      {"spirv", f.spirv},
                      {"glsl", f.glsl},
                      {"local_size", f.localSize},
                      {"dispatch", {{"size", sizeJson(f.dispatch.size)}, {"mode", toString(f.dispatch.mode)}}}});
    }
    passes.push_back(std::move(e));
  }
  nlohmann::ordered_json shade;
  shade["glsl"] = m.shade.glsl;
  shade["function"] = m.shade.function;
  shade["signature"] = m.shade.signature;
  shade["set"] = m.shade.set;
  auto& sb = shade["bindings"] = nlohmann::ordered_json::array();
  for (const auto& b : m.shade.bindings) sb.push_back(bindingJson(b));
  j["shade"] = std::move(shade);
  j["content_hash"] = m.contentHash;
  return j;
}

Manifest manifestFromJson(const nlohmann::json& j) {
  if (!j.is_object()) throw ManifestError("manifest: not a JSON object");
  // Other JSON (a scene, a sweep description) named where a manifest goes: say what it is not.
  if (!j.contains("format_version"))
    throw ManifestError(
        "not a shadowc manifest (no \"format_version\"; `shadowc compile FILTER.shadow -o DIR` writes one)");
  Manifest m;
  m.formatVersion = get<int>(j, "format_version");
  if (m.formatVersion != kManifestFormatVersion)
    throw ManifestError("manifest: format version " + std::to_string(m.formatVersion) +
                        " is not supported (this build reads version " + std::to_string(kManifestFormatVersion) +
                        "); recompile the filter with this shadowc");
  m.compilerVersion = get<std::string>(j, "compiler_version");
  m.filter = get<std::string>(j, "filter");
  m.spec = field(j, "spec");
  for (const auto& e : field(j, "images")) {
    ImageDesc im;
    im.name = get<std::string>(e, "name");
    im.format = parseEnum(e, "format", kFormats);
    im.size = sizeFromJson(field(e, "size"));
    im.mipLevels = get<int>(e, "mip_levels");
    im.layers = get<int>(e, "layers");
    im.role = parseEnum(e, "role", kRoles);
    im.linearFilter = get<bool>(e, "linear_filter");
    m.images.push_back(std::move(im));
  }
  if (j.contains("buffers"))
    for (const auto& e : field(j, "buffers")) m.buffers.push_back(bufferFromJson(e));
  for (const auto& e : field(j, "passes")) {
    Pass p;
    p.name = get<std::string>(e, "name");
    p.kind = get<std::string>(e, "kind");
    p.spirv = get<std::string>(e, "spirv");
    p.glsl = get<std::string>(e, "glsl");
    p.localSize = get<std::array<uint32_t, 3>>(e, "local_size");
    const auto& d = field(e, "dispatch");
    p.dispatch.size = sizeFromJson(field(d, "size"));
    p.dispatch.mode = parseEnum(d, "mode", kModes);
    for (const auto& b : field(e, "bindings")) p.bindings.push_back(bindingFromJson(b));
    for (const auto& pc : field(e, "push_constants"))
      p.pushConstants.push_back({get<std::string>(pc, "name"), get<uint32_t>(pc, "offset"),
                                 parseEnum(pc, "type", kScalars), get<double>(pc, "value")});
    if (e.contains("parameters")) p.parameters = parametersFromJson(e["parameters"], p.name);
    formsFromJson(e, p);
    m.passes.push_back(std::move(p));
  }
  const auto& s = field(j, "shade");
  m.shade.glsl = get<std::string>(s, "glsl");
  m.shade.function = get<std::string>(s, "function");
  m.shade.signature = get<std::string>(s, "signature");
  m.shade.set = s.contains("set") ? get<uint32_t>(s, "set") : 0;  // absent before --lookup-set: set 0
  for (const auto& b : field(s, "bindings")) m.shade.bindings.push_back(bindingFromJson(b));
  m.contentHash = get<std::string>(j, "content_hash");
  // Cross-references: every binding names a declared image (or the frame buffer).
  for (const auto& p : m.passes)
    for (const auto& b : p.bindings) {
      if (b.access == Access::Uniform && b.image == kParametersBinding &&
          (!p.parameters || p.parameters->binding != b.binding))
        throw ManifestError("manifest: pass '" + p.name + "' binds 'parameters' at " + std::to_string(b.binding) +
                            " but has no parameter block there");
      if (b.access == Access::Uniform) continue;
      if (b.access == Access::StorageBufferRead || b.access == Access::StorageBufferReadWrite) {
        if (!std::any_of(m.buffers.begin(), m.buffers.end(), [&](const BufferDesc& d) { return d.name == b.image; }))
          throw ManifestError("manifest: pass '" + p.name + "' binds unknown buffer '" + b.image + "'");
        continue;
      }
      const bool known =
          std::any_of(m.images.begin(), m.images.end(), [&](const ImageDesc& im) { return im.name == b.image; });
      if (!known) throw ManifestError("manifest: pass '" + p.name + "' binds unknown image '" + b.image + "'");
    }
  return m;
}

Manifest loadManifest(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ManifestError("cannot open manifest '" + path + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(ss.str(), nullptr, false);
  if (j.is_discarded()) throw ManifestError("manifest '" + path + "' is not valid JSON");
  try {
    return manifestFromJson(j);
  } catch (const ManifestError& e) {
    throw ManifestError(path + ": " + e.what());
  }
}

}  // namespace shadowc

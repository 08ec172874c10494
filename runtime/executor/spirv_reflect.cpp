#include "runtime/executor/spirv_reflect.h"

#include <map>
#include <set>
#include <stdexcept>

#include <glslang/SPIRV/spirv.hpp>

namespace shadowc::rt {
namespace {

std::optional<ImageFormat> manifestFormat(uint32_t f) {
  switch (f) {
    case spv::ImageFormatR32f: return ImageFormat::R32F;
    case spv::ImageFormatRg32f: return ImageFormat::RG32F;
    case spv::ImageFormatRgba32f: return ImageFormat::RGBA32F;
    case spv::ImageFormatR16f: return ImageFormat::R16F;
    case spv::ImageFormatRg16f: return ImageFormat::RG16F;
    case spv::ImageFormatRgba16f: return ImageFormat::RGBA16F;
    case spv::ImageFormatR16: return ImageFormat::R16Unorm;
    case spv::ImageFormatRg16: return ImageFormat::RG16Unorm;
    case spv::ImageFormatRgba16: return ImageFormat::RGBA16Unorm;
    case spv::ImageFormatR32ui: return ImageFormat::R32UI;
    case spv::ImageFormatRg32ui: return ImageFormat::RG32UI;
    case spv::ImageFormatRgba32ui: return ImageFormat::RGBA32UI;
    default: return std::nullopt;
  }
}

struct TypeInfo {
  uint32_t opcode = 0;
  std::vector<uint32_t> operands;  // after the result id
};

}  // namespace

const char* toString(DescriptorKind k) {
  switch (k) {
    case DescriptorKind::UniformBuffer: return "uniform buffer";
    case DescriptorKind::StorageBuffer: return "storage buffer";
    case DescriptorKind::StorageImage: return "storage image";
    case DescriptorKind::CombinedImageSampler: return "combined image sampler";
    case DescriptorKind::Other: return "other descriptor";
  }
  return "?";
}

ReflectedModule reflectSpirv(const std::vector<uint32_t>& words) {
  if (words.size() < 5 || words[0] != spv::MagicNumber) throw std::invalid_argument("not a SPIR-V module (bad magic number)");
  std::map<uint32_t, TypeInfo> types;
  std::map<uint32_t, uint32_t> bindingOf, setOf;
  std::map<uint32_t, std::string> names;
  std::set<uint32_t> bufferBlocks;
  struct Var { uint32_t id, pointerType, storageClass; };
  std::vector<Var> vars;
  ReflectedModule out;
  for (size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, op = words[i] & 0xffff;
    if (count == 0 || i + count > words.size()) throw std::invalid_argument("truncated SPIR-V instruction");
    const uint32_t* w = &words[i];
    switch (op) {
      case spv::OpName: {
        std::string s;
        for (uint32_t k = 2; k < count; ++k)
          for (int b = 0; b < 4; ++b) {
            const char c = char((w[k] >> (8 * b)) & 0xff);
            if (c == 0) k = count, b = 4;
            else s += c;
          }
        names[w[1]] = s;
        break;
      }
      case spv::OpDecorate:
        if (count >= 4 && w[2] == spv::DecorationBinding) bindingOf[w[1]] = w[3];
        if (count >= 4 && w[2] == spv::DecorationDescriptorSet) setOf[w[1]] = w[3];
        if (count >= 3 && w[2] == spv::DecorationBufferBlock) bufferBlocks.insert(w[1]);  // SPIR-V < 1.3 SSBOs
        break;
      case spv::OpExecutionMode:
        if (count >= 6 && w[2] == spv::ExecutionModeLocalSize) out.localSize = std::array<uint32_t, 3>{w[3], w[4], w[5]};
        break;
      case spv::OpTypeImage: case spv::OpTypeSampledImage: case spv::OpTypeArray: case spv::OpTypeStruct:
      case spv::OpTypeSampler: case spv::OpTypePointer: case spv::OpTypeRuntimeArray:
        types[w[1]] = TypeInfo{op, std::vector<uint32_t>(w + 2, w + count)};
        break;
      case spv::OpVariable:
        vars.push_back({w[2], w[1], w[3]});
        break;
      default:
        break;
    }
    i += count;
  }
  for (const Var& v : vars) {
    if (!bindingOf.count(v.id)) continue;
    ReflectedBinding b;
    b.binding = bindingOf[v.id];
    b.set = setOf.count(v.id) ? setOf[v.id] : 0;
    if (names.count(v.id)) b.variable = names[v.id];
    const auto ptr = types.find(v.pointerType);
    uint32_t pointee = ptr != types.end() && ptr->second.operands.size() >= 2 ? ptr->second.operands[1] : 0;
    auto t = types.find(pointee);
    if (t != types.end() && (t->second.opcode == spv::OpTypeArray || t->second.opcode == spv::OpTypeRuntimeArray))
      t = types.find(t->second.operands.at(0));  // arrays of descriptors: look at the element
    const bool block = t != types.end() && t->second.opcode == spv::OpTypeStruct;
    if (block && (v.storageClass == spv::StorageClassStorageBuffer || bufferBlocks.count(t->first))) {
      b.kind = DescriptorKind::StorageBuffer;
    } else if (v.storageClass == spv::StorageClassUniform && block) {
      b.kind = DescriptorKind::UniformBuffer;
    } else if (t != types.end() && t->second.opcode == spv::OpTypeSampledImage) {
      b.kind = DescriptorKind::CombinedImageSampler;
      const auto img = types.find(t->second.operands.at(0));
      if (img != types.end() && img->second.operands.size() >= 7) b.arrayed = img->second.operands[3] != 0;
    } else if (t != types.end() && t->second.opcode == spv::OpTypeImage && t->second.operands.size() >= 7) {
      // Operands: sampled type, Dim, Depth, Arrayed, MS, Sampled (2 = storage), Format.
      b.arrayed = t->second.operands[3] != 0;
      b.kind = t->second.operands[5] == 2 ? DescriptorKind::StorageImage : DescriptorKind::Other;
      b.format = manifestFormat(t->second.operands[6]);
    }
    out.bindings.push_back(b);
  }
  return out;
}

}  // namespace shadowc::rt

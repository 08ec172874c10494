// Which (set, binding) of a SPIR-V module is an arrayed image (sampler2DArray, image2DArray):
// the view an engine creates for it must be a 2D array view. Engines reflect their modules
// anyway (SPIRV-Reflect, SPIRV-Cross); these few lines read only what the sample needs.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace engine {

inline std::set<std::pair<uint32_t, uint32_t>> arrayedBindings(const std::vector<uint32_t>& w) {
  enum : uint32_t { TypeImage = 25, TypeSampledImage = 27, TypePointer = 32, Variable = 59, Decorate = 71 };
  enum : uint32_t { Binding = 33, DescriptorSet = 34 };
  std::map<uint32_t, uint32_t> set, binding, pointee, sampledImage;
  std::set<uint32_t> arrayedImages;
  std::map<uint32_t, uint32_t> variableType;
  for (size_t i = 5; i < w.size();) {
    const uint32_t op = w[i] & 0xffff, n = w[i] >> 16;
    if (n == 0 || i + n > w.size()) break;
    if (op == Decorate && n >= 4 && w[i + 2] == DescriptorSet) set[w[i + 1]] = w[i + 3];
    if (op == Decorate && n >= 4 && w[i + 2] == Binding) binding[w[i + 1]] = w[i + 3];
    if (op == TypeImage && n >= 7 && w[i + 5] == 1) arrayedImages.insert(w[i + 1]);
    if (op == TypeSampledImage && n >= 3) sampledImage[w[i + 1]] = w[i + 2];
    if (op == TypePointer && n >= 4) pointee[w[i + 1]] = w[i + 3];
    if (op == Variable && n >= 4) variableType[w[i + 2]] = w[i + 1];
    i += n;
  }
  std::set<std::pair<uint32_t, uint32_t>> out;
  for (const auto& [var, ptr] : variableType) {
    if (!set.count(var) || !binding.count(var) || !pointee.count(ptr)) continue;
    uint32_t type = pointee[ptr];
    if (sampledImage.count(type)) type = sampledImage[type];
    if (arrayedImages.count(type)) out.insert({set[var], binding[var]});
  }
  return out;
}

}  // namespace engine

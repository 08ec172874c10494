#include "runtime/executor/pass_executor.h"

#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <map>
#include <tuple>

#include "runtime/executor/spirv_reflect.h"
#include "runtime/vulkan/vulkan_context.h"
#include "runtime/vulkan/vulkan_error.h"
#include "runtime/vulkan/vulkan_formats.h"
#include "runtime/vulkan/vulkan_resources.h"

namespace shadowc::rt {
namespace {

bool isStorage(Access a) {
  return a == Access::StorageRead || a == Access::StorageWrite || a == Access::StorageReadWrite;
}

uint32_t ceilDiv(uint32_t a, uint32_t b) { return (a + b - 1) / b; }

// A binding's descriptor, and the kind the shader must declare for it.
VkDescriptorType descriptorType(Access a) {
  return a == Access::Uniform                                                    ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER
         : a == Access::StorageBufferRead || a == Access::StorageBufferReadWrite ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER
         : isStorage(a)                                                          ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                        : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
}
DescriptorKind descriptorKind(Access a) {
  return a == Access::Uniform                                                    ? DescriptorKind::UniformBuffer
         : a == Access::StorageBufferRead || a == Access::StorageBufferReadWrite ? DescriptorKind::StorageBuffer
         : isStorage(a)                                                          ? DescriptorKind::StorageImage
                                                                                 : DescriptorKind::CombinedImageSampler;
}
bool isBuffer(Access a) { return a == Access::StorageBufferRead || a == Access::StorageBufferReadWrite; }
bool isImage(Access a) { return a != Access::Uniform && !isBuffer(a); }

// The pass's module from the compiled files (little-endian words, as every .spv is stored).
std::vector<uint32_t> spirvWords(const CompiledPasses& compiled, const Pass& pass) {
  const auto it = compiled.files.find(pass.spirv);
  if (it == compiled.files.end())
    throw ExecutorError(fmt::format("pass '{}': SPIR-V file '{}' not found", pass.name, pass.spirv));
  const std::string& bytes = it->second;
  if (bytes.empty() || bytes.size() % 4 != 0)
    throw ExecutorError(
        fmt::format("pass '{}': '{}' is not a SPIR-V module ({} bytes)", pass.name, pass.spirv, bytes.size()));
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  return words;
}

}  // namespace

std::array<uint32_t, 3> dispatchGroups(const Pass& pass, uint32_t mapSize, uint32_t screenWidth,
                                       uint32_t screenHeight) {
  const auto [w, h] = extentOf(pass.dispatch.size, mapSize, screenWidth, screenHeight);
  const uint32_t lx = std::max(1u, pass.localSize[0]), ly = std::max(1u, pass.localSize[1]);
  switch (pass.dispatch.mode) {
    case DispatchMode::Texels:
      return {ceilDiv(w, lx), ceilDiv(h, ly), 1};
    case DispatchMode::Rows:
      return {ceilDiv(h, lx), 1, 1};
    case DispatchMode::Columns:
      return {ceilDiv(w, lx), 1, 1};
    case DispatchMode::RowGroups:
      return {h, 1, 1};
    case DispatchMode::ColumnGroups:
      return {w, 1, 1};
  }
  return {1, 1, 1};
}

uint32_t mipLevelCount(const ImageDesc& image, uint32_t width, uint32_t height) {
  const uint32_t full = std::bit_width(std::max(width, height));  // floor(log2(max)) + 1
  return image.mipLevels <= 0 ? full : std::min<uint32_t>(uint32_t(image.mipLevels), full);
}

struct PassExecutor::Impl {
  struct ImageResource {
    ImageDesc desc;
    Image image;
    bool storage = false, sampled = false;
    UniqueSampler sampler;
    std::map<std::tuple<bool, int, bool>, UniqueImageView> views;  // (all levels, level, arrayed)
  };
  struct PassResource {
    UniqueShaderModule module;
    UniqueDescriptorSetLayout setLayout;
    UniquePipelineLayout layout;
    UniquePipeline pipeline;
    VkDescriptorSet set = VK_NULL_HANDLE;
    std::vector<uint8_t> push;
    Buffer parameters;  // the pass's ParameterBlock (generic shaders), written once from the manifest
    std::array<uint32_t, 3> groups{1, 1, 1};
  };

  VulkanContext& ctx;
  Manifest manifest;
  uint32_t mapSize, width, height;
  std::vector<ImageResource> images;
  std::map<std::string, size_t> imageIndex;
  Buffer frame;
  // The manifest's "buffers", written from its values at creation (and by resetBuffers: the work
  // counters a counted run adds into).
  std::map<std::string, Buffer> buffers;
  UniqueDescriptorPool pool;
  std::vector<PassResource> passes;
  UniqueQueryPool queries;
  VkCommandBuffer cmd = VK_NULL_HANDLE;       // the whole run, stamped
  std::vector<VkCommandBuffer> passCmds;      // one pass each, unstamped: the host clock's runs
  VkCommandBuffer emptyCmd = VK_NULL_HANDLE;  // nothing: one submission's host overhead
  HostClock hostClock = steadyHostClock();
  std::vector<FormChoice> formChoices;

  Impl(VulkanContext& c, const Manifest& m, uint32_t map, uint32_t w, uint32_t h)
      : ctx(c), manifest(m), mapSize(map), width(w), height(h) {}
  ~Impl() {
    if (ctx.device()) vkQueueWaitIdle(ctx.queue());
    for (VkCommandBuffer c : allCommandBuffers())
      if (c) vkFreeCommandBuffers(ctx.device(), ctx.commandPool(), 1, &c);
  }

  ImageResource& image(const std::string& name, const char* what) {
    const auto it = imageIndex.find(name);
    if (it == imageIndex.end()) throw ExecutorError(fmt::format("{}: the manifest has no image '{}'", what, name));
    return images[it->second];
  }

  VkImageView view(ImageResource& im, bool allLevels, int level, bool arrayed) {
    auto& v = im.views[{allLevels, level, arrayed}];
    if (!v.get())
      v = createView(ctx, im.image, arrayed ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D,
                     aspectOf(im.desc.format), allLevels ? 0 : uint32_t(level), allLevels ? im.image.levels : 1);
    return v.get();
  }

  void createImages() {
    for (const auto& desc : manifest.images) {
      if (imageIndex.count(desc.name))
        throw ExecutorError(fmt::format("manifest: image '{}' is declared twice", desc.name));
      if (desc.layers < 1)
        throw ExecutorError(fmt::format("manifest: image '{}' has {} layers", desc.name, desc.layers));
      imageIndex[desc.name] = images.size();
      images.push_back(ImageResource{desc, {}, false, false, {}, {}});
    }
    for (const auto& pass : manifest.passes)
      for (const auto& b : pass.bindings) {
        if (!isImage(b.access)) continue;
        const auto it = imageIndex.find(b.image);
        if (it == imageIndex.end())
          throw ExecutorError(fmt::format("pass '{}': binding {} names image '{}', which the manifest does not declare",
                                          pass.name, b.binding, b.image));
        auto& im = images[it->second];
        (isStorage(b.access) ? im.storage : im.sampled) = true;
      }
    // Usage follows what the passes do with each image; the device must support it.
    for (auto& im : images) {
      const VkFormat format = vkFormatOf(im.desc.format);
      const VkFormatFeatureFlags features = ctx.formatFeatures(format);
      auto require = [&](VkFormatFeatureFlags bit, const char* what) {
        if (features & bit) return;
        std::string user = "no pass";
        for (const auto& pass : manifest.passes)
          for (const auto& b : pass.bindings)
            if (b.image == im.desc.name) user = "pass '" + pass.name + "'";
        throw ExecutorError(fmt::format("{}: image '{}' format {} is not supported for {} on {}", user, im.desc.name,
                                        toString(im.desc.format), what, ctx.deviceName()));
      };
      VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
      if (im.storage) {
        require(VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT, "storage");
        usage |= VK_IMAGE_USAGE_STORAGE_BIT;
      }
      if (im.sampled || im.desc.linearFilter) {
        require(VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT, "sampling");
        usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
      }
      if (im.desc.linearFilter) {
        if (isIntegerFormat(im.desc.format))
          throw ExecutorError(fmt::format("manifest: image '{}' is {} and cannot be linearly filtered", im.desc.name,
                                          toString(im.desc.format)));
        require(VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT, "linear filtering");
      }
      const auto [w, h] = extentOf(im.desc.size, mapSize, width, height);
      im.image = createImage(ctx, format, w, h, mipLevelCount(im.desc, w, h), uint32_t(im.desc.layers), usage);

      VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
      const VkFilter filter = im.desc.linearFilter ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
      s.magFilter = s.minFilter = filter;
      s.mipmapMode = im.desc.linearFilter ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
      s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
      s.maxLod = float(im.image.levels);
      VkSampler sampler = VK_NULL_HANDLE;
      checkVk(vkCreateSampler(ctx.device(), &s, nullptr, &sampler), "vkCreateSampler");
      im.sampler = UniqueSampler(ctx.device(), sampler);
    }
    // Every image lives in GENERAL from here on, zero-filled so that results never depend on
    // stale memory.
    ctx.submitAndWait([&](VkCommandBuffer c) {
      std::vector<VkImageMemoryBarrier> barriers;
      for (auto& im : images) {
        VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
        b.srcAccessMask = 0;
        b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = im.image.image;
        b.subresourceRange = {aspectOf(im.desc.format), 0, im.image.levels, 0, im.image.layers};
        barriers.push_back(b);
      }
      vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                           nullptr, uint32_t(barriers.size()), barriers.data());
      const VkClearColorValue zero{};
      const VkClearDepthStencilValue zeroDepth{};
      for (auto& im : images) {
        const VkImageSubresourceRange range{aspectOf(im.desc.format), 0, im.image.levels, 0, im.image.layers};
        if (isDepthFormat(im.desc.format))
          vkCmdClearDepthStencilImage(c, im.image.image, VK_IMAGE_LAYOUT_GENERAL, &zeroDepth, 1, &range);
        else
          vkCmdClearColorImage(c, im.image.image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
      }
    });
  }

  void createPasses(const CompiledPasses& compiled) {
    frame = createHostBuffer(ctx, sizeof(ShadowcFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(frame.mapped, 0, sizeof(ShadowcFrame));

    for (const auto& desc : manifest.buffers) {
      if (buffers.count(desc.name))
        throw ExecutorError(fmt::format("manifest: buffer '{}' is declared twice", desc.name));
      const size_t bytes = desc.values.size() * sizeof(int32_t);
      if (bytes == 0) throw ExecutorError(fmt::format("manifest: buffer '{}' is empty", desc.name));
      Buffer& b = buffers[desc.name] = createHostBuffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      std::memcpy(b.mapped, desc.values.data(), bytes);  // little-endian int32, as the manifest says
    }

    std::map<VkDescriptorType, uint32_t> counts;
    for (const auto& pass : manifest.passes)
      for (const auto& b : pass.bindings) ++counts[descriptorType(b.access)];
    std::vector<VkDescriptorPoolSize> sizes;
    for (const auto& [type, n] : counts) sizes.push_back({type, n});
    if (sizes.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1});
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = std::max<uint32_t>(1, uint32_t(manifest.passes.size()));
    poolInfo.poolSizeCount = uint32_t(sizes.size());
    poolInfo.pPoolSizes = sizes.data();
    VkDescriptorPool p = VK_NULL_HANDLE;
    checkVk(vkCreateDescriptorPool(ctx.device(), &poolInfo, nullptr, &p), "vkCreateDescriptorPool");
    pool = UniqueDescriptorPool(ctx.device(), p);

    for (const auto& pass : manifest.passes) passes.push_back(createPass(pass, compiled));

    VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    q.queryType = VK_QUERY_TYPE_TIMESTAMP;
    q.queryCount = queryCount();
    VkQueryPool qp = VK_NULL_HANDLE;
    checkVk(vkCreateQueryPool(ctx.device(), &q, nullptr, &qp), "vkCreateQueryPool");
    queries = UniqueQueryPool(ctx.device(), qp);
  }

  PassResource createPass(const Pass& pass, const CompiledPasses& compiled) {
    PassResource r;
    const std::vector<uint32_t> words = spirvWords(compiled, pass);
    ReflectedModule reflected;
    try {
      reflected = reflectSpirv(words);
    } catch (const std::exception& e) {
      throw ExecutorError(fmt::format("pass '{}': {}: {}", pass.name, pass.spirv, e.what()));
    }
    if (reflected.localSize && *reflected.localSize != pass.localSize)
      throw ExecutorError(fmt::format("pass '{}': the manifest says local size {}x{}x{}, the shader declares {}x{}x{}",
                                      pass.name, pass.localSize[0], pass.localSize[1], pass.localSize[2],
                                      (*reflected.localSize)[0], (*reflected.localSize)[1], (*reflected.localSize)[2]));
    std::map<uint32_t, ReflectedBinding> declared;
    for (const auto& rb : reflected.bindings) {
      if (rb.set != 0)
        throw ExecutorError(
            fmt::format("pass '{}': the shader uses descriptor set {} (only set 0 is supported)", pass.name, rb.set));
      declared[rb.binding] = rb;
    }
    std::map<uint32_t, const Binding*> listed;
    for (const auto& b : pass.bindings) {
      if (listed.count(b.binding))
        throw ExecutorError(fmt::format("pass '{}': binding {} is listed twice", pass.name, b.binding));
      listed[b.binding] = &b;
    }
    for (const auto& [n, rb] : declared)
      if (!listed.count(n))
        throw ExecutorError(
            fmt::format("pass '{}': the shader declares binding {} ({}) that the manifest does not list", pass.name, n,
                        rb.variable.empty() ? toString(rb.kind) : rb.variable));

    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    for (const auto& b : pass.bindings) {
      const VkDescriptorType type = descriptorType(b.access);
      if (declared.count(b.binding) && declared[b.binding].kind != descriptorKind(b.access))
        throw ExecutorError(fmt::format("pass '{}': binding {} ('{}') is {} in the manifest but a {} in the shader",
                                        pass.name, b.binding, b.image, toString(b.access),
                                        toString(declared[b.binding].kind)));
      layoutBindings.push_back({b.binding, type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    }
    VkDescriptorSetLayoutCreateInfo dsl{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    dsl.bindingCount = uint32_t(layoutBindings.size());
    dsl.pBindings = layoutBindings.data();
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    checkVk(vkCreateDescriptorSetLayout(ctx.device(), &dsl, nullptr, &setLayout), "vkCreateDescriptorSetLayout");
    r.setLayout = UniqueDescriptorSetLayout(ctx.device(), setLayout);

    // Push constants: one block, bytes laid out at the manifest's offsets.
    uint32_t pushSize = 0;
    for (const auto& pc : pass.pushConstants) pushSize = std::max(pushSize, pc.offset + 4);
    if (pushSize > ctx.properties().limits.maxPushConstantsSize)
      throw ExecutorError(fmt::format("pass '{}': {} bytes of push constants exceed the device limit {}", pass.name,
                                      pushSize, ctx.properties().limits.maxPushConstantsSize));
    r.push.assign(pushSize, 0);
    for (const auto& pc : pass.pushConstants) {
      if (pc.offset % 4)
        throw ExecutorError(
            fmt::format("pass '{}': push constant '{}' offset {} is not 4-aligned", pass.name, pc.name, pc.offset));
      uint32_t bits = 0;
      switch (pc.type) {
        case ScalarType::U32:
          bits = uint32_t(pc.value);
          break;
        case ScalarType::I32:
          bits = std::bit_cast<uint32_t>(int32_t(pc.value));
          break;
        case ScalarType::F32:
          bits = std::bit_cast<uint32_t>(float(pc.value));
          break;
      }
      std::memcpy(r.push.data() + pc.offset, &bits, 4);
    }
    const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushSize};
    VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &setLayout;
    pl.pushConstantRangeCount = pushSize ? 1 : 0;
    pl.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    checkVk(vkCreatePipelineLayout(ctx.device(), &pl, nullptr, &layout), "vkCreatePipelineLayout");
    r.layout = UniquePipelineLayout(ctx.device(), layout);

    r.module = createShaderModule(ctx, words.data(), words.size());
    VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    ci.stage.module = r.module;
    ci.stage.pName = "main";
    ci.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    const VkResult pr = vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline);
    if (pr != VK_SUCCESS)
      throw ExecutorError(
          fmt::format("pass '{}': creating the compute pipeline failed: {}", pass.name, vkResultName(pr)));
    r.pipeline = UniquePipeline(ctx.device(), pipeline);

    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &setLayout;
    checkVk(vkAllocateDescriptorSets(ctx.device(), &ai, &r.set), "vkAllocateDescriptorSets");

    std::vector<VkDescriptorImageInfo> imageInfos;
    imageInfos.reserve(pass.bindings.size());
    std::vector<VkDescriptorBufferInfo> bufferInfos;
    bufferInfos.reserve(pass.bindings.size());
    const VkDescriptorBufferInfo bufferInfo{frame.buffer, 0, sizeof(ShadowcFrame)};
    VkDescriptorBufferInfo parameterInfo{VK_NULL_HANDLE, 0, 0};
    if (pass.parameters) {
      // The generic shader's options: the manifest's values, laid out as it says (std140).
      if (pass.parameters->size > ctx.properties().limits.maxUniformBufferRange)
        throw ExecutorError(fmt::format("pass '{}': the {}-byte parameter block exceeds the device limit {}", pass.name,
                                        pass.parameters->size, ctx.properties().limits.maxUniformBufferRange));
      std::vector<uint8_t> bytes;
      writeParameterBytes(*pass.parameters, bytes);
      r.parameters = createHostBuffer(ctx, bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      std::memcpy(r.parameters.mapped, bytes.data(), bytes.size());
      parameterInfo = {r.parameters.buffer, 0, bytes.size()};
    }
    std::vector<VkWriteDescriptorSet> writes;
    for (const auto& b : pass.bindings) {
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = r.set;
      w.dstBinding = b.binding;
      w.descriptorCount = 1;
      if (b.access == Access::Uniform) {
        w.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        if (b.image == kParametersBinding && !pass.parameters)
          throw ExecutorError(fmt::format("pass '{}': binding {} is 'parameters' but the pass has no parameter block",
                                          pass.name, b.binding));
        w.pBufferInfo = b.image == kParametersBinding ? &parameterInfo : &bufferInfo;
        writes.push_back(w);
        continue;
      }
      if (isBuffer(b.access)) {
        const auto it = buffers.find(b.image);
        if (it == buffers.end())
          throw ExecutorError(
              fmt::format("pass '{}': binding {} names buffer '{}', which the manifest does not declare", pass.name,
                          b.binding, b.image));
        bufferInfos.push_back({it->second.buffer, 0, VK_WHOLE_SIZE});
        w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        w.pBufferInfo = &bufferInfos.back();
        writes.push_back(w);
        continue;
      }
      ImageResource& im = images[imageIndex.at(b.image)];
      const bool multiLayer = im.image.layers > 1;
      bool arrayed = multiLayer;
      if (declared.count(b.binding)) {
        const ReflectedBinding& rb = declared[b.binding];
        arrayed = rb.arrayed;
        if (multiLayer && !rb.arrayed)
          throw ExecutorError(
              fmt::format("pass '{}': image '{}' has {} layers but binding {} is not an array image in the shader",
                          pass.name, b.image, im.image.layers, b.binding));
        if (rb.kind == DescriptorKind::StorageImage && rb.format && *rb.format != im.desc.format)
          throw ExecutorError(
              fmt::format("pass '{}': binding {} ('{}') is {} in the manifest but the shader declares {}", pass.name,
                          b.binding, b.image, toString(im.desc.format), toString(*rb.format)));
      }
      if (isStorage(b.access)) {
        const int level = std::max(0, b.level);
        if (uint32_t(level) >= im.image.levels)
          throw ExecutorError(fmt::format("pass '{}': binding {} uses level {} of '{}', which has {} levels", pass.name,
                                          b.binding, level, b.image, im.image.levels));
        imageInfos.push_back({VK_NULL_HANDLE, view(im, false, level, arrayed), VK_IMAGE_LAYOUT_GENERAL});
        w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
      } else {
        imageInfos.push_back({im.sampler, view(im, true, 0, arrayed), VK_IMAGE_LAYOUT_GENERAL});
        w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      }
      w.pImageInfo = &imageInfos.back();
      writes.push_back(w);
    }
    vkUpdateDescriptorSets(ctx.device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
    r.groups = dispatchGroups(pass, mapSize, width, height);
    return r;
  }

  std::vector<VkCommandBuffer> allCommandBuffers() const {
    std::vector<VkCommandBuffer> all = passCmds;
    all.push_back(cmd);
    all.push_back(emptyCmd);
    return all;
  }

  // One reusable command buffer: a stamp before the first pass and one after each pass's
  // closing barrier; pass i's time is stamp[i+1] - stamp[i]. Each stamp is followed by a
  // second, throw-away stamp: lavapipe (Mesa 22.3) queues a timestamp to its rasterizer threads,
  // which take its value only after the next flush, and a non-TOP_OF_PIPE vkCmdWriteTimestamp
  // flushes first. Even so those threads race the compute threads for the cores, so a CPU
  // device's stamps can be late by a whole pass: it is timed on the host clock instead
  // (docs/runtime.md "Timing method").
  void stamp(uint32_t point) {
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 2 * point);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 2 * point + 1);
  }

  VkCommandBuffer beginCommands() {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = ctx.commandPool();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer c = VK_NULL_HANDLE;
    checkVk(vkAllocateCommandBuffers(ctx.device(), &alloc, &c), "vkAllocateCommandBuffers");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    checkVk(vkBeginCommandBuffer(c, &begin), "vkBeginCommandBuffer");
    return c;
  }

  void recordPass(VkCommandBuffer c, const PassResource& p) {
    vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline);
    vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout, 0, 1, &p.set, 0, nullptr);
    if (!p.push.empty())
      vkCmdPushConstants(c, p.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, uint32_t(p.push.size()), p.push.data());
    vkCmdDispatch(c, p.groups[0], p.groups[1], p.groups[2]);
    // The next pass reads (or overwrites) what this one wrote; the stamp waits for it too.
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 1, &b, 0,
                         nullptr, 0, nullptr);
  }

  void record() {
    cmd = beginCommands();
    vkCmdResetQueryPool(cmd, queries, 0, queryCount());
    fullBarrier(cmd);  // uploads and the previous run happen before this one
    stamp(0);
    for (size_t i = 0; i < passes.size(); ++i) {
      recordPass(cmd, passes[i]);
      stamp(uint32_t(i + 1));
    }
    if (writesBuffers()) hostBarrier(cmd);
    checkVk(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
    for (const PassResource& p : passes) {
      passCmds.push_back(beginCommands());
      fullBarrier(passCmds.back());  // the previous submission's writes
      recordPass(passCmds.back(), p);
      checkVk(vkEndCommandBuffer(passCmds.back()), "vkEndCommandBuffer");
    }
    emptyCmd = beginCommands();
    checkVk(vkEndCommandBuffer(emptyCmd), "vkEndCommandBuffer");
  }

  bool writesBuffers() const {
    for (const Pass& p : manifest.passes)
      for (const Binding& b : p.bindings)
        if (b.access == Access::StorageBufferReadWrite) return true;
    return false;
  }
  // The shaders' buffer writes made visible to the host that reads them back (readBuffer).
  static void hostBarrier(VkCommandBuffer c) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &b, 0, nullptr, 0,
                         nullptr);
  }

  uint32_t queryCount() const { return 2 * (uint32_t(manifest.passes.size()) + 1); }
};

PassExecutor::PassExecutor(VulkanContext& ctx, const CompiledPasses& compiled, uint32_t mapSize, uint32_t screenWidth,
                           uint32_t screenHeight, const std::string& passForm) {
  ChosenForms chosen =
      chooseForms(compiled.manifest, deviceTraits(ctx), passForm.empty() ? passFormFromEnvironment() : passForm);
  impl_ = std::make_unique<Impl>(ctx, chosen.manifest, mapSize, screenWidth, screenHeight);
  impl_->formChoices = std::move(chosen.choices);
  const Manifest& manifest = compiled.manifest;
  if (manifest.formatVersion != kManifestFormatVersion)
    throw ExecutorError(
        fmt::format("manifest format version {} is not supported (this build runs version {}); "
                    "recompile the filter with this shadowc",
                    manifest.formatVersion, kManifestFormatVersion));
  if (mapSize == 0 || screenWidth == 0 || screenHeight == 0)
    throw ExecutorError("map and screen sizes must be positive");
  impl_->createImages();
  impl_->createPasses(compiled);
  impl_->record();
}

PassExecutor::~PassExecutor() = default;

const Manifest& PassExecutor::manifest() const { return impl_->manifest; }

const std::vector<FormChoice>& PassExecutor::formChoices() const { return impl_->formChoices; }

std::string PassExecutor::imageWithRole(ImageRole role) const {
  for (const auto& im : impl_->manifest.images)
    if (im.role == role) return im.name;
  return "";
}

void PassExecutor::setFrame(const ShadowcFrame& frame) { std::memcpy(impl_->frame.mapped, &frame, sizeof frame); }

void PassExecutor::upload(const std::string& name, const HostImage& data) {
  auto& im = impl_->image(name, "upload");
  if (data.width != im.image.width || data.height != im.image.height || data.layers != im.image.layers ||
      data.format != im.desc.format)
    throw ExecutorError(fmt::format("upload '{}': got a {}x{}x{} {} image, the manifest needs {}x{}x{} {}", name,
                                    data.width, data.height, data.layers, toString(data.format), im.image.width,
                                    im.image.height, im.image.layers, toString(im.desc.format)));
  if (data.bytes.size() != size_t(data.width) * data.height * data.layers * bytesPerTexel(data.format))
    throw ExecutorError(fmt::format("upload '{}': {} bytes do not match the image size", name, data.bytes.size()));
  Buffer staging = createHostBuffer(impl_->ctx, data.bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::memcpy(staging.mapped, data.bytes.data(), data.bytes.size());
  impl_->ctx.submitAndWait([&](VkCommandBuffer c) {
    // Copies go through the TRANSFER_*_OPTIMAL layouts (core validation warns on GENERAL);
    // passes always see GENERAL.
    const VkImageSubresourceRange range{aspectOf(im.desc.format), 0, 1, 0, im.image.layers};
    imageBarrier(c, im.image.image, range, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT | VK_ACCESS_MEMORY_READ_BIT,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {aspectOf(im.desc.format), 0, 0, im.image.layers};
    copy.imageExtent = {im.image.width, im.image.height, 1};
    vkCmdCopyBufferToImage(c, staging.buffer, im.image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    imageBarrier(c, im.image.image, range, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                 VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
  });
}

void PassExecutor::run() { impl_->ctx.submitAndWait(impl_->cmd); }

namespace {

// The executor's runs as the timing loop sees them (run_timing.h).
class ExecutorRuns final : public TimedDevice {
 public:
  ExecutorRuns(VulkanContext& ctx, VkQueryPool queries, VkCommandBuffer run, const std::vector<VkCommandBuffer>& passes,
               VkCommandBuffer empty)
      : ctx_(ctx), queries_(queries), run_(run), passes_(passes), empty_(empty) {}
  size_t passCount() const override { return passes_.size(); }
  void submitRun() override { ctx_.submitAndWait(run_); }
  void submitPass(size_t pass) override { ctx_.submitAndWait(passes_.at(pass)); }
  void submitEmpty() override { ctx_.submitAndWait(empty_); }
  double timestampTickMs() const override { return ctx_.properties().limits.timestampPeriod * 1e-6; }
  RunReading readTimestamps() override {
    const size_t n = passes_.size();
    std::vector<uint64_t> ticks(2 * (n + 1));
    checkVk(vkGetQueryPoolResults(ctx_.device(), queries_, 0, uint32_t(ticks.size()), ticks.size() * sizeof(uint64_t),
                                  ticks.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
            "vkGetQueryPoolResults");
    // Signed: a stamp taken out of order is a negative time, which the check rejects.
    const auto ms = [&](size_t a, size_t b) { return double(int64_t(ticks[b] - ticks[a])) * timestampTickMs(); };
    RunReading r;
    for (size_t i = 0; i < n; ++i) r.passMs.push_back(ms(2 * i, 2 * (i + 1)));
    r.totalMs = ms(0, 2 * n);
    return r;
  }

 private:
  VulkanContext& ctx_;
  VkQueryPool queries_;
  VkCommandBuffer run_;
  const std::vector<VkCommandBuffer>& passes_;
  VkCommandBuffer empty_;
};

}  // namespace

TimingResult PassExecutor::time(int warmup, const RunCount& runs, ClockChoice choice) {
  const bool cpu = impl_->ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  ExecutorRuns device(impl_->ctx, impl_->queries, impl_->cmd, impl_->passCmds, impl_->emptyCmd);
  std::vector<std::string> names, kinds;
  for (const Pass& p : impl_->manifest.passes) {
    names.push_back(p.name);
    kinds.push_back(p.kind);
  }
  try {
    return timeRuns(device, resolveClock(choice, cpu), impl_->hostClock, warmup, runs, names, kinds);
  } catch (const VulkanError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw ExecutorError(e.what());
  }
}

void PassExecutor::resetBuffers() {
  for (const BufferDesc& desc : impl_->manifest.buffers)
    std::memcpy(impl_->buffers.at(desc.name).mapped, desc.values.data(), desc.values.size() * sizeof(int32_t));
}

std::vector<int32_t> PassExecutor::readBuffer(const std::string& name) const {
  const auto it = impl_->buffers.find(name);
  if (it == impl_->buffers.end()) throw ExecutorError(fmt::format("read back: the manifest has no buffer '{}'", name));
  std::vector<int32_t> values(it->second.size / sizeof(int32_t));
  std::memcpy(values.data(), it->second.mapped, values.size() * sizeof(int32_t));
  return values;
}

void PassExecutor::setHostClock(HostClock clock) { impl_->hostClock = std::move(clock); }

HostImage PassExecutor::download(const std::string& name, uint32_t level, uint32_t layer) {
  auto& im = impl_->image(name, "download");
  if (level >= im.image.levels || layer >= im.image.layers)
    throw ExecutorError(fmt::format("download '{}': level {} layer {} outside {} levels x {} layers", name, level,
                                    layer, im.image.levels, im.image.layers));
  const uint32_t w = std::max(1u, im.image.width >> level), h = std::max(1u, im.image.height >> level);
  HostImage out = HostImage::zeros(w, h, im.desc.format);
  Buffer staging = createHostBuffer(impl_->ctx, out.bytes.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  impl_->ctx.submitAndWait([&](VkCommandBuffer c) {
    const VkImageSubresourceRange range{aspectOf(im.desc.format), level, 1, layer, 1};
    imageBarrier(c, im.image.image, range, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {aspectOf(im.desc.format), level, layer, 1};
    copy.imageExtent = {w, h, 1};
    vkCmdCopyImageToBuffer(c, im.image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &copy);
    imageBarrier(c, im.image.image, range, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0);
    VkBufferMemoryBarrier b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
    b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.buffer = staging.buffer;
    b.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(c, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &b, 0,
                         nullptr);
  });
  std::memcpy(out.bytes.data(), staging.mapped, out.bytes.size());
  return out;
}

}  // namespace shadowc::rt

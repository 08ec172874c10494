// samples/engine: a small headless Vulkan "engine" that uses a shadowc filter the way an engine
// would (docs/integration.md): the filter is compiled at build time into a C++ header
// (<filter>.h: SPIR-V arrays + the manifest as constexpr structs, no JSON parser) and an
// includable lookup; the engine creates the filter's images, runs its passes from the header
// every frame, then its own lighting shader (lighting.comp: Lambert N·L times the shadow term
// from the lookup). The scene side (built-in scene, light depth map and G-buffer rasterization,
// Vulkan device and object wrappers) is reused from runtime/ to keep the sample short: those
// parts are what any engine already has. The pass executor below is the part an engine writes.
//
//   shadowc_engine_sample OUT_DIR [SCENE] [SCREEN] [MAP]
// writes OUT_DIR/shaded.png and the raw shadow term OUT_DIR/shadow_term.f32 (SCREEN² float32,
// little-endian, row 0 = top). With SHADOWC_VALIDATION=1 any validation message fails the run.
#include <fmt/core.h>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "runtime/executor/spirv_reflect.h"
#include "runtime/images/atomic_file.h"
#include "runtime/images/png_image.h"
#include "runtime/raster/rasterizer.h"
#include "runtime/scene/frame_setup.h"
#include "runtime/scene/scene.h"
#include "runtime/vulkan/vulkan_context.h"
#include "runtime/vulkan/vulkan_error.h"
#include "runtime/vulkan/vulkan_resources.h"
#include SHADOWC_ENGINE_FILTER_HEADER

namespace sf = shadowc_filters;
namespace rt = shadowc::rt;
namespace filter = SHADOWC_ENGINE_FILTER_NAMESPACE;

// Inside shadowc::rt for the Vulkan entry points the runtime loads at run time (vulkan_api.h).
namespace shadowc::rt::engine_sample {
namespace {

VkFormat vkFormat(sf::Format f) {
  switch (f) {
    case sf::Format::R32F:
      return VK_FORMAT_R32_SFLOAT;
    case sf::Format::RG32F:
      return VK_FORMAT_R32G32_SFLOAT;
    case sf::Format::RGBA32F:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
    case sf::Format::R16F:
      return VK_FORMAT_R16_SFLOAT;
    case sf::Format::RG16F:
      return VK_FORMAT_R16G16_SFLOAT;
    case sf::Format::RGBA16F:
      return VK_FORMAT_R16G16B16A16_SFLOAT;
    case sf::Format::R16Unorm:
      return VK_FORMAT_R16_UNORM;
    case sf::Format::RG16Unorm:
      return VK_FORMAT_R16G16_UNORM;
    case sf::Format::D32F:  // a depth_input filter's attachment (this sample's filter reads linear depth)
      return VK_FORMAT_D32_SFLOAT;
    case sf::Format::D24:
      return VK_FORMAT_X8_D24_UNORM_PACK32;
    case sf::Format::RGBA16Unorm:
      return VK_FORMAT_R16G16B16A16_UNORM;
    case sf::Format::R32UI:
      return VK_FORMAT_R32_UINT;
    case sf::Format::RG32UI:
      return VK_FORMAT_R32G32_UINT;
    case sf::Format::RGBA32UI:
      return VK_FORMAT_R32G32B32A32_UINT;
  }
  return VK_FORMAT_UNDEFINED;
}

VkDescriptorType descriptorType(sf::Access a) {
  switch (a) {
    case sf::Access::Sampled:
      return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case sf::Access::Uniform:
      return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case sf::Access::StorageBufferRead:
      return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    default:
      return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  }
}

struct Extent {
  uint32_t w, h;
};
Extent extentOf(sf::SizeRule r, uint32_t map, uint32_t screen) {
  const uint32_t side = r.domain == sf::Domain::Map ? map : screen;
  return {std::max(1u, side >> r.shift), std::max(1u, side >> r.shift)};
}

// A GPU image with one sampler (the filter says nearest or linear) and its views.
struct GpuImage {
  rt::Image image;
  rt::UniqueSampler sampler;
  std::vector<rt::UniqueImageView> views;
};

GpuImage makeImage(const rt::VulkanContext& ctx, VkFormat format, Extent e, uint32_t levels, uint32_t layers,
                   bool linear) {
  GpuImage g;
  g.image = rt::createImage(ctx, format, e.w, e.h, levels, layers,
                            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  s.magFilter = s.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  s.mipmapMode = linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  s.maxLod = float(levels);
  VkSampler sampler = VK_NULL_HANDLE;
  rt::checkVk(vkCreateSampler(ctx.device(), &s, nullptr, &sampler), "vkCreateSampler");
  g.sampler = rt::UniqueSampler(ctx.device(), sampler);
  return g;
}

VkImageSubresourceRange wholeImage(const rt::Image& im) {
  return {VK_IMAGE_ASPECT_COLOR_BIT, 0, im.levels, 0, im.layers};
}

void upload(const rt::VulkanContext& ctx, const rt::Image& im, const std::vector<uint8_t>& bytes) {
  rt::Buffer staging = rt::createHostBuffer(ctx, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::memcpy(staging.mapped, bytes.data(), bytes.size());
  ctx.submitAndWait([&](VkCommandBuffer c) {
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, im.layers};
    rt::imageBarrier(c, im.image, range, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT | VK_ACCESS_MEMORY_READ_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, im.layers};
    copy.imageExtent = {im.width, im.height, 1};
    vkCmdCopyBufferToImage(c, staging.buffer, im.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    rt::imageBarrier(c, im.image, range, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                     VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
  });
}

std::vector<float> download(const rt::VulkanContext& ctx, const rt::Image& im, uint32_t channels) {
  const size_t bytes = size_t(im.width) * im.height * channels * sizeof(float);
  rt::Buffer staging = rt::createHostBuffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  ctx.submitAndWait([&](VkCommandBuffer c) {
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    rt::imageBarrier(c, im.image, range, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {im.width, im.height, 1};
    vkCmdCopyImageToBuffer(c, im.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &copy);
    rt::imageBarrier(c, im.image, range, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                     VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                     VK_ACCESS_HOST_READ_BIT);
  });
  std::vector<float> out(bytes / sizeof(float));
  std::memcpy(out.data(), staging.mapped, bytes);
  return out;
}

// One compute pipeline with its descriptor sets (one per set layout).
struct Pipeline {
  std::vector<rt::UniqueDescriptorSetLayout> setLayouts;
  rt::UniquePipelineLayout layout;
  rt::UniquePipeline pipeline;
  std::vector<VkDescriptorSet> sets;
  std::vector<uint8_t> push;
};

// What a binding points at: an image (with the view the shader declares) or a buffer.
struct Resource {
  uint32_t binding = 0;
  VkDescriptorType type{};
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize range = 0;
};

Pipeline makePipeline(const rt::VulkanContext& ctx, VkDescriptorPool pool, const std::vector<uint32_t>& spirv,
                      const std::vector<std::vector<Resource>>& sets, uint32_t pushBytes) {
  Pipeline p;
  std::vector<VkDescriptorSetLayout> raw;
  for (const auto& set : sets) {
    std::vector<VkDescriptorSetLayoutBinding> bs;
    for (const Resource& r : set) bs.push_back({r.binding, r.type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = uint32_t(bs.size());
    li.pBindings = bs.data();
    VkDescriptorSetLayout l = VK_NULL_HANDLE;
    rt::checkVk(vkCreateDescriptorSetLayout(ctx.device(), &li, nullptr, &l), "vkCreateDescriptorSetLayout");
    p.setLayouts.emplace_back(ctx.device(), l);
    raw.push_back(l);
  }
  const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes};
  VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pl.setLayoutCount = uint32_t(raw.size());
  pl.pSetLayouts = raw.data();
  pl.pushConstantRangeCount = pushBytes ? 1 : 0;
  pl.pPushConstantRanges = &range;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  rt::checkVk(vkCreatePipelineLayout(ctx.device(), &pl, nullptr, &layout), "vkCreatePipelineLayout");
  p.layout = rt::UniquePipelineLayout(ctx.device(), layout);
  rt::UniqueShaderModule module = rt::createShaderModule(ctx, spirv.data(), spirv.size());
  VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  ci.stage.module = module;
  ci.stage.pName = "main";
  ci.layout = layout;
  VkPipeline pipe = VK_NULL_HANDLE;
  rt::checkVk(vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &ci, nullptr, &pipe),
              "vkCreateComputePipelines");
  p.pipeline = rt::UniquePipeline(ctx.device(), pipe);

  p.sets.resize(raw.size());
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = pool;
  ai.descriptorSetCount = uint32_t(raw.size());
  ai.pSetLayouts = raw.data();
  rt::checkVk(vkAllocateDescriptorSets(ctx.device(), &ai, p.sets.data()), "vkAllocateDescriptorSets");
  for (size_t s = 0; s < sets.size(); ++s)
    for (const Resource& r : sets[s]) {
      VkDescriptorImageInfo ii{r.sampler, r.view, VK_IMAGE_LAYOUT_GENERAL};
      VkDescriptorBufferInfo bi{r.buffer, 0, r.range};
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = p.sets[s];
      w.dstBinding = r.binding;
      w.descriptorCount = 1;
      w.descriptorType = r.type;
      if (r.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || r.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER)
        w.pBufferInfo = &bi;
      else
        w.pImageInfo = &ii;
      vkUpdateDescriptorSets(ctx.device(), 1, &w, 0, nullptr);
    }
  return p;
}

std::vector<uint32_t> readSpirv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && bytes.empty()) throw std::runtime_error(path.string() + ": cannot read");
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

// The engine's own frame block (lighting.comp, std140).
struct EngineFrame {
  float lightView[16];
  float lightParams[4];
  float lightCentre[4];
  float albedo[4];
};
static_assert(sizeof(EngineFrame) == 112);

constexpr const char* kUsage =
    "usage: shadowc_engine_sample OUT_DIR [SCENE] [SCREEN] [MAP]\n"
    "Runs the build-time compiled filter and the engine's lighting shader on a built-in scene\n"
    "(docs/integration.md).\n"
    "  OUT_DIR  folder for shaded.png and shadow_term.f32 (SCREEN^2 float32, row 0 = top)\n"
    "  SCENE    built-in scene name or scene .json file (default two_planes)\n"
    "  SCREEN   screen width and height in pixels (default 256)\n"
    "  MAP      shadow-map side in texels (default 1024)\n"
    "With SHADOWC_VALIDATION=1 any Vulkan validation message fails the run.\n";

// A positive whole number, or a message naming the argument (std::stoul would say "stoul").
uint32_t positiveArgument(const char* text, const char* name) {
  char* end = nullptr;
  const unsigned long v = std::strtoul(text, &end, 10);
  if (*text < '0' || *text > '9' || *end != '\0' || v == 0 || v > (1u << 16))
    throw std::invalid_argument(fmt::format("{} must be a whole number in [1, 65536], got '{}'", name, text));
  return uint32_t(v);
}

}  // namespace

int run(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      fmt::print("{}", kUsage);
      return 0;
    }
    // No option names a folder: `--help`-like input must not become ./--help/shaded.png.
    if (arg.size() > 1 && arg[0] == '-') {
      fmt::print(stderr, "shadowc_engine_sample: error: unknown option '{}'\n{}", arg, kUsage);
      return 2;
    }
  }
  if (argc < 2 || argc > 5) {
    fmt::print(stderr, "{}", kUsage);
    return 2;
  }
  const std::filesystem::path out = argv[1];
  const std::string sceneName = argc > 2 ? argv[2] : "two_planes";
  const uint32_t screen = argc > 3 ? positiveArgument(argv[3], "SCREEN") : 256;
  const uint32_t map = argc > 4 ? positiveArgument(argv[4], "MAP") : 1024;
  std::filesystem::create_directories(out);

  rt::VulkanContext ctx;  // lavapipe; SHADOWC_VALIDATION=1 turns the Khronos layer on
  const rt::Scene scene = rt::loadScene(sceneName);
  const rt::FrameSetup setup = rt::setupFrame(scene, map, screen, screen);
  const rt::RasterOutputs raster = rt::rasterize(ctx, scene, setup);

  // The filter's images, as its header lists them; all kept in GENERAL layout, zero-filled.
  std::vector<GpuImage> images;
  for (const sf::Image& desc : filter::images) {
    const Extent e = extentOf(desc.size, map, screen);
    const uint32_t full = std::bit_width(std::max(e.w, e.h));
    const uint32_t levels = desc.mipLevels <= 0 ? full : std::min<uint32_t>(uint32_t(desc.mipLevels), full);
    images.push_back(makeImage(ctx, vkFormat(desc.format), e, levels, uint32_t(desc.layers), desc.linearFilter));
  }
  // The engine's own images: G-buffer in, shaded colour and raw shadow term out.
  GpuImage gPosition = makeImage(ctx, VK_FORMAT_R32G32B32A32_SFLOAT, {screen, screen}, 1, 1, false);
  GpuImage gNormal = makeImage(ctx, VK_FORMAT_R32G32B32A32_SFLOAT, {screen, screen}, 1, 1, false);
  GpuImage shaded = makeImage(ctx, VK_FORMAT_R32G32B32A32_SFLOAT, {screen, screen}, 1, 1, false);
  GpuImage shadowTerm = makeImage(ctx, VK_FORMAT_R32_SFLOAT, {screen, screen}, 1, 1, false);
  std::vector<rt::Image*> all{&gPosition.image, &gNormal.image, &shaded.image, &shadowTerm.image};
  for (GpuImage& g : images) all.push_back(&g.image);
  ctx.submitAndWait([&](VkCommandBuffer c) {
    const VkClearColorValue zero{};
    for (rt::Image* im : all) {
      rt::imageBarrier(c, im->image, wholeImage(*im), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                       VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_TRANSFER_WRITE_BIT);
      const VkImageSubresourceRange range = wholeImage(*im);
      vkCmdClearColorImage(c, im->image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    }
    rt::fullBarrier(c);
  });
  for (size_t i = 0; i < std::size(filter::images); ++i)
    if (filter::images[i].role == sf::Role::InputDepth) upload(ctx, images[i].image, raster.lightDepth.bytes);
  upload(ctx, gPosition.image, raster.gbufferPosition.bytes);
  upload(ctx, gNormal.image, raster.gbufferNormal.bytes);

  rt::Buffer shadowcFrame = rt::createHostBuffer(ctx, sizeof setup.frame, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::memcpy(shadowcFrame.mapped, &setup.frame, sizeof setup.frame);
  EngineFrame ef{};
  std::memcpy(ef.lightView, setup.frame.lightView, sizeof ef.lightView);
  std::memcpy(ef.lightParams, setup.frame.lightParams, sizeof ef.lightParams);
  ef.lightCentre[0] = scene.light.position.x;
  ef.lightCentre[1] = scene.light.position.y;
  ef.lightCentre[2] = scene.light.position.z;
  ef.albedo[0] = 0.9f, ef.albedo[1] = 0.85f, ef.albedo[2] = 0.8f;
  rt::Buffer engineFrame = rt::createHostBuffer(ctx, sizeof ef, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::memcpy(engineFrame.mapped, &ef, sizeof ef);

  // The filter's read-only buffers (the quadtree's Next/Child tables), written once from the header.
  std::vector<rt::Buffer> buffers;
  for (size_t i = 0; i < filter::filter.bufferCount; ++i) {
    const sf::Buffer& b = filter::filter.buffers[i];
    buffers.push_back(rt::createHostBuffer(ctx, b.valueCount * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
    std::memcpy(buffers.back().mapped, b.values, b.valueCount * 4);
  }

  VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 256},
                                  {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 256},
                                  {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 64},
                                  {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 64}};
  VkDescriptorPoolCreateInfo dp{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dp.maxSets = 64;
  dp.poolSizeCount = 4;
  dp.pPoolSizes = sizes;
  VkDescriptorPool rawPool = VK_NULL_HANDLE;
  rt::checkVk(vkCreateDescriptorPool(ctx.device(), &dp, nullptr, &rawPool), "vkCreateDescriptorPool");
  rt::UniqueDescriptorPool pool(ctx.device(), rawPool);

  // A binding of the header -> a resource; the view type (2D or 2D array) is what the shader
  // declares, read from its SPIR-V (engines reflect their modules anyway).
  auto resourceFor = [&](const sf::Binding& b, const rt::ReflectedModule& module, uint32_t set) {
    Resource r;
    r.binding = b.binding;
    r.type = descriptorType(b.access);
    if (b.imageIndex < 0) {
      r.buffer = shadowcFrame.buffer;
      r.range = sizeof setup.frame;
      return r;
    }
    if (b.access == sf::Access::StorageBufferRead) {
      r.buffer = buffers.at(size_t(b.imageIndex)).buffer;
      r.range = VK_WHOLE_SIZE;
      return r;
    }
    bool arrayed = false;
    for (const auto& rb : module.bindings)
      if (rb.set == set && rb.binding == b.binding) arrayed = rb.arrayed;
    GpuImage& g = images[size_t(b.imageIndex)];
    const bool storage = r.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    const uint32_t base = storage && b.level > 0 ? uint32_t(b.level) : 0;
    g.views.push_back(rt::createView(ctx, g.image, arrayed ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D,
                                     VK_IMAGE_ASPECT_COLOR_BIT, base, storage ? 1 : g.image.levels));
    r.view = g.views.back();
    r.sampler = g.sampler;
    return r;
  };

  // The filter's passes, in the header's order. The "shade" pass is the harness's way to get a
  // visibility image; an engine skips it and calls the lookup in its own shader instead.
  struct Step {
    Pipeline pipeline;
    uint32_t groups[3];
  };
  std::vector<Step> steps;
  for (const sf::Pass& pass : filter::passes) {
    if (std::string(pass.kind) == "shade") continue;
    const std::vector<uint32_t> spirv(pass.spirv, pass.spirv + pass.spirvWords);
    const rt::ReflectedModule module = rt::reflectSpirv(spirv);
    std::vector<Resource> set;
    for (size_t i = 0; i < pass.bindingCount; ++i) set.push_back(resourceFor(pass.bindings[i], module, 0));
    uint32_t pushBytes = 0;
    for (size_t i = 0; i < pass.pushConstantCount; ++i)
      pushBytes = std::max(pushBytes, pass.pushConstants[i].offset + 4);
    Step step{makePipeline(ctx, pool, spirv, {set}, pushBytes), {1, 1, 1}};
    step.pipeline.push.resize(pushBytes);
    for (size_t i = 0; i < pass.pushConstantCount; ++i) {
      const sf::PushConstant& c = pass.pushConstants[i];
      uint32_t word = 0;
      if (c.type == sf::Scalar::F32) {
        const float f = float(c.value);
        std::memcpy(&word, &f, 4);
      } else {
        word = c.type == sf::Scalar::I32 ? uint32_t(int32_t(c.value)) : uint32_t(c.value);
      }
      std::memcpy(step.pipeline.push.data() + c.offset, &word, 4);
    }
    const Extent e = extentOf(pass.dispatchSize, map, screen);
    const uint32_t lx = std::max(1u, pass.localSize[0]), ly = std::max(1u, pass.localSize[1]);
    if (pass.dispatchMode == sf::DispatchMode::Texels) {
      step.groups[0] = (e.w + lx - 1) / lx;
      step.groups[1] = (e.h + ly - 1) / ly;
    } else {
      step.groups[0] = ((pass.dispatchMode == sf::DispatchMode::Rows ? e.h : e.w) + lx - 1) / lx;
    }
    steps.push_back(std::move(step));
  }

  // The engine's lighting pass: its own set 0, the lookup's set (filter.lookup) for the rest.
  const std::vector<uint32_t> lightingSpirv = readSpirv(SHADOWC_ENGINE_LIGHTING_SPV);
  const rt::ReflectedModule lightingModule = rt::reflectSpirv(lightingSpirv);
  gPosition.views.push_back(
      rt::createView(ctx, gPosition.image, VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1));
  gNormal.views.push_back(rt::createView(ctx, gNormal.image, VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1));
  shaded.views.push_back(rt::createView(ctx, shaded.image, VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1));
  shadowTerm.views.push_back(
      rt::createView(ctx, shadowTerm.image, VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1));
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  std::vector<Resource> engineSet{
      {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_NULL_HANDLE, VK_NULL_HANDLE, engineFrame.buffer, sizeof ef},
      {1, storage, gPosition.views[0], VK_NULL_HANDLE, VK_NULL_HANDLE, 0},
      {2, storage, gNormal.views[0], VK_NULL_HANDLE, VK_NULL_HANDLE, 0},
      {3, storage, shaded.views[0], VK_NULL_HANDLE, VK_NULL_HANDLE, 0},
      {4, storage, shadowTerm.views[0], VK_NULL_HANDLE, VK_NULL_HANDLE, 0}};
  std::vector<std::vector<Resource>> lightingSets(filter::filter.lookup.set + 1);
  lightingSets[0] = engineSet;
  for (size_t i = 0; i < filter::filter.lookup.bindingCount; ++i) {
    const sf::Binding& b = filter::filter.lookup.bindings[i];
    if (b.imageIndex < 0) continue;  // the frame comes from the engine's block (SHADOWC_FRAME_EXTERNAL)
    lightingSets[filter::filter.lookup.set].push_back(resourceFor(b, lightingModule, filter::filter.lookup.set));
  }
  Pipeline lighting = makePipeline(ctx, pool, lightingSpirv, lightingSets, 0);

  // One frame: the filter's passes, a barrier after each, then lighting.
  ctx.submitAndWait([&](VkCommandBuffer c) {
    for (const Step& s : steps) {
      vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_COMPUTE, s.pipeline.pipeline);
      vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_COMPUTE, s.pipeline.layout, 0, uint32_t(s.pipeline.sets.size()),
                              s.pipeline.sets.data(), 0, nullptr);
      if (!s.pipeline.push.empty())
        vkCmdPushConstants(c, s.pipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, uint32_t(s.pipeline.push.size()),
                           s.pipeline.push.data());
      vkCmdDispatch(c, s.groups[0], s.groups[1], s.groups[2]);
      rt::fullBarrier(c);
    }
    vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_COMPUTE, lighting.pipeline);
    vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_COMPUTE, lighting.layout, 0, uint32_t(lighting.sets.size()),
                            lighting.sets.data(), 0, nullptr);
    vkCmdDispatch(c, (screen + 7) / 8, (screen + 7) / 8, 1);
    rt::fullBarrier(c);
  });

  const std::vector<float> colour = download(ctx, shaded.image, 4);
  const std::vector<float> term = download(ctx, shadowTerm.image, 1);
  rt::Rgb8Image png{screen, screen, 3, {}};
  for (size_t i = 0; i < size_t(screen) * screen; ++i)
    for (int ch = 0; ch < 3; ++ch)
      png.pixels.push_back(uint8_t(std::lround(std::clamp(colour[4 * i + ch], 0.0f, 1.0f) * 255.0f)));
  rt::writePng(out / "shaded.png", png);
  rt::writeFileAtomically(out / "shadow_term.f32",
                          std::string(reinterpret_cast<const char*>(term.data()), term.size() * sizeof(float)));
  if (ctx.validationEnabled() && ctx.validationMessageCount() > 0) {
    for (const std::string& m : ctx.validationMessages()) fmt::print(stderr, "validation: {}\n", m);
    fmt::print(stderr, "shadowc_engine_sample: error: {} validation messages\n", ctx.validationMessageCount());
    return 1;
  }
  fmt::print("{}: {} passes + lighting on {} ({}x{}, map {}) -> {}\n", filter::filter.name, steps.size(), sceneName,
             screen, screen, map, (out / "shaded.png").string());
  return 0;
}

}  // namespace shadowc::rt::engine_sample

int main(int argc, char** argv) {
  try {
    return shadowc::rt::engine_sample::run(argc, argv);
  } catch (const std::exception& e) {
    fmt::print(stderr, "shadowc_engine_sample: error: {}\n", e.what());
    return 1;
  }
}

// samples/engine: a small headless Vulkan "engine" that uses a shadowc filter the way an engine
// would (docs/integration.md), built from the installed package alone (find_package(shadowc)):
// the filter (-DSHADOWC_FILTER) is compiled at build time into a C++ header (<filter>.h: SPIR-V
// arrays and the manifest as constexpr structs) and an includable lookup; the engine renders its
// own light-depth map and G-buffer (raster.cpp) from a scene written by `shadowc export-scene`,
// fills the ShadowcFrame block with <shadowc/frame.h>, creates the filter's images, runs its
// passes from the header with a barrier after each, then its own lighting shader (Lambert N·L
// times the shadow term from the lookup).
//
//   shadowc_engine_sample SCENE_DIR OUT_DIR
// writes OUT_DIR/shaded.png and the raw shadow term OUT_DIR/shadow_term.f32 (screen² float32,
// little-endian, row 0 = top). With SHADOWC_VALIDATION=1 any validation message fails the run.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include "raster.h"
#include "scene_file.h"
#include "spirv_arrayed.h"
#include "vulkan_device.h"
#include SHADOWC_ENGINE_FILTER_HEADER

namespace sf = shadowc_filters;
namespace filter = SHADOWC_ENGINE_FILTER_NAMESPACE;

namespace engine {
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
    case sf::Format::RGBA16Unorm:
      return VK_FORMAT_R16G16B16A16_UNORM;
    case sf::Format::R32UI:
      return VK_FORMAT_R32_UINT;
    case sf::Format::RG32UI:
      return VK_FORMAT_R32G32_UINT;
    case sf::Format::RGBA32UI:
      return VK_FORMAT_R32G32B32A32_UINT;
    case sf::Format::D32F:  // a depth_input filter reads the light pass's depth attachment
      return VK_FORMAT_D32_SFLOAT;
    case sf::Format::D24:
      return VK_FORMAT_X8_D24_UNORM_PACK32;
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

uint32_t side(sf::SizeRule r, uint32_t map, uint32_t screen) {
  return std::max(1u, (r.domain == sf::Domain::Map ? map : screen) >> r.shift);
}

// What a binding points at: an image view with its sampler, or a buffer.
struct Resource {
  uint32_t binding = 0;
  VkDescriptorType type{};
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  VkBuffer buffer = VK_NULL_HANDLE;
};

// One compute pipeline with a descriptor set per set index (empty sets for gaps).
struct Pipeline {
  std::vector<VkDescriptorSetLayout> setLayouts;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets;
  std::vector<uint8_t> push;
  uint32_t groups[3] = {1, 1, 1};
};

Pipeline makePipeline(VkDevice d, VkDescriptorPool pool, const std::vector<uint32_t>& spirv,
                      const std::vector<std::vector<Resource>>& sets, uint32_t pushBytes) {
  Pipeline p;
  for (const auto& set : sets) {
    std::vector<VkDescriptorSetLayoutBinding> bs;
    for (const Resource& r : set) bs.push_back({r.binding, r.type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    li.bindingCount = uint32_t(bs.size());
    li.pBindings = bs.data();
    VkDescriptorSetLayout l = VK_NULL_HANDLE;
    check(vkCreateDescriptorSetLayout(d, &li, nullptr, &l), "vkCreateDescriptorSetLayout");
    p.setLayouts.push_back(l);
  }
  const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes};
  VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pl.setLayoutCount = uint32_t(p.setLayouts.size());
  pl.pSetLayouts = p.setLayouts.data();
  pl.pushConstantRangeCount = pushBytes ? 1 : 0;
  pl.pPushConstantRanges = &range;
  check(vkCreatePipelineLayout(d, &pl, nullptr, &p.layout), "vkCreatePipelineLayout");
  VkShaderModuleCreateInfo mi{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  mi.codeSize = spirv.size() * 4;
  mi.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  check(vkCreateShaderModule(d, &mi, nullptr, &module), "vkCreateShaderModule");
  VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  ci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  ci.stage.module = module;
  ci.stage.pName = "main";
  ci.layout = p.layout;
  check(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &ci, nullptr, &p.pipeline), "vkCreateComputePipelines");
  vkDestroyShaderModule(d, module, nullptr);

  p.sets.resize(p.setLayouts.size());
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = pool;
  ai.descriptorSetCount = uint32_t(p.setLayouts.size());
  ai.pSetLayouts = p.setLayouts.data();
  check(vkAllocateDescriptorSets(d, &ai, p.sets.data()), "vkAllocateDescriptorSets");
  for (size_t s = 0; s < sets.size(); ++s)
    for (const Resource& r : sets[s]) {
      const VkDescriptorImageInfo ii{r.sampler, r.view, VK_IMAGE_LAYOUT_GENERAL};
      const VkDescriptorBufferInfo bi{r.buffer, 0, VK_WHOLE_SIZE};
      VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      w.dstSet = p.sets[s];
      w.dstBinding = r.binding;
      w.descriptorCount = 1;
      w.descriptorType = r.type;
      const bool buffer = r.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || r.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      if (buffer)
        w.pBufferInfo = &bi;
      else
        w.pImageInfo = &ii;
      vkUpdateDescriptorSets(d, 1, &w, 0, nullptr);
    }
  return p;
}

// An image's texels read back (level 0, layer 0) as floats.
std::vector<float> download(Device& device, const Image& im, uint32_t channels) {
  const size_t bytes = size_t(im.width) * im.height * channels * sizeof(float);
  Buffer staging = device.createBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  device.submit([&](VkCommandBuffer c) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {im.width, im.height, 1};
    barrier(c, im, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    vkCmdCopyImageToBuffer(c, im.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &copy);
    barrier(c, im, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL);
  });
  std::vector<float> out(bytes / sizeof(float));
  std::memcpy(out.data(), staging.mapped, bytes);
  return out;
}

struct EngineLight {  // shaders/lighting.comp, std140
  float lightCentre[4];
  float albedo[4];
};

constexpr const char* kUsage =
    "usage: shadowc_engine_sample SCENE_DIR OUT_DIR\n"
    "Renders a scene written by `shadowc export-scene SCENE -o SCENE_DIR` with the filter this\n"
    "sample was built with (-DSHADOWC_FILTER), its passes from the generated header and its\n"
    "lookup in the engine's lighting shader (docs/integration.md).\n"
    "  SCENE_DIR  scene.json and mesh.f32 from shadowc export-scene (sizes and light views included)\n"
    "  OUT_DIR    folder for shaded.png and shadow_term.f32 (screen^2 float32, row 0 = top)\n"
    "With SHADOWC_VALIDATION=1 any Vulkan validation message fails the run;\n"
    "SHADOWC_ENGINE_DEVICE picks the device by name (default: llvmpipe, else the first).\n";

int run(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (arg.size() > 1 && arg[0] == '-') {  // no option names a folder: --help-like input is not an OUT_DIR
      std::fprintf(stderr, "shadowc_engine_sample: error: unknown option '%s'\n%s", arg.c_str(), kUsage);
      return 2;
    }
  }
  if (argc != 3) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  const SceneFile scene = readSceneFile(argv[1]);  // before the device: a bad scene is one message
  const std::filesystem::path out = argv[2];
  const char* validationEnv = std::getenv("SHADOWC_VALIDATION");
  Device device(validationEnv && std::string(validationEnv) == "1");
  VkDevice d = device.device();
  const uint32_t map = scene.map, screen = scene.screen;

  // The filter's images as its header lists them, the light pass's targets among them.
  const VkImageUsageFlags colourUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  std::vector<Image> images;
  std::vector<VkSampler> samplers;
  RasterTargets targets;
  targets.reversed = filter::depthInputReversed;
  bool haveLinear = false, haveDepth = false;
  for (const sf::Image& desc : filter::images) {
    const uint32_t s = side(desc.size, map, screen), full = std::bit_width(s);
    const uint32_t levels = desc.mipLevels <= 0 ? full : std::min<uint32_t>(uint32_t(desc.mipLevels), full);
    const VkFormat format = vkFormat(desc.format);
    Image im;
    if (desc.role == sf::Role::InputHardwareDepth) {
      im = device.createImage(format, s, s, 1, 1,
                              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
      targets.depth = im, haveDepth = true;
    } else if (desc.role == sf::Role::InputDepth) {
      im = device.createImage(format, s, s, levels, uint32_t(desc.layers),
                              colourUsage | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
      targets.linearDepth = im, haveLinear = true;
    } else {
      im = device.createImage(format, s, s, levels, uint32_t(desc.layers), colourUsage);
    }
    images.push_back(im);
    samplers.push_back(device.createSampler(desc.linearFilter, levels));
  }
  const VkImageUsageFlags target = colourUsage | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if (!haveLinear) targets.linearDepth = device.createImage(VK_FORMAT_R32_SFLOAT, map, map, 1, 1, target);
  if (!haveDepth)
    targets.depth =
        device.createImage(VK_FORMAT_D32_SFLOAT, map, map, 1, 1, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  targets.position = device.createImage(VK_FORMAT_R32G32B32A32_SFLOAT, screen, screen, 1, 1, target);
  targets.normal = device.createImage(VK_FORMAT_R32G32B32A32_SFLOAT, screen, screen, 1, 1, target);
  const Image shaded = device.createImage(VK_FORMAT_R32G32B32A32_SFLOAT, screen, screen, 1, 1, colourUsage);
  const Image shadowTerm = device.createImage(VK_FORMAT_R32_SFLOAT, screen, screen, 1, 1, colourUsage);

  // Every image the raster passes do not write starts zeroed in GENERAL.
  device.submit([&](VkCommandBuffer c) {
    std::vector<const Image*> cleared{&shaded, &shadowTerm};
    for (size_t i = 0; i < images.size(); ++i)
      if (filter::images[i].role != sf::Role::InputDepth && filter::images[i].role != sf::Role::InputHardwareDepth)
        cleared.push_back(&images[i]);
    const VkClearColorValue zero{};
    for (const Image* im : cleared) {
      barrier(c, *im, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
      const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, im->levels, 0, im->layers};
      vkCmdClearColorImage(c, im->image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
    }
    fullBarrier(c);
  });
  renderScene(device, scene, targets, SHADOWC_ENGINE_SHADER_DIR);

  // The frame block (filled from the light with <shadowc/frame.h>, scene_file.cpp): the bytes
  // the filter declares (filter::frameBytes), and the engine's own light block.
  Buffer frame = device.createBuffer(filter::frameBytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::memcpy(frame.mapped, &scene.frame, filter::frameBytes);
  EngineLight el{{scene.lightPosition[0], scene.lightPosition[1], scene.lightPosition[2], 0}, {0.9f, 0.85f, 0.8f, 0}};
  Buffer engineLight = device.createBuffer(sizeof el, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
  std::memcpy(engineLight.mapped, &el, sizeof el);
  std::vector<Buffer> buffers;  // the quadtree's Next/Child tables, written once from the header
  for (size_t i = 0; i < filter::filter.bufferCount; ++i) {
    const sf::Buffer& b = filter::filter.buffers[i];
    buffers.push_back(device.createBuffer(b.valueCount * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
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
  VkDescriptorPool pool = VK_NULL_HANDLE;
  check(vkCreateDescriptorPool(d, &dp, nullptr, &pool), "vkCreateDescriptorPool");

  // A binding of the header -> a resource; a 2D or 2D-array view as the shader declares it.
  auto resourceFor = [&](const sf::Binding& b, const std::set<std::pair<uint32_t, uint32_t>>& arrayed, uint32_t set) {
    Resource r;
    r.binding = b.binding;
    r.type = descriptorType(b.access);
    if (b.access == sf::Access::StorageBufferRead) {
      r.buffer = buffers.at(size_t(b.imageIndex)).buffer;
      return r;
    }
    if (b.imageIndex < 0) {  // the frame block ("parameters" is a generic build's, not this sample's)
      r.buffer = frame.buffer;
      return r;
    }
    const Image& im = images[size_t(b.imageIndex)];
    const bool storage = r.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    const uint32_t base = storage && b.level > 0 ? uint32_t(b.level) : 0;
    r.view =
        device.createView(im, arrayed.count({set, b.binding}) ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D,
                          base, storage ? 1 : im.levels);
    r.sampler = samplers[size_t(b.imageIndex)];
    return r;
  };

  // The filter's passes in the header's order, but "shade": the harness's way to get a
  // visibility image; an engine calls the lookup in its own shader instead.
  std::vector<Pipeline> steps;
  for (const sf::Pass& pass : filter::passes) {
    if (std::string(pass.kind) == "shade") continue;
    const std::vector<uint32_t> spirv(pass.spirv, pass.spirv + pass.spirvWords);
    const auto arrayed = arrayedBindings(spirv);
    std::vector<Resource> set;
    for (size_t i = 0; i < pass.bindingCount; ++i) set.push_back(resourceFor(pass.bindings[i], arrayed, 0));
    uint32_t pushBytes = 0;
    for (size_t i = 0; i < pass.pushConstantCount; ++i)
      pushBytes = std::max(pushBytes, pass.pushConstants[i].offset + 4);
    Pipeline step = makePipeline(d, pool, spirv, {set}, pushBytes);
    step.push.resize(pushBytes);
    for (size_t i = 0; i < pass.pushConstantCount; ++i) {
      const sf::PushConstant& c = pass.pushConstants[i];
      const float f = float(c.value);
      uint32_t word = c.type == sf::Scalar::I32 ? uint32_t(int32_t(c.value)) : uint32_t(c.value);
      if (c.type == sf::Scalar::F32) std::memcpy(&word, &f, 4);
      std::memcpy(step.push.data() + c.offset, &word, 4);
    }
    const uint32_t e = side(pass.dispatchSize, map, screen);
    const uint32_t lx = std::max(1u, pass.localSize[0]), ly = std::max(1u, pass.localSize[1]);
    if (pass.dispatchMode == sf::DispatchMode::Texels) {
      step.groups[0] = (e + lx - 1) / lx;
      step.groups[1] = (e + ly - 1) / ly;
    } else {
      step.groups[0] = (e + lx - 1) / lx;  // rows or columns of a square map: one invocation each
    }
    steps.push_back(std::move(step));
  }

  // The lighting pass: its own set 0, the lookup's set (filter.lookup.set) for the rest.
  const std::vector<uint32_t> lightingSpirv =
      readSpirv(std::filesystem::path(SHADOWC_ENGINE_SHADER_DIR) / "lighting.spv");
  const auto lightingArrayed = arrayedBindings(lightingSpirv);
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  std::vector<std::vector<Resource>> lightingSets(filter::filter.lookup.set + 1);
  lightingSets[0] = {
      {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_NULL_HANDLE, VK_NULL_HANDLE, engineLight.buffer},
      {1, storage, device.createView(targets.position, VK_IMAGE_VIEW_TYPE_2D, 0, 1), VK_NULL_HANDLE, VK_NULL_HANDLE},
      {2, storage, device.createView(targets.normal, VK_IMAGE_VIEW_TYPE_2D, 0, 1), VK_NULL_HANDLE, VK_NULL_HANDLE},
      {3, storage, device.createView(shaded, VK_IMAGE_VIEW_TYPE_2D, 0, 1), VK_NULL_HANDLE, VK_NULL_HANDLE},
      {4, storage, device.createView(shadowTerm, VK_IMAGE_VIEW_TYPE_2D, 0, 1), VK_NULL_HANDLE, VK_NULL_HANDLE}};
  for (size_t i = 0; i < filter::filter.lookup.bindingCount; ++i)
    lightingSets[filter::filter.lookup.set].push_back(
        resourceFor(filter::filter.lookup.bindings[i], lightingArrayed, filter::filter.lookup.set));
  Pipeline lighting = makePipeline(d, pool, lightingSpirv, lightingSets, 0);
  lighting.groups[0] = lighting.groups[1] = (screen + 7) / 8;
  steps.push_back(std::move(lighting));

  // One frame: the filter's passes and the lighting, a barrier after each.
  device.submit([&](VkCommandBuffer c) {
    for (const Pipeline& s : steps) {
      vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_COMPUTE, s.pipeline);
      vkCmdBindDescriptorSets(c, VK_PIPELINE_BIND_POINT_COMPUTE, s.layout, 0, uint32_t(s.sets.size()), s.sets.data(), 0,
                              nullptr);
      if (!s.push.empty())
        vkCmdPushConstants(c, s.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, uint32_t(s.push.size()), s.push.data());
      vkCmdDispatch(c, s.groups[0], s.groups[1], s.groups[2]);
      fullBarrier(c);
    }
  });

  const std::vector<float> colour = download(device, shaded, 4);
  const std::vector<float> term = download(device, shadowTerm, 1);
  for (const Pipeline& p : steps) {
    vkDestroyPipeline(d, p.pipeline, nullptr);
    vkDestroyPipelineLayout(d, p.layout, nullptr);
    for (VkDescriptorSetLayout l : p.setLayouts) vkDestroyDescriptorSetLayout(d, l, nullptr);
  }
  vkDestroyDescriptorPool(d, pool, nullptr);

  std::filesystem::create_directories(out);
  std::vector<uint8_t> rgb;
  for (size_t i = 0; i < size_t(screen) * screen; ++i)
    for (int ch = 0; ch < 3; ++ch)
      rgb.push_back(uint8_t(std::lround(std::clamp(colour[4 * i + ch], 0.0f, 1.0f) * 255.0f)));
  if (!stbi_write_png((out / "shaded.png").string().c_str(), int(screen), int(screen), 3, rgb.data(), int(screen) * 3))
    throw std::runtime_error((out / "shaded.png").string() + ": cannot write");
  std::ofstream(out / "shadow_term.f32", std::ios::binary)
      .write(reinterpret_cast<const char*>(term.data()), std::streamsize(term.size() * sizeof(float)));
  if (!device.messages().empty()) {
    for (const std::string& m : device.messages()) std::fprintf(stderr, "validation: %s\n", m.c_str());
    std::fprintf(stderr, "shadowc_engine_sample: error: %zu validation messages\n", device.messages().size());
    return 1;
  }
  std::printf("%s: %zu passes + lighting on %s (%ux%u, map %u, %zu light views, %s) -> %s\n", filter::filter.name,
              steps.size() - 1, scene.name.c_str(), screen, screen, map, scene.views.size(), device.name().c_str(),
              (out / "shaded.png").string().c_str());
  return 0;
}

}  // namespace
}  // namespace engine

int main(int argc, char** argv) {
  try {
    return engine::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowc_engine_sample: error: %s\n", e.what());
    return 1;
  }
}

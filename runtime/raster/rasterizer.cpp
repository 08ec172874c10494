#include "runtime/raster/rasterizer.h"

#include <fmt/core.h>

#include <cstring>
#include <glm/gtc/type_ptr.hpp>
#include <string>
#include <vector>

#include "backend/spirv_backend.h"
#include "runtime/raster/raster_shaders.h"
#include "runtime/scene/light_views.h"
#include "runtime/vulkan/vulkan_context.h"
#include "runtime/vulkan/vulkan_error.h"
#include "runtime/vulkan/vulkan_formats.h"
#include "runtime/vulkan/vulkan_resources.h"

namespace shadowc::rt {
namespace {

struct RasterPush {  // runtime/shaders/raster_push.glsl
  float viewProj[16];
  float lightZRow[4];
  float depthRange[4];
};
static_assert(sizeof(RasterPush) == 96);

struct Geometry {
  Buffer vertices;  // interleaved position (vec3), normal (vec3)
  Buffer indices;
  uint32_t indexCount = 0;
};

Geometry uploadGeometry(const VulkanContext& ctx, const Scene& scene) {
  std::vector<float> vertices;
  std::vector<uint32_t> indices;
  for (const Mesh& m : scene.meshes) {
    if (m.normals.size() != m.positions.size())
      throw VulkanError(fmt::format("rasterize: mesh '{}' has {} normals for {} positions", m.name, m.normals.size(),
                                    m.positions.size()));
    const uint32_t base = uint32_t(vertices.size() / 6);
    for (size_t i = 0; i < m.positions.size(); ++i) {
      vertices.insert(vertices.end(), {m.positions[i].x, m.positions[i].y, m.positions[i].z});
      vertices.insert(vertices.end(), {m.normals[i].x, m.normals[i].y, m.normals[i].z});
    }
    for (uint32_t idx : m.indices) {
      if (idx >= m.positions.size())
        throw VulkanError(fmt::format("rasterize: mesh '{}' index {} out of range", m.name, idx));
      indices.push_back(base + idx);
    }
  }
  Geometry g;
  g.indexCount = uint32_t(indices.size() / 3 * 3);
  g.vertices = createHostBuffer(ctx, std::max<size_t>(4, vertices.size() * 4), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  g.indices = createHostBuffer(ctx, std::max<size_t>(4, indices.size() * 4), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  if (!vertices.empty()) std::memcpy(g.vertices.mapped, vertices.data(), vertices.size() * 4);
  if (!indices.empty()) std::memcpy(g.indices.mapped, indices.data(), indices.size() * 4);
  return g;
}

const std::vector<uint32_t>& shader(VulkanContext& ctx, const std::string& name, ShaderStage stage) {
  return ctx.cachedSpirv("raster/" + name, [&] {
    const std::string_view text = runtime_shaders::find(name);
    if (text.empty()) throw VulkanError("runtime shader '" + name + "' is not embedded");
    const IncludeResolver includes = [](const std::string& file) -> std::optional<std::string> {
      const std::string_view t = runtime_shaders::find(file);
      if (t.empty()) return std::nullopt;
      return std::string(t);
    };
    const SpirvResult r = compileGlsl(text, stage, name, includes, BackendOptions{});
    if (!r.ok) throw VulkanError("compiling runtime shader '" + name + "' failed:\n" + r.log);
    return r.words;
  });
}

struct PassSpec {
  uint32_t width = 0, height = 0;
  std::vector<ImageFormat> colors;
  std::vector<VkClearColorValue> clears;
  std::string vert, frag;
  uint32_t attributes = 1;  // 1: position only, 2: position + normal
  RasterPush push{};
  HardwareDepth depth;  // the depth attachment's format and direction; kept as the last output if asked
};

// Reverse Z from a zero-to-one clip matrix: z_c' = w_c - z_c, so depth' = 1 - depth.
glm::mat4 reversedDepth(const glm::mat4& clip) {
  glm::mat4 r(1.0f);  // column-major: r[col][row]
  r[2][2] = -1.0f;
  r[3][2] = 1.0f;
  return r * clip;
}

// The word a cleared depth attachment holds: the far value (1, reversed 0) in its format.
uint32_t farDepthWord(const HardwareDepth& d) {
  if (d.format == ImageFormat::D24) return d.reversed ? 0u : 0x00FFFFFFu;
  const float v = d.reversed ? 0.0f : 1.0f;
  uint32_t w;
  std::memcpy(&w, &v, 4);
  return w;
}

// One offscreen render pass: color targets + a depth attachment (D32 LESS unless spec.depth asks
// for another format or reverse Z: GREATER, cleared to 0), the scene drawn once, every color
// target copied back to the host, then the depth attachment's words when spec.depth.kept().
std::vector<HostImage> renderOffscreen(VulkanContext& ctx, const Geometry& geometry, const PassSpec& spec) {
  const VkDevice dev = ctx.device();
  const bool keepDepth = spec.depth.kept();
  const ImageFormat attachment = keepDepth ? spec.depth.format : ImageFormat::D32F;
  const VkFormat depthFormat = vkFormatOf(attachment);
  if (!(ctx.formatFeatures(depthFormat) & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT))
    throw VulkanError(
        fmt::format("rasterize: {} is not a depth attachment format on {}", toString(attachment), ctx.deviceName()));
  std::vector<Image> targets;
  std::vector<UniqueImageView> views;
  for (ImageFormat f : spec.colors) {
    const VkFormat vf = vkFormatOf(f);
    if (!(ctx.formatFeatures(vf) & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT))
      throw VulkanError(
          fmt::format("rasterize: {} is not a color attachment format on {}", toString(f), ctx.deviceName()));
    targets.push_back(createImage(ctx, vf, spec.width, spec.height, 1, 1,
                                  VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT));
    views.push_back(createView(ctx, targets.back(), VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_COLOR_BIT, 0, 1));
  }
  Image depth =
      createImage(ctx, depthFormat, spec.width, spec.height, 1, 1,
                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                      (keepDepth ? VkImageUsageFlags(VK_IMAGE_USAGE_TRANSFER_SRC_BIT) : VkImageUsageFlags(0)));
  UniqueImageView depthView = createView(ctx, depth, VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1);

  const uint32_t n = uint32_t(spec.colors.size());
  std::vector<VkAttachmentDescription> attachments;
  std::vector<VkAttachmentReference> colorRefs;
  for (uint32_t i = 0; i < n; ++i) {
    VkAttachmentDescription a{};
    a.format = targets[i].format;
    a.samples = VK_SAMPLE_COUNT_1_BIT;
    a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    a.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    attachments.push_back(a);
    colorRefs.push_back({i, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
  }
  VkAttachmentDescription da{};
  da.format = depthFormat;
  da.samples = VK_SAMPLE_COUNT_1_BIT;
  da.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  da.storeOp = keepDepth ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  da.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  da.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  da.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  da.finalLayout = keepDepth ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  attachments.push_back(da);
  const VkAttachmentReference depthRef{n, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = n;
  subpass.pColorAttachments = colorRefs.data();
  subpass.pDepthStencilAttachment = &depthRef;
  const VkPipelineStageFlags attachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  const VkSubpassDependency deps[2] = {
      {VK_SUBPASS_EXTERNAL, 0, attachmentStages, attachmentStages, 0,
       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
           VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
       0},
      {0, VK_SUBPASS_EXTERNAL,
       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
       VK_PIPELINE_STAGE_TRANSFER_BIT,
       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
       0}};
  VkRenderPassCreateInfo rpInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  rpInfo.attachmentCount = uint32_t(attachments.size());
  rpInfo.pAttachments = attachments.data();
  rpInfo.subpassCount = 1;
  rpInfo.pSubpasses = &subpass;
  rpInfo.dependencyCount = 2;
  rpInfo.pDependencies = deps;
  VkRenderPass rp = VK_NULL_HANDLE;
  checkVk(vkCreateRenderPass(dev, &rpInfo, nullptr, &rp), "vkCreateRenderPass");
  UniqueRenderPass renderPass(dev, rp);

  std::vector<VkImageView> fbViews;
  for (const auto& v : views) fbViews.push_back(v);
  fbViews.push_back(depthView);
  VkFramebufferCreateInfo fbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fbInfo.renderPass = rp;
  fbInfo.attachmentCount = uint32_t(fbViews.size());
  fbInfo.pAttachments = fbViews.data();
  fbInfo.width = spec.width;
  fbInfo.height = spec.height;
  fbInfo.layers = 1;
  VkFramebuffer fb = VK_NULL_HANDLE;
  checkVk(vkCreateFramebuffer(dev, &fbInfo, nullptr, &fb), "vkCreateFramebuffer");
  UniqueFramebuffer framebuffer(dev, fb);

  const auto& vertWords = shader(ctx, spec.vert, ShaderStage::Vertex);
  const auto& fragWords = shader(ctx, spec.frag, ShaderStage::Fragment);
  UniqueShaderModule vert = createShaderModule(ctx, vertWords.data(), vertWords.size());
  UniqueShaderModule frag = createShaderModule(ctx, fragWords.data(), fragWords.size());

  const VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(RasterPush)};
  VkPipelineLayoutCreateInfo plInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plInfo.pushConstantRangeCount = 1;
  plInfo.pPushConstantRanges = &range;
  VkPipelineLayout pl = VK_NULL_HANDLE;
  checkVk(vkCreatePipelineLayout(dev, &plInfo, nullptr, &pl), "vkCreatePipelineLayout");
  UniquePipelineLayout layout(dev, pl);

  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert;
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag;
  stages[1].pName = "main";
  const VkVertexInputBindingDescription binding{0, 6 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attrs[2] = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 3 * sizeof(float)}};
  VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vi.vertexBindingDescriptionCount = 1;
  vi.pVertexBindingDescriptions = &binding;
  vi.vertexAttributeDescriptionCount = spec.attributes;  // only what the vertex shader consumes
  vi.pVertexAttributeDescriptions = attrs;
  VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  // Viewport without a y flip: framebuffer row = (ndc.y * 0.5 + 0.5) * height, so the light
  // map's row is uv.y * size as frame.glsl expects; the camera matrix flips y itself.
  const VkViewport viewport{0, 0, float(spec.width), float(spec.height), 0, 1};
  const VkRect2D scissor{{0, 0}, {spec.width, spec.height}};
  VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  vp.viewportCount = 1;
  vp.pViewports = &viewport;
  vp.scissorCount = 1;
  vp.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.cullMode = VK_CULL_MODE_NONE;  // both faces: closed meshes and one-sided planes alike
  rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  rs.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  ds.depthTestEnable = VK_TRUE;
  ds.depthWriteEnable = VK_TRUE;
  ds.depthCompareOp = spec.depth.reversed ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
  std::vector<VkPipelineColorBlendAttachmentState> blend(n);
  for (auto& b : blend)
    b.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  cb.attachmentCount = n;
  cb.pAttachments = blend.data();
  VkGraphicsPipelineCreateInfo gp{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  gp.stageCount = 2;
  gp.pStages = stages;
  gp.pVertexInputState = &vi;
  gp.pInputAssemblyState = &ia;
  gp.pViewportState = &vp;
  gp.pRasterizationState = &rs;
  gp.pMultisampleState = &ms;
  gp.pDepthStencilState = &ds;
  gp.pColorBlendState = &cb;
  gp.layout = pl;
  gp.renderPass = rp;
  VkPipeline p = VK_NULL_HANDLE;
  checkVk(vkCreateGraphicsPipelines(dev, VK_NULL_HANDLE, 1, &gp, nullptr, &p), "vkCreateGraphicsPipelines");
  UniquePipeline pipeline(dev, p);

  std::vector<Buffer> staging;
  std::vector<HostImage> out;
  std::vector<ImageFormat> outFormats = spec.colors;
  if (keepDepth) outFormats.push_back(spec.depth.format);
  for (ImageFormat f : outFormats) {
    out.push_back(HostImage::zeros(spec.width, spec.height, f));
    staging.push_back(createHostBuffer(ctx, out.back().bytes.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT));
  }
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    std::vector<VkClearValue> clears;
    for (const auto& c : spec.clears) clears.push_back(VkClearValue{.color = c});
    clears.push_back(VkClearValue{.depthStencil = {spec.depth.reversed ? 0.0f : 1.0f, 0}});
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = rp;
    begin.framebuffer = fb;
    begin.renderArea = scissor;
    begin.clearValueCount = uint32_t(clears.size());
    begin.pClearValues = clears.data();
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    if (geometry.indexCount > 0) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      RasterPush push = spec.push;
      if (spec.depth.reversed)
        std::memcpy(push.viewProj, glm::value_ptr(reversedDepth(glm::make_mat4(spec.push.viewProj))),
                    sizeof push.viewProj);
      vkCmdPushConstants(cmd, pl, range.stageFlags, 0, sizeof(RasterPush), &push);
      const VkDeviceSize offset = 0;
      const VkBuffer vb = geometry.vertices.buffer;
      vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
      vkCmdBindIndexBuffer(cmd, geometry.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
      vkCmdDrawIndexed(cmd, geometry.indexCount, 1, 0, 0, 0);
    }
    vkCmdEndRenderPass(cmd);
    for (uint32_t i = 0; i < n; ++i) {
      VkBufferImageCopy copy{};
      copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      copy.imageExtent = {spec.width, spec.height, 1};
      vkCmdCopyImageToBuffer(cmd, targets[i].image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging[i].buffer, 1, &copy);
    }
    if (keepDepth) {
      VkBufferImageCopy copy{};
      copy.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
      copy.imageExtent = {spec.width, spec.height, 1};
      vkCmdCopyImageToBuffer(cmd, depth.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging[n].buffer, 1, &copy);
    }
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0,
                         nullptr);
  });
  for (size_t i = 0; i < out.size(); ++i) std::memcpy(out[i].bytes.data(), staging[i].mapped, out[i].bytes.size());
  if (keepDepth && spec.depth.format == ImageFormat::D24)
    for (size_t t = 0; t < out.back().bytes.size(); t += 4) out.back().bytes[t + 3] = 0;  // X8: undefined high byte
  return out;
}

// The atlases a light pass fills: the linear depth, then the depth attachment's words if kept;
// every texel starts as "nothing hit" (1.0, or the attachment's far value).
std::vector<HostImage> emptyAtlases(uint32_t mapSize, const PassSpec& light) {
  std::vector<HostImage> atlases{
      HostImage::fromFloats(mapSize, mapSize, ImageFormat::R32F, std::vector<float>(size_t(mapSize) * mapSize, 1.0f))};
  if (light.depth.kept()) {
    HostImage words = HostImage::zeros(mapSize, mapSize, light.depth.format);
    const uint32_t far = farDepthWord(light.depth);
    for (size_t t = 0; t < words.bytes.size(); t += 4) std::memcpy(words.bytes.data() + t, &far, 4);
    atlases.push_back(std::move(words));
  }
  return atlases;
}

// Copies every output of one view into its tile at (x0, y0) of the matching atlas.
void placeTile(std::vector<HostImage>& atlases, const std::vector<HostImage>& view, uint32_t x0, uint32_t y0) {
  for (size_t k = 0; k < atlases.size(); ++k)
    for (uint32_t y = 0; y < view[k].height; ++y)
      std::memcpy(atlases[k].bytes.data() + atlases[k].texelOffset(x0, y0 + y),
                  view[k].bytes.data() + view[k].texelOffset(0, y),
                  size_t(view[k].width) * bytesPerTexel(view[k].format));
}

}  // namespace

HardwareDepth hardwareDepthFromSpec(const nlohmann::json& spec) {
  HardwareDepth d;
  if (!spec.is_object() || !spec.contains("depth_input")) return d;
  const nlohmann::json& j = spec["depth_input"];
  const std::string format = j.value("format", std::string("linear"));
  if (format == "d32")
    d.format = ImageFormat::D32F;
  else if (format == "d24")
    d.format = ImageFormat::D24;
  else if (format != "linear")
    throw VulkanError("manifest spec: unknown depth_input format '" + format + "'");
  d.reversed = j.value("z", std::string("standard")) == "reverse";
  return d;
}

RasterOutputs rasterize(VulkanContext& ctx, const Scene& scene, const FrameSetup& setup,
                        const HardwareDepth& hardwareDepth) {
  const Geometry geometry = uploadGeometry(ctx, scene);
  RasterOutputs out;

  PassSpec light;
  light.colors = {ImageFormat::R32F};
  VkClearColorValue far{};
  far.float32[0] = 1.0f;  // "nothing hit" (frame.glsl)
  light.clears = {far};
  light.vert = "light_depth.vert";
  light.frag = "light_depth.frag";
  light.attributes = 1;
  light.depth = hardwareDepth;
  light.push.depthRange[0] = setup.nearPlane;
  light.push.depthRange[1] = setup.farPlane;
  // Every view (light_views.h: the map, six cube faces, cascades or light samples) rendered on
  // its own at its tile's size and copied into its tile; the rest of the map stays "nothing hit".
  std::vector<HostImage> light0 = emptyAtlases(setup.mapSize, light);
  for (const LightView& v : lightViews(setup)) {
    std::memcpy(light.push.viewProj, glm::value_ptr(v.viewProj), sizeof light.push.viewProj);
    for (int c = 0; c < 4; ++c) light.push.lightZRow[c] = v.zRow[c];
    light.width = light.height = v.size;
    placeTile(light0, renderOffscreen(ctx, geometry, light), v.x0, v.y0);
  }
  out.lightDepth = std::move(light0.at(0));
  if (hardwareDepth.kept()) out.hardwareDepth = std::move(light0.at(1));

  PassSpec camera;
  camera.width = setup.width;
  camera.height = setup.height;
  camera.colors = {ImageFormat::RGBA32F, ImageFormat::RGBA32F};
  camera.clears = {VkClearColorValue{}, VkClearColorValue{}};
  camera.vert = "gbuffer.vert";
  camera.frag = "gbuffer.frag";
  camera.attributes = 2;
  std::memcpy(camera.push.viewProj, glm::value_ptr(setup.cameraViewProj), sizeof camera.push.viewProj);
  auto gbuffer = renderOffscreen(ctx, geometry, camera);
  out.gbufferPosition = std::move(gbuffer.at(0));
  out.gbufferNormal = std::move(gbuffer.at(1));
  return out;
}

}  // namespace shadowc::rt

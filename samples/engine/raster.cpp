#include "raster.h"

#include <cstring>
#include <fstream>

namespace engine {
namespace {

struct Push {  // shaders/raster_push.glsl
  float viewProj[16];
  float zRow[4];
  float depthRange[4];
};
static_assert(sizeof(Push) == 96);

struct Pass {
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  void destroy(VkDevice d) {
    vkDestroyPipeline(d, pipeline, nullptr);
    vkDestroyPipelineLayout(d, layout, nullptr);
    vkDestroyFramebuffer(d, framebuffer, nullptr);
    vkDestroyRenderPass(d, renderPass, nullptr);
    for (VkShaderModule m : modules) vkDestroyShaderModule(d, m, nullptr);
  }
};

VkShaderModule module(VkDevice d, const std::filesystem::path& file) {
  const std::vector<uint32_t> words = readSpirv(file);
  VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  ci.codeSize = words.size() * 4;
  ci.pCode = words.data();
  VkShaderModule m = VK_NULL_HANDLE;
  check(vkCreateShaderModule(d, &ci, nullptr, &m), "vkCreateShaderModule");
  return m;
}

// One render pass over `colors` + `depth` (cleared: colours to `clear`, depth to 1), ending in
// GENERAL, with a pipeline of the two shaders; `attributes` vec3s per vertex are read.
Pass makePass(Device& device, const std::vector<Image>& colors, const Image& depth, const std::filesystem::path& vert,
              const std::filesystem::path& frag, uint32_t attributes, uint32_t width, uint32_t height, bool reversed) {
  VkDevice d = device.device();
  Pass p;
  std::vector<VkAttachmentDescription> att;
  std::vector<VkAttachmentReference> refs;
  for (const Image& c : colors) {
    refs.push_back({uint32_t(att.size()), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    att.push_back({0, c.format, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE,
                   VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_GENERAL});
  }
  const VkAttachmentReference depthRef{uint32_t(att.size()), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  att.push_back({0, depth.format, VK_SAMPLE_COUNT_1_BIT, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE,
                 VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_DONT_CARE, VK_IMAGE_LAYOUT_UNDEFINED,
                 VK_IMAGE_LAYOUT_GENERAL});
  VkSubpassDescription sub{};
  sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  sub.colorAttachmentCount = uint32_t(refs.size());
  sub.pColorAttachments = refs.data();
  sub.pDepthStencilAttachment = &depthRef;
  // The filter's compute passes read the targets after the pass.
  const VkSubpassDependency after{
      0,
      VK_SUBPASS_EXTERNAL,
      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
      VK_ACCESS_SHADER_READ_BIT,
      0};
  VkRenderPassCreateInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  rp.attachmentCount = uint32_t(att.size());
  rp.pAttachments = att.data();
  rp.subpassCount = 1;
  rp.pSubpasses = &sub;
  rp.dependencyCount = 1;
  rp.pDependencies = &after;
  check(vkCreateRenderPass(d, &rp, nullptr, &p.renderPass), "vkCreateRenderPass");

  std::vector<VkImageView> views;
  for (const Image& c : colors) views.push_back(device.createView(c, VK_IMAGE_VIEW_TYPE_2D, 0, 1));
  views.push_back(device.createView(depth, VK_IMAGE_VIEW_TYPE_2D, 0, 1));
  VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb.renderPass = p.renderPass;
  fb.attachmentCount = uint32_t(views.size());
  fb.pAttachments = views.data();
  fb.width = width;
  fb.height = height;
  fb.layers = 1;
  check(vkCreateFramebuffer(d, &fb, nullptr, &p.framebuffer), "vkCreateFramebuffer");

  const VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(Push)};
  VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pl.pushConstantRangeCount = 1;
  pl.pPushConstantRanges = &range;
  check(vkCreatePipelineLayout(d, &pl, nullptr, &p.layout), "vkCreatePipelineLayout");

  p.modules[0] = module(d, vert);
  p.modules[1] = module(d, frag);
  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = p.modules[0];
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = p.modules[1];
  stages[1].pName = "main";
  const VkVertexInputBindingDescription binding{0, 6 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attrs[2] = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 3 * sizeof(float)}};
  VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vi.vertexBindingDescriptionCount = 1;
  vi.pVertexBindingDescriptions = &binding;
  vi.vertexAttributeDescriptionCount = attributes;
  vi.pVertexAttributeDescriptions = attrs;
  VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  vp.viewportCount = vp.scissorCount = 1;  // dynamic: one per light view
  VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.cullMode = VK_CULL_MODE_NONE;  // one-sided planes cast shadows from both sides
  rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  rs.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  ds.depthTestEnable = ds.depthWriteEnable = VK_TRUE;
  ds.depthCompareOp = reversed ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_LESS;
  std::vector<VkPipelineColorBlendAttachmentState> blend(colors.size());
  for (auto& b : blend) b.colorWriteMask = 0xf;
  VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  cb.attachmentCount = uint32_t(blend.size());
  cb.pAttachments = blend.data();
  const VkDynamicState dyn[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dy{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dy.dynamicStateCount = 2;
  dy.pDynamicStates = dyn;
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
  gp.pDynamicState = &dy;
  gp.layout = p.layout;
  gp.renderPass = p.renderPass;
  check(vkCreateGraphicsPipelines(d, VK_NULL_HANDLE, 1, &gp, nullptr, &p.pipeline), "vkCreateGraphicsPipelines");
  return p;
}

void begin(VkCommandBuffer c, const Pass& p, uint32_t w, uint32_t h, size_t colors, float colorClear,
           float depthClear) {
  std::vector<VkClearValue> clears(colors + 1);
  for (size_t i = 0; i < colors; ++i) clears[i].color = {{colorClear, colorClear, colorClear, colorClear}};
  clears[colors].depthStencil = {depthClear, 0};
  VkRenderPassBeginInfo bi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  bi.renderPass = p.renderPass;
  bi.framebuffer = p.framebuffer;
  bi.renderArea = {{0, 0}, {w, h}};
  bi.clearValueCount = uint32_t(clears.size());
  bi.pClearValues = clears.data();
  vkCmdBeginRenderPass(c, &bi, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(c, VK_PIPELINE_BIND_POINT_GRAPHICS, p.pipeline);
}

// A viewport without a y flip (row = (ndc.y * 0.5 + 0.5) * size): the light map's uv convention
// (templates/frame.glsl); the camera's clip matrix flips y itself.
void draw(VkCommandBuffer c, const Pass& p, const Push& push, uint32_t x0, uint32_t y0, uint32_t w, uint32_t h,
          VkBuffer vertices, uint32_t vertexCount) {
  const VkViewport viewport{float(x0), float(y0), float(w), float(h), 0.0f, 1.0f};
  const VkRect2D scissor{{int32_t(x0), int32_t(y0)}, {w, h}};
  vkCmdSetViewport(c, 0, 1, &viewport);
  vkCmdSetScissor(c, 0, 1, &scissor);
  vkCmdPushConstants(c, p.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(c, 0, 1, &vertices, &offset);
  vkCmdDraw(c, vertexCount, 1, 0, 0);
}

}  // namespace

std::vector<uint32_t> readSpirv(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty() || bytes.size() % 4) throw std::runtime_error(file.string() + ": not a SPIR-V file");
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  return words;
}

void renderScene(Device& device, const SceneFile& scene, const RasterTargets& t, const std::filesystem::path& dir) {
  const uint32_t vertexCount = uint32_t(scene.vertices.size() / 6);
  Buffer vertices =
      device.createBuffer(std::max<size_t>(4, scene.vertices.size() * 4), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  std::memcpy(vertices.mapped, scene.vertices.data(), scene.vertices.size() * 4);
  const Image cameraDepth = device.createImage(VK_FORMAT_D32_SFLOAT, scene.screen, scene.screen, 1, 1,
                                               VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
  Pass light = makePass(device, {t.linearDepth}, t.depth, dir / "light_depth.vert.spv", dir / "light_depth.frag.spv", 1,
                        scene.map, scene.map, t.reversed);
  Pass camera = makePass(device, {t.position, t.normal}, cameraDepth, dir / "gbuffer.vert.spv",
                         dir / "gbuffer.frag.spv", 2, scene.screen, scene.screen, false);
  device.submit([&](VkCommandBuffer c) {
    // Every view into its tile of one map; texels outside every tile keep the clear ("nothing hit").
    begin(c, light, scene.map, scene.map, 1, 1.0f, t.reversed ? 0.0f : 1.0f);
    for (const LightView& v : scene.views) {
      Push push{};
      std::memcpy(push.viewProj, v.viewProj.data(), sizeof push.viewProj);
      std::memcpy(push.zRow, v.zRow.data(), sizeof push.zRow);
      push.depthRange[0] = scene.nearPlane;
      push.depthRange[1] = scene.farPlane;
      // Reverse Z: clip z' = w - z (row 2 of the matrix replaced by row 3 minus row 2), so near
      // maps to 1 and far to 0.
      if (t.reversed)
        for (int col = 0; col < 4; ++col)
          push.viewProj[4 * col + 2] = push.viewProj[4 * col + 3] - push.viewProj[4 * col + 2];
      draw(c, light, push, v.x0, v.y0, v.size, v.size, vertices.buffer, vertexCount);
    }
    vkCmdEndRenderPass(c);
    begin(c, camera, scene.screen, scene.screen, 2, 0.0f, 1.0f);
    Push push{};
    std::memcpy(push.viewProj, scene.cameraViewProj.data(), sizeof push.viewProj);
    draw(c, camera, push, 0, 0, scene.screen, scene.screen, vertices.buffer, vertexCount);
    vkCmdEndRenderPass(c);
  });
  light.destroy(device.device());
  camera.destroy(device.device());
}

}  // namespace engine

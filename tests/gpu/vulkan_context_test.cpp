// VulkanContext on lavapipe with the Khronos validation layer.
#include <string>

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include "gpu/vulkan_fixture.h"
#include "runtime/vulkan/vulkan_error.h"

namespace shadowc::test {
namespace {

using ContextTest = VulkanTest;

TEST_F(ContextTest, PicksLavapipeWithValidation) {
  rt::VulkanContext& ctx = context();
  EXPECT_NE(ctx.deviceName().find("llvmpipe"), std::string::npos) << ctx.describe();
  EXPECT_TRUE(ctx.validationEnabled());
  EXPECT_GE(ctx.properties().apiVersion, VK_API_VERSION_1_2);
  EXPECT_GT(ctx.properties().limits.timestampPeriod, 0.0f);
}

TEST_F(ContextTest, ListsDevicesIncludingLlvmpipe) {
  const auto devices = rt::VulkanContext::listDevices();
  bool found = false;
  for (const auto& d : devices) found = found || d.name.find("llvmpipe") != std::string::npos;
  EXPECT_TRUE(found);
}

TEST_F(ContextTest, SelectsDeviceByNameAndIndex) {
  const auto devices = rt::VulkanContext::listDevices();
  ASSERT_FALSE(devices.empty());
  rt::VulkanContext byName(rt::VulkanOptions{"LLVMPIPE", false});
  EXPECT_NE(byName.deviceName().find("llvmpipe"), std::string::npos);
  uint32_t index = 0;
  for (const auto& d : devices)
    if (d.name.find("llvmpipe") != std::string::npos) index = d.index;
  rt::VulkanContext byIndex(rt::VulkanOptions{std::to_string(index), false});
  EXPECT_EQ(byIndex.deviceName(), byName.deviceName());
}

TEST_F(ContextTest, UnknownDeviceIsOneClearError) {
  try {
    rt::VulkanContext ctx(rt::VulkanOptions{"no-such-gpu", false});
    FAIL() << "expected VulkanError";
  } catch (const rt::VulkanError& e) {
    EXPECT_NE(std::string(e.what()).find("matches no device"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("llvmpipe"), std::string::npos) << "lists the available devices: " << e.what();
  }
  EXPECT_THROW(rt::VulkanContext(rt::VulkanOptions{"99", false}), rt::VulkanError);
}

// The fixture's check must be able to fail: a recorded message is reported as a failure.
TEST_F(ContextTest, RecordedValidationMessageFailsTheTest) {
  context().recordValidationMessage("[error] synthetic: injected by the test");
  EXPECT_NONFATAL_FAILURE(expectNoValidationMessages(), "synthetic");
}

// The layer is really live: a real misuse (anisotropic filtering without the feature enabled)
// is caught and counted by the messenger.
TEST_F(ContextTest, LayerReportsRealMisuse) {
  rt::VulkanContext& ctx = context();
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.anisotropyEnable = VK_TRUE;
  info.maxAnisotropy = 4.0f;
  info.maxLod = 1.0f;
  VkSampler sampler = VK_NULL_HANDLE;
  const size_t before = ctx.validationMessageCount();
  if (rt::vkCreateSampler(ctx.device(), &info, nullptr, &sampler) == VK_SUCCESS)
    rt::vkDestroySampler(ctx.device(), sampler, nullptr);
  EXPECT_GT(ctx.validationMessageCount(), before);
  ctx.clearValidationMessages();
}

}  // namespace
}  // namespace shadowc::test

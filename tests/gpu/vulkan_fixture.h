// GPU test fixture: one lavapipe VulkanContext per test program (instance creation with the
// validation layer costs ~0.1 s), validation on (the suite sets SHADOWC_VALIDATION=1; the
// fixture forces it anyway), and every test fails at TearDown if the layer reported any
// warning or error during it.
#pragma once

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "runtime/vulkan/vulkan_context.h"

namespace shadowc::test {

class VulkanTest : public ::testing::Test {
 public:
  static rt::VulkanContext& context() {
    static std::unique_ptr<rt::VulkanContext> ctx = [] {
      rt::VulkanOptions options;
      options.validation = true;
      return std::make_unique<rt::VulkanContext>(options);
    }();
    return *ctx;
  }

 protected:
  void SetUp() override { context().clearValidationMessages(); }
  void TearDown() override { expectNoValidationMessages(); }

  static void expectNoValidationMessages() {
    const auto messages = context().validationMessages();
    std::string all;
    for (const auto& m : messages) all += "\n  " + m;
    EXPECT_EQ(messages.size(), 0u) << "validation messages:" << all;
    context().clearValidationMessages();
  }
};

}  // namespace shadowc::test

// HostImage conversions, half floats, dispatch arithmetic and SPIR-V reflection: no device.
#include <cmath>

#include <gtest/gtest.h>

#include "backend/spirv_backend.h"
#include "runtime/executor/host_image.h"
#include "runtime/executor/pass_executor.h"
#include "runtime/executor/spirv_reflect.h"

namespace shadowc::test {
namespace {

TEST(HostImage, FloatRoundTripPerFormat) {
  const std::vector<float> v{0.0f, 0.25f, 1.0f, -2.5f, 0.1f, 65504.0f};
  const auto f32 = rt::HostImage::fromFloats(3, 2, ImageFormat::R32F, v);
  EXPECT_EQ(f32.texel(0, 1), -2.5f);
  EXPECT_EQ(f32.channel(), v);
  const auto f16 = rt::HostImage::fromFloats(3, 1, ImageFormat::RG16F, v);
  EXPECT_EQ(f16.texel(1, 0, 1), -2.5f);      // exact in half
  EXPECT_EQ(f16.texel(2, 0, 1), 65504.0f);   // the largest half
  EXPECT_NEAR(f16.texel(2, 0, 0), 0.1f, 0.1f * 1e-3f);  // 11-bit mantissa
  const auto u16 = rt::HostImage::fromFloats(6, 1, ImageFormat::R16Unorm, v);
  EXPECT_EQ(u16.texel(1, 0), float(std::lround(0.25 * 65535)) / 65535.0f);
  EXPECT_EQ(u16.texel(3, 0), 0.0f) << "unorm clamps";
  EXPECT_EQ(u16.texel(5, 0), 1.0f) << "unorm clamps";
  const auto ui = rt::HostImage::fromUints(1, 1, ImageFormat::RGBA32UI, {1, 2, 0xffffffffu, 4});
  EXPECT_EQ(ui.texelUint(0, 0, 2), 0xffffffffu);
  EXPECT_THROW(rt::HostImage::fromFloats(2, 2, ImageFormat::R32F, v), std::invalid_argument);
  EXPECT_THROW(f32.texel(3, 0), std::out_of_range);
  EXPECT_THROW(f32.texelUint(0, 0), std::invalid_argument);
}

TEST(HostImage, HalfConversionMatchesIeeeOnEveryHalf) {
  // Every finite half converts to float and back unchanged (round-trip exactness).
  uint32_t mismatches = 0;
  for (uint32_t h = 0; h < 0x10000; ++h) {
    if ((h & 0x7c00) == 0x7c00) continue;  // inf / NaN
    mismatches += rt::floatToHalf(rt::halfToFloat(uint16_t(h))) != h;
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(rt::halfToFloat(0x3c00), 1.0f);
  EXPECT_EQ(rt::halfToFloat(0x0001), std::ldexp(1.0f, -24));
  EXPECT_EQ(rt::floatToHalf(1.0f + std::ldexp(1.0f, -11)), 0x3c00) << "ties round to even";
  EXPECT_EQ(rt::floatToHalf(1e6f), 0x7c00) << "overflow gives infinity";
}

TEST(Dispatch, GroupCountsPerMode) {
  Pass p;
  p.localSize = {8, 8, 1};
  p.dispatch.size = {SizeDomain::Screen, 0};
  EXPECT_EQ(rt::dispatchGroups(p, 1024, 37, 23), (std::array<uint32_t, 3>{5, 3, 1}));
  p.dispatch.size = {SizeDomain::Map, 3};
  EXPECT_EQ(rt::dispatchGroups(p, 1024, 37, 23), (std::array<uint32_t, 3>{16, 16, 1}));
  p.localSize = {64, 1, 1};
  p.dispatch.mode = DispatchMode::Rows;
  p.dispatch.size = {SizeDomain::Screen, 0};
  EXPECT_EQ(rt::dispatchGroups(p, 1024, 300, 130), (std::array<uint32_t, 3>{3, 1, 1}));  // 130 rows
  p.dispatch.mode = DispatchMode::Columns;
  EXPECT_EQ(rt::dispatchGroups(p, 1024, 300, 130), (std::array<uint32_t, 3>{5, 1, 1}));  // 300 columns
  ImageDesc im;
  im.mipLevels = 0;
  EXPECT_EQ(rt::mipLevelCount(im, 1024, 1024), 11u);
  EXPECT_EQ(rt::mipLevelCount(im, 37, 23), 6u);
  im.mipLevels = 3;
  EXPECT_EQ(rt::mipLevelCount(im, 1024, 1024), 3u);
}

TEST(SpirvReflect, BindingsKindsFormatsAndLocalSize) {
  const char* glsl = R"(#version 460
layout(local_size_x = 16, local_size_y = 4) in;
layout(set = 0, binding = 0, std140) uniform F { vec4 a; } f;
layout(set = 0, binding = 3, rg32ui) uniform uimage2DArray sat;
layout(set = 0, binding = 5) uniform sampler2DArray moments;
layout(set = 0, binding = 6) uniform sampler2D depth;
void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  imageStore(sat, p, uvec4(texelFetch(moments, p, 0).x + texelFetch(depth, p.xy, 0).x + f.a.x));
}
)";
  const SpirvResult r = compileGlsl(glsl, ShaderStage::Compute, "reflect.comp", {}, BackendOptions{});
  ASSERT_TRUE(r.ok) << r.log;
  const rt::ReflectedModule m = rt::reflectSpirv(r.words);
  ASSERT_TRUE(m.localSize.has_value());
  EXPECT_EQ(*m.localSize, (std::array<uint32_t, 3>{16, 4, 1}));
  ASSERT_EQ(m.bindings.size(), 4u);
  std::map<uint32_t, rt::ReflectedBinding> by;
  for (const auto& b : m.bindings) by[b.binding] = b;
  EXPECT_EQ(by[0].kind, rt::DescriptorKind::UniformBuffer);
  EXPECT_EQ(by[3].kind, rt::DescriptorKind::StorageImage);
  EXPECT_TRUE(by[3].arrayed);
  EXPECT_EQ(by[3].format, ImageFormat::RG32UI);
  EXPECT_EQ(by[5].kind, rt::DescriptorKind::CombinedImageSampler);
  EXPECT_TRUE(by[5].arrayed);
  EXPECT_FALSE(by[6].arrayed);
  EXPECT_THROW(rt::reflectSpirv({1, 2, 3, 4, 5}), std::invalid_argument);
}

}  // namespace
}  // namespace shadowc::test

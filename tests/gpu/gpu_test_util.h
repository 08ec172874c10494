// Helpers for GPU tests: inline GLSL -> SPIR-V bytes for hand-written manifests, image comparison
// with a tolerance that reports the worst texel (and can be shown to fail).
#pragma once

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "backend/spirv_backend.h"
#include "runtime/executor/host_image.h"
#include "support/test_support.h"

namespace shadowc::test {

// Deterministic pseudo-random depths in [0, 1] (a 64-bit LCG from `seed`) with a band of cleared
// texels (1.0, rows 0-2) and a band of exact zeros (columns 0-1), so an encoder's clamp and
// rounding at both ends are exercised.
inline std::vector<float> craftedDepth(uint32_t n, uint64_t seed = 0x9E3779B97F4A7C15ull) {
  std::vector<float> d(size_t(n) * n);
  uint64_t s = seed;
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) {
      s = s * 6364136223846793005ull + 1442695040888963407ull;
      float v = float(double(s >> 11) / double(1ull << 53));
      if (y < 3) v = 1.0f;
      if (x < 2) v = 0.0f;
      d[size_t(y) * n + x] = v;
    }
  return d;
}

// Compiles compute GLSL (with templates/frame.glsl includable) to the bytes of a .spv file, for
// CompiledPasses::files. A compile error fails the test (the executor then sees no module).
inline std::string computeSpirv(const std::string& name, const std::string& glsl) {
  const IncludeResolver includes = [](const std::string& file) -> std::optional<std::string> {
    std::ifstream in(test::sourceDir() / "templates" / file);
    if (!in) return std::nullopt;
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const SpirvResult r = compileGlsl(glsl, ShaderStage::Compute, name, includes, BackendOptions{});
  if (!r.ok) {
    ADD_FAILURE() << name << ": " << r.log;
    return {};
  }
  return std::string(reinterpret_cast<const char*>(r.words.data()), r.words.size() * 4);
}

// Every texel of channel 0 (layer 0) within `tolerance` of expected(x, y); the message names
// the worst texel.
inline ::testing::AssertionResult imageMatches(const rt::HostImage& image,
                                               const std::function<double(uint32_t, uint32_t)>& expected,
                                               double tolerance) {
  double worst = -1;
  uint32_t wx = 0, wy = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const double err = std::fabs(double(image.texel(x, y)) - expected(x, y));
      if (!(err <= worst) || std::isnan(err)) {
        worst = std::isnan(err) ? INFINITY : err;
        wx = x;
        wy = y;
      }
    }
  if (worst <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << fmt::format("texel ({}, {}) is {} but should be {} (error {} > tolerance {})",
                                                      wx, wy, image.texel(wx, wy), expected(wx, wy), worst, tolerance);
}

}  // namespace shadowc::test

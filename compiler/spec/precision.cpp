// Exponent limits per storage format. Numbers: docs/dsl.md "Exponent limits".
#include "spec/precision.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace shadowc::spec {

ExponentLimit warpExponentLimit(const StorageSpec& storage, int mapSize) {
  // fp32: exp(2c) <= FLT_MAX gives c <= ln(FLT_MAX)/2 = 44.36; 42 is the common safe pick that
  // leaves headroom for the blur/mip sums of a few texels.
  constexpr double kFp32 = 42.0;
  // fp16: exp(2c) <= 65504 (largest half) gives c <= ln(65504)/2 = 5.545.
  const double kFp16 = std::log(65504.0) / 2.0;
  // 16 fractional bits (unorm16, int32 16.16 SAT): values are kept in (0,1], and e^2 = exp(2c(d-1))
  // must stay above the quantum 2^-16 over the depth range, so c <= ln(2^16)/2 = 5.545.
  const double k16Bits = std::log(65536.0) / 2.0;
  const double w = static_cast<double>(mapSize);
  switch (storage.sat) {
    case SatKind::Int32:
      return {k16Bits, "16.16 fixed point keeps 16 fractional bits: exp(2c) must stay within 2^16", "an int32 SAT"};
    case SatKind::Fp32Centered:
    case SatKind::Fp32Naive:
      // A SAT entry sums up to W^2 texels: W^2 exp(2c) <= FLT_MAX lowers the limit by ln(W^2)/2.
      return {kFp32 - std::log(w * w) / 2.0,
              fmt::format("fp32 c <= 42, minus ln(W^2)/2 = {:.2f} for sums over a {}^2 map (map_size)",
                          std::log(w * w) / 2.0, mapSize),
              fmt::format("an fp32 SAT of {}^2 texels", mapSize)};
    case SatKind::None:
      break;
  }
  switch (storage.format) {
    case StorageFormat::Fp16:
      return {kFp16, "exp(2c) must stay below 65504, the largest fp16", "fp16"};
    case StorageFormat::Unorm16:
      return {k16Bits, "unorm16 keeps 16 bits: exp(2c) must stay within 2^16", "unorm16"};
    case StorageFormat::Fp32:
      break;
  }
  return {kFp32, "exp(2c) must stay finite in fp32 (ln(FLT_MAX)/2 = 44.4; 42 keeps headroom)", "fp32"};
}

double msmDefaultBias(const StorageSpec& storage) {
  const bool sixteenBits =
      storage.sat == SatKind::Int32 || (storage.sat == SatKind::None && storage.format != StorageFormat::Fp32);
  return sixteenBits ? 3e-5 : 3e-6;
}

MsmSatPrecision msmFp32SatPrecision(const FilterSpec& spec) {
  const double w = static_cast<double>(spec.mapSize);
  const long long half = spec.kernel.size == KernelSize::Fixed ? (spec.kernel.fixedTexels + 1) / 2 : 1;
  MsmSatPrecision p;
  p.boxTexels = std::max(1LL, half * half);
  p.meanError = 2.0 * std::ldexp(1.0, -24) * w * w * w / static_cast<double>(p.boxTexels);
  return p;
}

}  // namespace shadowc::spec

// Precision limits of the moment storage formats (docs/dsl.md "Exponent limits"; lauritzen2008 sec. 6).
// The exponential warps store e = exp(c (d - 1)) and e^2 (positive part), and exp(c- (1 - d))
// and its square (EVSM4 negative part), so the format must represent a dynamic range of
// exp(2c) in the second moment. The checker rejects exponents above these limits instead of
// emitting a shader that overflows to Inf/NaN or quantizes every receiver to 0.
#pragma once

#include <string>

#include "spec/filter_spec.h"

namespace shadowc::spec {

struct ExponentLimit {
  double maxExponent = 0;   // largest safe warp exponent c for this storage
  std::string reason;       // one line: where the limit comes from
  std::string storageName;  // "fp16", "an fp32 SAT of 2048^2 texels", ...
};

ExponentLimit warpExponentLimit(const StorageSpec& storage, int mapSize);

// Int32 16.16 SAT: a box sum of k texels of values <= 1 fits in 32 bits while k*65536 < 2^32
// (modular arithmetic makes every such box sum exact; Lauritzen 2007), i.e. k <= 65535 texels.
inline constexpr int kInt32SatMaxBoxTexels = 65535;
// So a wider box is summed in pieces of at most 255 texels a side (255^2 <= 65535), each exact,
// added in float (templates/lookup/sat.glsl): kernels up to the whole map keep 16.16 precision.
inline constexpr int kInt32SatPieceTexels = 255;
// Search and penumbra kernels are clamped to `max` (at most this) and to the map.
inline constexpr double kMaxKernelTexels = 4096;
// Pieces per axis of the widest box a kernel clamped to `maxTexels` can query.
inline int int32SatPieces(double maxTexels) {
  const double w = maxTexels < 1 ? 1 : maxTexels > kMaxKernelTexels ? kMaxKernelTexels : maxTexels;
  return static_cast<int>((static_cast<long long>(w + 0.999999) + kInt32SatPieceTexels - 1) / kInt32SatPieceTexels);
}

// Moment shadow maps (Peters & Klein 2015). The moment bias alpha must cover the rounding of the
// stored moments: 3e-5 for 16-bit storage (unorm16, the 16.16 int32 SAT), the paper's value with
// the sec. 4.3 quantization; 3e-6 for fp32, the smallest for which fp32 evaluation of Algorithm 3
// keeps a single-depth receiver 1e-3 in front of its occluder lit (docs/techniques.md).
double msmDefaultBias(const StorageSpec& storage);

// Worst-case error of a box mean read from an fp32 SAT of moments (values in [0,1], centered or
// not): each entry is W row adds then W column adds of partial sums up to W^2 / 2, each rounding
// by 2^-24 of the sum, so |error| <= u W^3 / 2 per entry and 2 u W^3 over the four corners; the
// mean divides by the smallest box the kernel can read (a fixed kernel clipped at a map corner).
struct MsmSatPrecision {
  double meanError = 0;
  long long boxTexels = 1;
};
MsmSatPrecision msmFp32SatPrecision(const FilterSpec& spec);

}  // namespace shadowc::spec

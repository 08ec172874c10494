// Precision limits of the moment storage formats (FACTS.md "Precision"; lauritzen2008 sec. 6).
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
// (modular arithmetic makes every such box sum exact; FACTS.md), i.e. k <= 65535 texels.
inline constexpr int kInt32SatMaxBoxTexels = 65535;

}  // namespace shadowc::spec

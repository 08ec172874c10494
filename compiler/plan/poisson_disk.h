// Deterministic Poisson-disk tap sets for PCF and PCSS blocker search (pcss-blog: Poisson
// taps rotated per world position turn banding into noise).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace shadowc {

// `count` points in the unit disk by Mitchell's best-candidate dart throwing: each new point is
// the candidate (of 32 * k tried) farthest from the points so far. Uses its own splitmix64
// generator, not <random> distributions, so the taps are the same bytes on every platform.
std::vector<std::pair<double, double>> poissonDisk(int count, uint64_t seed);

}  // namespace shadowc

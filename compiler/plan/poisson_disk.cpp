// Best-candidate Poisson disk (see poisson_disk.h).
#include "plan/poisson_disk.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowc {

namespace {
struct SplitMix64 {
  uint64_t state;
  uint64_t next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};
}  // namespace

std::vector<std::pair<double, double>> poissonDisk(int count, uint64_t seed) {
  SplitMix64 rng{seed};
  std::vector<std::pair<double, double>> points;
  for (int i = 0; i < count; ++i) {
    const int candidates = 32 * (i + 1);
    std::pair<double, double> best{0.0, 0.0};
    double bestDistance = -1.0;
    for (int c = 0; c < candidates; ++c) {
      // Rejection sampling keeps the candidates uniform over the disk.
      double x, y;
      do {
        x = 2.0 * rng.unit() - 1.0;
        y = 2.0 * rng.unit() - 1.0;
      } while (x * x + y * y > 1.0);
      double nearest = std::numeric_limits<double>::max();
      for (const auto& p : points) nearest = std::min(nearest, std::hypot(x - p.first, y - p.second));
      if (nearest > bestDistance) {
        bestDistance = nearest;
        best = {x, y};
      }
    }
    points.push_back(best);
  }
  return points;
}

}  // namespace shadowc

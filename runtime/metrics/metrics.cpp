#include "runtime/metrics/metrics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace shadowc::rt {

Metrics computeMetrics(const std::vector<float>& result, const std::vector<float>& reference,
                       const std::vector<uint8_t>& mask) {
  if (result.size() != reference.size() || (!mask.empty() && mask.size() != result.size())) {
    throw std::invalid_argument(fmt::format("computeMetrics: sizes differ (result {}, reference {}, mask {})",
                                            result.size(), reference.size(), mask.size()));
  }
  Metrics m;
  std::vector<double> errors;
  errors.reserve(result.size());
  double sumSq = 0, sumAbs = 0;
  uint64_t bleeding = 0, darkening = 0;
  for (size_t i = 0; i < result.size(); ++i) {
    if (!mask.empty() && mask[i] == 0) continue;
    ++m.pixels;
    const double r = result[i], ref = reference[i];
    if (!std::isfinite(ref)) {
      ++m.invalidReference;
      continue;
    }
    if (!std::isfinite(r)) {
      ++m.nonFinite;
      continue;
    }
    if (r < 0.0 || r > 1.0) ++m.outOfRange;
    const double e = std::abs(r - ref);
    errors.push_back(e);
    sumSq += e * e;
    sumAbs += e;
    m.maxAbsError = std::max(m.maxAbsError, e);
    if (ref < 0.05 && r > 0.2) ++bleeding;
    if (ref > 0.95 && r < 0.8) ++darkening;
  }
  m.compared = errors.size();
  if (m.compared > 0) {
    const double n = double(m.compared);
    m.rmse = std::sqrt(sumSq / n);
    m.mae = sumAbs / n;
    m.lightBleeding = double(bleeding) / n;
    m.overDarkening = double(darkening) / n;
    // Nearest rank: the smallest error with at least 99% of the errors <= it.
    const size_t rank = size_t(std::ceil(0.99 * n));
    const auto kth = errors.begin() + std::ptrdiff_t(std::max<size_t>(rank, 1) - 1);
    std::nth_element(errors.begin(), kth, errors.end());
    m.p99AbsError = *kth;
  }
  return m;
}

nlohmann::ordered_json toJson(const Metrics& m) {
  return {{"pixels", m.pixels},
          {"compared", m.compared},
          {"rmse", m.rmse},
          {"mae", m.mae},
          {"max_abs_error", m.maxAbsError},
          {"p99_abs_error", m.p99AbsError},
          {"light_bleeding", m.lightBleeding},
          {"over_darkening", m.overDarkening},
          {"non_finite", m.nonFinite},
          {"out_of_range", m.outOfRange},
          {"invalid_reference", m.invalidReference}};
}

std::vector<uint8_t> geometryMask(const std::vector<float>& positionsRGBA) {
  std::vector<uint8_t> mask(positionsRGBA.size() / 4);
  for (size_t i = 0; i < mask.size(); ++i) mask[i] = positionsRGBA[i * 4 + 3] != 0.0f ? 1 : 0;
  return mask;
}

}  // namespace shadowc::rt

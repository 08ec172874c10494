#include "runtime/executor/timing_stats.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace shadowc::rt {

namespace {

// P(B <= m) for B ~ Binomial(n, 1/2), summed in logs so a large n does not overflow.
double binomialHalfCdf(int n, int m) {
  double sum = 0;
  for (int i = 0; i <= m; ++i)
    sum += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) - n * std::log(2.0));
  return sum;
}

}  // namespace

MedianRanks medianRanks(int n, double level) {
  if (n <= 0) return {};
  MedianRanks r{1, n, 1 - 2 * binomialHalfCdf(n, 0)};
  for (int j = 2; 2 * j <= n + 1; ++j) {
    const double coverage = 1 - 2 * binomialHalfCdf(n, j - 1);
    if (coverage < level) break;
    r = {j, n + 1 - j, coverage};
  }
  return r;
}

double TimingStats::relativeHalfWidth() const { return medianMs > 0 ? 0.5 * (ciHighMs - ciLowMs) / medianMs : 0; }
double TimingStats::relativeWiderSide() const {
  return medianMs > 0 ? std::max(medianMs - ciLowMs, ciHighMs - medianMs) / medianMs : 0;
}

std::string coverageText(double coverage) { return fmt::format("{:g} %", std::floor(1000 * coverage + 1e-9) / 10); }

std::string intervalLabel(const std::vector<double>& coverages) {
  if (coverages.empty()) return "interval";
  const auto [least, most] = std::minmax_element(coverages.begin(), coverages.end());
  return (coverageText(*least) == coverageText(*most) ? "" : ">= ") + coverageText(*least) + " interval";
}

TimingStats timingStats(std::vector<double> v) {
  TimingStats s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  s.n = static_cast<int>(n);
  s.minMs = v.front();
  s.maxMs = v.back();
  s.medianMs = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  s.p90Ms = v[static_cast<size_t>(std::ceil(0.9 * static_cast<double>(n))) - 1];
  s.meanMs = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(n);
  if (n > 1) {
    double ss = 0;
    for (double x : v) ss += (x - s.meanMs) * (x - s.meanMs);
    s.stddevMs = std::sqrt(ss / static_cast<double>(n - 1));
  }
  s.cv = s.meanMs > 0 ? s.stddevMs / s.meanMs : 0;
  const MedianRanks r = medianRanks(s.n);
  s.ciLowMs = v[static_cast<size_t>(r.low - 1)];
  s.ciHighMs = v[static_cast<size_t>(r.high - 1)];
  s.ciCoverage = r.coverage;
  return s;
}

nlohmann::ordered_json toJson(const TimingStats& s) {
  return {{"n", s.n},
          {"min_ms", s.minMs},
          {"median_ms", s.medianMs},
          {"p90_ms", s.p90Ms},
          {"max_ms", s.maxMs},
          {"mean_ms", s.meanMs},
          {"stddev_ms", s.stddevMs},
          {"cv", s.cv},
          {"ci_low_ms", s.ciLowMs},
          {"ci_high_ms", s.ciHighMs},
          {"ci_coverage", s.ciCoverage}};
}

TimingStats timingStatsFromJson(const nlohmann::json& j) {
  TimingStats s;
  s.n = j.at("n").get<int>();
  s.minMs = j.at("min_ms").get<double>();
  s.medianMs = j.at("median_ms").get<double>();
  s.p90Ms = j.at("p90_ms").get<double>();
  s.maxMs = j.at("max_ms").get<double>();
  s.meanMs = j.at("mean_ms").get<double>();
  s.stddevMs = j.at("stddev_ms").get<double>();
  s.cv = j.at("cv").get<double>();
  s.ciLowMs = j.at("ci_low_ms").get<double>();
  s.ciHighMs = j.at("ci_high_ms").get<double>();
  s.ciCoverage = j.at("ci_coverage").get<double>();
  return s;
}

}  // namespace shadowc::rt

// Statistics of a set of timed runs: min, median, p90 and the median's confidence interval
// (docs/runtime.md "Timing statistics"). Pure arithmetic on the samples, no clock.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace shadowc::rt {

// The 1-based ranks j <= k of the order statistics that bracket the median, and the probability
// that the population median lies in [X_(j), X_(k)].
struct MedianRanks {
  int low = 0, high = 0;
  double coverage = 0;
};

// Distribution-free interval of the median from order statistics: for n samples of a continuous
// distribution the count B of samples below the median is Binomial(n, 1/2), so
//   P(X_(j) <= median <= X_(n+1-j)) = 1 - 2 * P(B <= j - 1) = 1 - 2 * sum_{i<j} C(n, i) / 2^n.
// j is the largest rank with coverage >= `level`. When even j = 1 falls short (n < 6 for 0.95) the
// interval is [X_(1), X_(n)] and `coverage` says what it reaches (1 - 2^(1-n)). n = 0 gives {0, 0, 0}.
MedianRanks medianRanks(int n, double level = 0.95);

struct TimingStats {
  int n = 0;
  double minMs = 0, medianMs = 0, p90Ms = 0, maxMs = 0;
  double meanMs = 0, stddevMs = 0;   // sample standard deviation (n - 1); 0 for n < 2
  double cv = 0;                     // stddev / mean; 0 when the mean is 0
  double ciLowMs = 0, ciHighMs = 0;  // the median's interval (medianRanks)
  double ciCoverage = 0;             // what that interval covers: >= 0.95, or less for n < 6
  // Half the interval's width relative to the median.
  double relativeHalfWidth() const;
  // The interval's wider side relative to the median, max(median - low, high - median) / median:
  // how far the median may be off in the worse direction (what `--runs auto` narrows,
  // docs/runtime.md "Automatic run count"); at least relativeHalfWidth, more when lopsided.
  double relativeWiderSide() const;
};

// "93.7 %": a coverage floored to a tenth of a percent, so that a label never claims more than
// the interval covers (n = 5: 0.9375; n = 2: "50 %").
std::string coverageText(double coverage);
// The heading of a column of intervals with these coverages: "96.8 % interval" when they all
// cover the same, ">= 93.7 % interval" (the least) when they differ, "interval" for none.
std::string intervalLabel(const std::vector<double>& coverages);

// p90 is the nearest-rank percentile: the ceil(0.9 n)-th smallest sample. All zero when empty.
TimingStats timingStats(std::vector<double> samplesMs);

// {"n", "min_ms", "median_ms", "p90_ms", "max_ms", "mean_ms", "stddev_ms", "cv", "ci_low_ms",
// "ci_high_ms", "ci_coverage"}: how validate's JSON and the sweep's results hold a time.
nlohmann::ordered_json toJson(const TimingStats& stats);
// The inverse; throws nlohmann::json::exception on a missing field.
TimingStats timingStatsFromJson(const nlohmann::json& j);

}  // namespace shadowc::rt

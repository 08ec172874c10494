// One result row (a variant on a case), a skipped variant, and a whole result set: what
// results.json / results.csv hold (docs/sweep.md "Results"), what merge reads back.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runtime/executor/timing_stats.h"
#include "runtime/harness/work_counts.h"
#include "runtime/metrics/metrics.h"

namespace shadowc::sweep {

struct PassTime {
  std::string name, kind;
  double medianMs = 0;
};

struct Row {
  std::string key;  // the cache key (cache_key.h): variant spec x scene x settings
  size_t variantIndex = 0, caseIndex = 0;
  std::string variant;  // label
  std::string base;     // base filter name
  std::vector<std::pair<std::string, std::string>> params;
  std::string shader = "specialized";
  std::string caseLabel, scene, sceneHash;
  uint32_t screen = 0, map = 0;
  int referenceSamples = 0, runs = 0, warmup = 0;
  nlohmann::ordered_json spec;  // the checker's normalized FilterSpec (specToJson)
  std::string filterText;       // the variant's filter description
  std::string normalizedText;   // the same filter with every default explicit (printFilter)
  std::string contentHash;      // manifest content hash of the compiled variant
  std::vector<PassTime> passes;
  double totalMs = 0;
  rt::TimingStats total;                    // the run totals' statistics (timing_stats.h); median == totalMs
  std::string clock = "device timestamps";  // rt::toString(TimingClock): what timed the row
  std::string busyWarning;                  // rt::busyWarning of its timing: empty on a quiet machine
  int rejectedRuns = 0;                     // implausible readings left out (docs/runtime.md "Rejected runs")
  rt::Metrics metrics;
  std::optional<rt::WorkCounts> work;  // the instrumented build's counts of one run ("counters": true)
  // The frame a device cost profile predicts from `work` (`sweep --cost-profile`, docs/cost.md):
  // when set, the frontier ranks by it (pareto.h rankedMs) and `totalMs` stays the measurement.
  std::optional<double> predictedMs;
  std::string device;
  std::string resultImage, errorImage, referenceImage;  // relative to the output folder
};

// A variant the checker (or the run) rejected: never a crash, counted by code.
struct Skipped {
  size_t variantIndex = 0;
  std::string variant;
  // The checker's diagnostic code (E0416 ...), or the sweep's own (docs/sweep.md "Skipped"): SW002 the run failed,
  // SW003 compile failed without a diagnostic, SW004 the map is larger than the filter's map_size.
  std::string code;
  std::string message;  // its first error, in glslc form without the caret lines
};

struct RunStats {
  size_t ran = 0, cached = 0;
};

struct Results {
  std::string sweep;          // the description's name
  std::string shard = "0/1";  // or "merged"
  std::vector<Row> rows;      // sorted by (case, variant)
  std::vector<Skipped> skipped;
  RunStats stats;
};

}  // namespace shadowc::sweep

// Error of a visibility image against a reference (Embree or a CPU filter reference), over
// the pixels a mask selects. One metrics module for the whole project (sweep, validate, tests).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

namespace shadowc::rt {

struct Metrics {
  uint64_t pixels = 0;    // pixels selected by the mask
  uint64_t compared = 0;  // of those, with a finite result and reference (the error stats)
  double rmse = 0, mae = 0, maxAbsError = 0;
  double p99AbsError = 0;         // nearest-rank 99th percentile of |result - reference|
  double lightBleeding = 0;       // fraction of `compared` with reference < 0.05 but result > 0.2
  double overDarkening = 0;       // fraction of `compared` with reference > 0.95 but result < 0.8
  uint64_t nonFinite = 0;         // NaN/Inf results (counted, never propagated into the stats)
  uint64_t outOfRange = 0;        // finite results outside [0, 1]
  uint64_t invalidReference = 0;  // NaN/Inf reference pixels (skipped)
};

// `mask`: empty = every pixel; else one byte per pixel, non-zero = compare. Sizes must agree
// (std::invalid_argument otherwise).
Metrics computeMetrics(const std::vector<float>& result, const std::vector<float>& reference,
                       const std::vector<uint8_t>& mask);

// Keys in a fixed order: pixels, compared, rmse, mae, max_abs_error, p99_abs_error,
// light_bleeding, over_darkening, non_finite, out_of_range, invalid_reference.
nlohmann::ordered_json toJson(const Metrics& m);

// The mask of G-buffer geometry pixels (position.w != 0) from an RGBA position buffer.
std::vector<uint8_t> geometryMask(const std::vector<float>& positionsRGBA);

}  // namespace shadowc::rt

// The work counts of one run of an instrumented build (`shadowc compile --counters`,
// docs/manifest.md "Work counters"): the totals the shade pass added into the manifest's
// counter buffer, by field, and per receiver. Read by the run harness after a counted run;
// shown by `validate --counters` and carried by the sweep's rows.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "manifest/manifest.h"

namespace shadowc::rt {

struct WorkCounts {
  std::string pass;                 // the pass that adds into the buffer ("shade")
  std::vector<std::string> fields;  // the manifest buffer's fields, in its order
  std::vector<uint64_t> totals;     // summed over every invocation of one run
  // The total of a field, or nullopt when the build does not count it.
  std::optional<uint64_t> total(const std::string& field) const;
  uint64_t receivers() const;  // the "receivers" total (0 when absent)
  // total / receivers; 0 when there are none.
  double perReceiver(const std::string& field) const;
  friend bool operator==(const WorkCounts&, const WorkCounts&) = default;
};

// The manifest's counter buffer (one with fields) and the pass that writes it, or nullptr when
// the build is not instrumented.
const BufferDesc* workCounterBuffer(const Manifest& manifest);
// The counts in the buffer's words as read back: (low, high) words a field. Throws
// std::invalid_argument when the words do not match the buffer's fields.
WorkCounts workCountsFromWords(const Manifest& manifest, const std::vector<int32_t>& words);

// "depth_fetches=25;sat_fetches=38.439": every nonzero field but the receivers, per receiver,
// at most 6 significant digits (a CSV cell; the JSON carries the exact totals).
std::string workFields(const WorkCounts& work);
// {"pass": ..., "receivers": N, "fields": [in buffer order], "totals": {field: total},
// "per_receiver": {field: x}}.
nlohmann::ordered_json workJson(const WorkCounts& work);
// The inverse of workJson (its "totals" and "pass"); throws std::invalid_argument on a bad shape.
WorkCounts workFromJson(const nlohmann::json& j);

}  // namespace shadowc::rt

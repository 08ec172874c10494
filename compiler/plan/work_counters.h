// The instrumented build (`shadowc compile --counters`, docs/manifest.md "Work counters"): the
// same shade pass with counters of the work it does, summed over its invocations into a storage
// buffer the manifest declares. Counts are exact and the same on every device, at any load and
// from run to run: what a pixel costs in fetches, bounds and walk steps, where a time is only a
// reading of one machine.
//
// Only the shade pass is instrumented: it is where a filter's work depends on the scene. The
// prefilter passes (moments, blur, SAT, mips, min-max, Lloyd) do a fixed amount per map texel,
// set when the filter is compiled.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "plan/pass_graph.h"

namespace shadowc {

struct WorkCounter {
  const char* name;   // the manifest's field, e.g. "depth_fetches"
  const char* macro;  // the template's index, e.g. "SHADOWC_WORK_DEPTH_FETCHES"
  const char* what;   // one line for docs and --help
};

// Every counter, in buffer order (element k counts workCounters()[k]). The first is the
// receivers: pixels with geometry, which every other count is divided by for "per receiver".
const std::vector<WorkCounter>& workCounters();

inline constexpr const char* kWorkCounterBuffer = "work_counters";
inline constexpr uint32_t kWorkCounterBinding = 11;  // after the quadtree tables at 10

// Adds the counters to the shade pass of `graph`: the manifest's buffer kWorkCounterBuffer (two
// zero words a counter, its `fields` the counters' names), its binding with access
// storage_buffer_read_write, and the SHADOWC_COUNTERS switch and indices the templates read.
// Deterministic. Throws InternalError when the graph has no shade pass or is counted already.
void addWorkCounters(PassGraph& graph);

}  // namespace shadowc

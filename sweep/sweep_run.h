// The sweep itself: expand the description, check every variant through the compiler driver
// (an invalid combination is skipped under the checker's own code), look each (variant, case)
// up in the cache, compile what must run (in parallel threads: compiling is CPU work that does
// not disturb timing, since nothing runs on the device yet), then run each case's variants
// through the run harness (prepareScene once per case, runOnScene per variant) one at a time,
// writing each finished row to the cache atomically as it completes.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>

#include "sweep/expand.h"
#include "sweep/sweep_row.h"
#include "sweep/sweep_spec.h"

namespace shadowc::sweep {

struct SweepOptions {
  std::filesystem::path outDir;
  Shard shard;
  int jobs = 0;             // compile threads; 0 = one per hardware thread
  std::string device;       // --device ("" = llvmpipe)
  bool validation = false;  // Khronos validation layer (also SHADOWC_VALIDATION=1)
  bool useReferenceCache = true;
  int tty = -1;  // progress bar: -1 = when stderr is a terminal
  // Test hook (env SHADOWC_SWEEP_STOP_AFTER): end the process abruptly, as a kill would, once
  // this many rows have run; 0 = never. The resume test counts what a rerun runs again.
  size_t stopAfter = 0;
};

struct SweepOutcome {
  Results results;
  size_t validationMessages = 0;
};

SweepOutcome runSweep(const SweepSpec& spec, const SweepOptions& options, std::FILE* log);

}  // namespace shadowc::sweep

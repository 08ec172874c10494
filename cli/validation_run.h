// The body of `shadowc validate` and `shadowc demo`: compile a filter with the driver, prepare the
// scene (rasterize + Embree reference) and run the passes through the run harness with per-pass
// timing (runtime/harness/scene_run.h), then report. One place so both commands report alike.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "runtime/executor/run_timing.h"

namespace shadowc::cli {

struct ValidationOptions {
  std::string filterPath;    // a .shadow file, or a label when filterSource is set
  std::string filterSource;  // the filter text itself (demo: embedded sample); empty = read filterPath
  std::string scene = "two_planes";
  uint32_t size = 512;    // screen width = height
  uint32_t map = 1024;    // shadow-map side
  bool mapGiven = false;  // --map given: else the filter's planned `resolution`, when it has one
  int samples = 16;       // reference light samples per axis
  std::string jsonOut;    // empty = none
  std::string imagesDir;  // empty = none
  std::string device;     // --device
  bool validation = false;
  rt::RunCount runs = 10;
  int warmup = 3;
  bool useCache = true;  // reference cache
  std::string passForm;  // --pass-form: auto, or a form name (serial, parallel); "" = SHADOWC_PASS_FORM or auto
  // --counters: also run the instrumented build once and report its work per receiver
  // (docs/manifest.md "Work counters"); the times stay those of the plain build.
  bool counters = false;
};

// Prints the report on stdout (progress on stderr). Returns the process exit code; throws
// on runtime errors (the caller prints "shadowc: error: ...").
int runValidation(const ValidationOptions& options);

}  // namespace shadowc::cli

// The cache key of one row: a content hash of everything that decides its numbers — the
// variant's normalized spec (what the checker made of its text, so reformatting the text or
// reordering settings keeps the key), the shader kind, the content hash of the code shadowc
// emitted for it (manifest.contentHash: a new template or folding rule makes a new key), the
// scene's content hash (geometry,
// camera and light), screen, map, reference samples, runs, warm-up and the device asked for.
// The same key means the row need not run again (docs/sweep.md "Resume and caching").
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "runtime/executor/run_timing.h"

namespace shadowc::sweep {

struct KeyInputs {
  nlohmann::ordered_json spec;
  std::string shader;
  std::string emitted;  // the compiled variant's manifest content hash
  std::string sceneHash;
  uint32_t screen = 0, map = 0;
  int referenceSamples = 0;
  rt::RunCount runs;
  int warmup = 0;
  std::string device;
  bool counters = false;  // the row carries work counts (sweep_spec.h)
};

// 32 hex digits (XXH3-128 through emit/content_hash.h, the project's one hash).
std::string cacheKey(const KeyInputs& in);

}  // namespace shadowc::sweep

// The emitter's entry point: PassGraph -> every output file of `shadowc compile`, in memory.
// It only renders what the planner decided: one shader per distinct pass source
// (shader_emitter.h) -> the includable lookup file (the shade pass's values) -> manifest.json
// with the content hash. Writing is separate (output_writer.h), so nothing reaches the disk
// unless every shader compiled and validated.
#pragma once

#include <string>
#include <vector>

#include "emit/content_hash.h"
#include "manifest/manifest.h"
#include "plan/pass_graph.h"
#include "spec/filter_spec.h"

namespace shadowc {

struct EmitOptions {
  bool optimize = true;           // -O (default) / -O0
  bool warningsAsErrors = false;  // -Werror
};

struct FilterEmitResult {
  bool ok = false;
  std::string log;  // compiler diagnostics when !ok (and warnings)
  Manifest manifest;
  std::vector<EmittedFile> files;  // sorted by name: <stem>.glsl/.spv, <filter>_lookup.glsl, manifest.json
};

// `graph` is planPasses(spec); compiler/driver/ is the one caller that wires the two. A
// malformed graph is an InternalError (plan/internal_error.h).
FilterEmitResult emitPassGraph(const FilterSpec& spec, const PassGraph& graph, const EmitOptions& options = {});

// The manifest's file name and the lookup file's name for a filter.
inline constexpr const char* kManifestFile = "manifest.json";
std::string lookupFileName(const std::string& filterName);

// SPIR-V words as the bytes of a .spv file (little-endian, as every consumer expects).
std::string spirvBytes(const std::vector<uint32_t>& words);

}  // namespace shadowc

// The emitter's entry points: PassGraph -> every output file of `shadowc compile`, in memory,
// in two steps around the backend, which the driver alone calls (docs/integration.md "Layering"):
//   emitSources: one shader text per distinct pass source (shader_emitter.h), the includable
//                lookup (the shade pass's values) and the manifest without its hash;
//   emitOutputs: with the SPIR-V the driver compiled from those texts, the files and
//                manifest.json with the content hash.
// It only renders what the planner decided. Writing is separate (output_writer.h), so nothing
// reaches the disk unless every shader compiled and validated.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "emit/content_hash.h"
#include "emit/glsl_preprocessor.h"
#include "emit/lookup_interface.h"
#include "emit/shader_emitter.h"
#include "manifest/manifest.h"
#include "plan/pass_graph.h"
#include "spec/filter_spec.h"

namespace shadowc {

struct EmitOptions {
  bool warningsAsErrors = false;  // -Werror
  LookupPlacement lookup;         // --lookup-set / --lookup-binding-base (lookup_interface.h)
  GlslPreprocessor preprocess;    // the driver's (glsl_preprocessor.h); required
};

// The texts the backend compiles, and the manifest they fill in.
struct FilterSources {
  bool ok = false;
  std::string log;  // diagnostics when !ok (and warnings)
  Manifest manifest;                            // local sizes and "shade" filled; no content hash yet
  std::map<std::string, EmittedShader> shaders;  // by output stem (<stem>.glsl / <stem>.spv)
  std::string lookupText;                        // <filter>_lookup.glsl
  // The lookup inside an empty compute shader: it must compile where an engine includes it.
  std::string lookupCheck;
};

struct FilterEmitResult {
  bool ok = false;
  std::string log;  // compiler diagnostics when !ok (and warnings)
  Manifest manifest;
  std::vector<EmittedFile> files;  // sorted by name: <stem>.glsl/.spv, <filter>_lookup.glsl, manifest.json
};

// `graph` is planPasses(spec); compiler/driver/ is the one caller that wires the two. A
// malformed graph is an InternalError (plan/internal_error.h).
FilterSources emitSources(const FilterSpec& spec, const PassGraph& graph, const EmitOptions& options);

// `spirv` holds the compiled module of every shader in `sources`, by stem.
FilterEmitResult emitOutputs(const FilterSpec& spec, FilterSources sources,
                             const std::map<std::string, std::vector<uint32_t>>& spirv);

// The manifest's file name and the lookup file's name for a filter.
inline constexpr const char* kManifestFile = "manifest.json";
std::string lookupFileName(const std::string& filterName);

// SPIR-V words as the bytes of a .spv file (little-endian, as every consumer expects).
std::string spirvBytes(const std::vector<uint32_t>& words);

}  // namespace shadowc

// The compiler driver: the one place that runs the stages in order:
//   load (dsl/ lexer + parser) -> check (spec/) -> plan (plan/) -> emit (emit/) -> backend
// for every caller — the CLI, validation/, the tests, bench/, `sweep` and `plan`. Nothing else
// wires stages together (tests/architecture keeps it so). The result lives in memory; writing
// it to disk is a separate step (writeArtifact), so nothing reaches the disk unless every
// shader compiled and validated.
#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "emit/content_hash.h"  // EmittedFile
#include "emit/lookup_interface.h"
#include "manifest/compiled_passes.h"
#include "manifest/manifest.h"
#include "plan/pass_graph.h"
#include "spec/filter_spec.h"
#include "spec/load_filter.h"  // Diagnostic

namespace shadowc::driver {

// Where the driver stops: `shadowc check` stops after Check, `--print-plan` / -M after Plan.
enum class Stage { Check, Plan, Emit };

// What `--emit` keeps when the artifact is written. Glsl, Spirv and Manifest are always in the
// artifact; Hlsl, Msl and CppHeader are derived from the SPIR-V (a SPIRV-Cross translation per
// shader) and only produced when Options::engineOutputs asks for them.
enum class OutputKind { Glsl, Spirv, Manifest, Hlsl, Msl, CppHeader };
// manifest.json -> Manifest, *.spv -> Spirv, *.hlsl -> Hlsl, *.metal -> Msl, *.h -> CppHeader,
// everything else (pass .glsl, the lookup) -> Glsl.
OutputKind outputKindOf(const std::string& fileName);

struct Options {
  bool optimize = true;           // -O (default) / -O0
  bool warningsAsErrors = false;  // -Werror: front-end and GLSL warnings fail the compile
  Stage stopAfter = Stage::Emit;
  // compileSpec re-checks a spec built in code through the checker. Off only for the stability
  // suite's naive demonstrations (docs/stability.md), which compile on purpose what the checker
  // rightly rejects (an EVSM exponent past the storage limit) to show it failing.
  bool checkBuiltSpec = true;
  LookupPlacement lookup;  // --lookup-set / --lookup-binding-base (emit/lookup_interface.h)
  // --generic: the shade pass as engines usually ship it, its numeric options and tables in a
  // uniform block the runtime fills from the manifest, its loops dynamic (plan/generic_block.h).
  bool generic = false;
  // --counters: the instrumented build, whose shade pass counts its work per pixel into the
  // manifest's work_counters buffer (plan/work_counters.h, docs/manifest.md "Work counters").
  bool counters = false;
  // --frame-external: the HLSL / MSL lookup takes the frame as arguments of shadowc_visibilityFrame
  // instead of declaring our uniform block (driver/cross_outputs.h); GLSL has SHADOWC_FRAME_EXTERNAL.
  bool frameExternal = false;
  std::set<OutputKind> engineOutputs;  // any of Hlsl, Msl, CppHeader (driver/cross_outputs.h, emit/cpp_header.h)
};

// A compiled filter, in memory.
struct Artifact {
  FilterSpec spec;                 // the checked, normalized spec
  PassGraph plan;                  // the planner's output (passes, images, typed values)
  Manifest manifest;               // as written to manifest.json (spec, hash, shade included)
  std::vector<EmittedFile> files;  // sorted by name: <stem>.glsl/.spv, <filter>_lookup.glsl, manifest.json
                                   // (+ <stem>.hlsl/.metal, <filter>_lookup.hlsl/.metal, <filter>.h when asked)
  // The bytes of one output file, or nullptr.
  const std::string* file(const std::string& name) const;
  // The manifest and its .spv files, for the run harness (runtime/harness/run_harness.h).
  CompiledPasses passes() const;
};

struct Result {
  std::vector<Diagnostic> diagnostics;  // front end (checker) diagnostics, errors and warnings
  std::string log;                      // everything to show the user: formatted diagnostics + backend log
  std::optional<FilterSpec> spec;       // set once Check passed
  std::optional<PassGraph> plan;        // set once Plan ran
  std::optional<Artifact> artifact;     // set once Emit succeeded
  // True when the requested stage completed without errors.
  bool ok = false;
};

Result compileSource(const std::string& text, const std::string& fileName, const Options& options = {});
Result compileFile(const std::string& path, const Options& options = {});
// A spec built in code (validation/, tests, the planner's edits): it goes through the
// checker's validation first (spec/validate.h), so an invalid hand-built spec is a located
// diagnostic, never an emitter exception.
Result compileSpec(const FilterSpec& spec, const Options& options = {});

// The output file names a spec will produce, without compiling (for -M), including the engine
// outputs asked for.
std::vector<std::string> plannedOutputs(const PassGraph& plan, const FilterSpec& spec,
                                        const std::set<OutputKind>& engineOutputs = {});

// A compiled artifact's pass shaders (not the lookup), each as the driver compiled it:
// bench/compile_bench times the backend alone on these.
struct ShaderText {
  std::string stem, glsl;
  std::vector<std::string> keepCalls;  // calls the -O compile keeps (emit/shader_emitter.h keptCalls)
};
std::vector<ShaderText> shaderTexts(const Artifact& artifact);
// The driver's -O compile of one of them; false with the backend's log appended.
bool compileShaderText(const ShaderText& shader, std::string& log);
// The -O recipe, in order, as spirv-opt flags (`shadowc compile --print-recipe`).
const std::vector<std::string>& optimizationRecipe();

// Writes the artifact's files of the given kinds (all when empty) plus `extra` files into
// `dir`, all-or-nothing (emit/output_writer.h). Returns "" on success, else one line.
std::string writeArtifact(const std::filesystem::path& dir, const Artifact& artifact,
                          const std::set<OutputKind>& kinds = {}, const std::vector<EmittedFile>& extra = {});

}  // namespace shadowc::driver

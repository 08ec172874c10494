// GLSL -> SPIR-V in process: glslang front end, an explicit spirv-opt recipe, spirv-val.
// No shelling out (ground rules: "glslang and SPIRV-Tools in process"). Knows nothing about
// shadows; the runtime uses it for its own raster shaders as well.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowc {

enum class ShaderStage { Vertex, Fragment, Compute };

// Resolves `#include "name"` (GL_GOOGLE_include_directive). Returns nullopt when unknown.
using IncludeResolver = std::function<std::optional<std::string>(const std::string& name)>;

struct SpirvResult {
  bool ok = false;
  std::vector<uint32_t> words;
  std::string log;  // glslang / optimizer / validator messages, "name:line: error: ..." form
};

struct BackendOptions {
  bool optimize = true;  // run the -O recipe; false = -O0 (no spirv-opt at all)
  bool validate = true;  // spirv-val after every stage of the recipe
  // GLSL functions the recipe keeps as calls (dont_inline.h): an unrolled quadtree's node
  // callbacks, whose inlined copies made the recipe take seconds.
  std::vector<std::string> keepCalls;
};

// Runs the glslang preprocessor only: folds #define constants and strips #if'd-out code so
// that an emitted .glsl holds only the code the filter uses. `name` labels diagnostics.
SpirvResult preprocessGlsl(std::string_view source, ShaderStage stage, const std::string& name,
                           const IncludeResolver& includes, std::string& out);

// Compiles GLSL 4.60 for Vulkan 1.2 / SPIR-V 1.5, then optimizes and validates.
SpirvResult compileGlsl(std::string_view source, ShaderStage stage, const std::string& name,
                        const IncludeResolver& includes, const BackendOptions& options);

// HLSL -> SPIR-V with glslang's HLSL front end (entry point `entry`), validated, never
// optimized: the round-trip check of translated HLSL (cross_compile.h, tests/engine).
SpirvResult compileHlsl(std::string_view source, ShaderStage stage, const std::string& name, const std::string& entry);

// spirv-val on a module (Vulkan 1.2 rules). Empty string when valid, else the message.
std::string validateSpirv(const std::vector<uint32_t>& words);

// The -O recipe, in order, as spirv-opt flags (printed by `shadowc compile --print-recipe`).
const std::vector<std::string>& optimizationRecipe();

// Disassembly for golden tests and debugging.
std::string disassembleSpirv(const std::vector<uint32_t>& words);

}  // namespace shadowc

// SPIR-V -> HLSL / MSL in process with SPIRV-Cross (Debian's libspirv-cross-c-shared-dev ships
// the C++ libraries and their CMake configs), for engines that do not consume SPIR-V. Like the
// rest of backend/ it knows nothing about shadows: one module in, one source text out.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace shadowc {

enum class CrossTarget { Hlsl, Msl };

// The fixed target versions (recorded in docs/cli.md): HLSL shader model 5.0 (the oldest with
// compute shaders and typed UAV loads; compiled back by glslang's HLSL front end in the tests),
// MSL 2.1 for macOS.
inline constexpr uint32_t kHlslShaderModel = 50;
inline constexpr uint32_t kMslVersionMajor = 2, kMslVersionMinor = 1;

struct CrossResult {
  bool ok = false;
  std::string source;  // the translated shader
  std::string log;     // "name: error: ..." when !ok
};

// Translates `spirv` (one module, one entry point). `entryName` renames the entry point in the
// output ("" keeps SPIRV-Cross's default: main / main0) so that translated pieces meant for
// inclusion do not clash with the including shader's own entry point. `name` labels messages.
CrossResult crossCompile(const std::vector<uint32_t>& spirv, CrossTarget target, const std::string& name,
                         const std::string& entryName = "");

// File extension (with the dot) of a translated shader: ".hlsl", ".metal".
const char* crossExtension(CrossTarget target);

}  // namespace shadowc

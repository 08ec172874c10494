// One shader from one template: insert the specialization at the `// @shadowc:specialize`
// marker (#defines, generated tables, then `#line` back into the template), run the glslang
// preprocessor so the emitted GLSL holds only folded, used code, tidy it, and compile exactly
// that text to SPIR-V (glslang -> spirv-opt recipe -> spirv-val, in process).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "backend/spirv_backend.h"
#include "plan/specialization.h"

namespace shadowc {

struct EmittedShader {
  bool ok = false;
  std::string log;   // diagnostics, "templates/<path>:line: ..." form
  std::string glsl;  // the emitted (preprocessed) GLSL
  std::vector<uint32_t> spirv;
  std::array<uint32_t, 3> localSize{1, 1, 1};  // read back from the emitted layout(local_size_*)
};

struct ShaderEmitOptions {
  bool optimize = true;           // -O recipe; false = -O0
  bool warningsAsErrors = false;  // a preprocessor/compiler warning fails the shader
};

EmittedShader emitComputeShader(const std::string& templatePath, const Specialization& specialization,
                                const ShaderEmitOptions& options);

// The functions a shader's -O compile keeps as calls (BackendOptions::keepCalls): an unrolled
// quadtree's node callbacks (backend/dont_inline.h). bench/compile_bench uses the same list.
std::vector<std::string> keptCalls(const Specialization& specialization);

// The specialized (not yet preprocessed) text: template with the block at the marker.
// Sets `error` (and returns "") when the template is unknown or has no marker.
std::string specializeTemplate(const std::string& templatePath, const Specialization& specialization,
                               std::string& error);

}  // namespace shadowc

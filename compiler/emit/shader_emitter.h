// One shader's text from one template: insert the specialization at the `// @shadowc:specialize`
// marker (#defines, generated tables, then `#line` back into the template), run the GLSL
// preprocessor (glsl_preprocessor.h) so the emitted GLSL holds only folded, used code, and tidy
// it. The driver compiles exactly that text to SPIR-V (driver/shader_compile.h).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "emit/glsl_preprocessor.h"
#include "plan/specialization.h"

namespace shadowc {

struct EmittedShader {
  bool ok = false;
  std::string name;  // "templates/<path>": what diagnostics point into
  std::string log;   // diagnostics, "templates/<path>:line: ..." form
  std::string glsl;  // the emitted (preprocessed) GLSL
  std::array<uint32_t, 3> localSize{1, 1, 1};  // read back from the emitted layout(local_size_*)
  std::vector<std::string> keepCalls;          // keptCalls(specialization)
};

// `warningsAsErrors`: a preprocessor warning fails the shader.
EmittedShader emitComputeShader(const std::string& templatePath, const Specialization& specialization,
                                const GlslPreprocessor& preprocess, bool warningsAsErrors = false);

// glslang's info log says "WARNING:" for warnings that do not fail a compile.
bool hasWarning(const std::string& log);

// The functions a shader's -O compile keeps as calls: an unrolled quadtree's node callbacks,
// whose inlined copies made the optimizer take seconds (backend/dont_inline.h).
std::vector<std::string> keptCalls(const Specialization& specialization);

// The specialized (not yet preprocessed) text: template with the block at the marker.
// Sets `error` (and returns "") when the template is unknown or has no marker.
std::string specializeTemplate(const std::string& templatePath, const Specialization& specialization,
                               std::string& error);

}  // namespace shadowc

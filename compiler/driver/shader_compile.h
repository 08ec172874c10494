// The backend's side of emitting a shader: the emitter renders text (emit/shader_emitter.h) with
// glslang's preprocessor handed to it as a callback, and the driver compiles exactly that text
// (glslang -> spirv-opt recipe -> spirv-val, in process), so the .spv is the .glsl that ships.
// The driver is the one stage that calls the backend (docs/integration.md "Layering").
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "emit/glsl_preprocessor.h"
#include "emit/shader_emitter.h"
#include "plan/specialization.h"

namespace shadowc::driver {

// glslang's preprocessor, for the emitter.
GlslPreprocessor glslangPreprocessor();

struct ShaderOptions {
  bool optimize = true;           // -O recipe; false = -O0
  bool warningsAsErrors = false;  // a preprocessor or compiler warning fails the shader
};

// Compiles an emitted shader's text (its kept calls stay calls at -O). Appends the backend's
// messages to `log`; false when it failed (or warned under warningsAsErrors).
bool compileEmitted(const EmittedShader& shader, const ShaderOptions& options, std::vector<uint32_t>& words,
                    std::string& log);

// One pass shader from one template, emitted and compiled: what the emit tests inspect.
struct CompiledShader {
  bool ok = false;
  std::string log;   // diagnostics, "templates/<path>:line: ..." form
  std::string glsl;  // the emitted (preprocessed) GLSL
  std::vector<uint32_t> spirv;
  std::array<uint32_t, 3> localSize{1, 1, 1};
};
CompiledShader compileShader(const std::string& templatePath, const Specialization& specialization,
                             const ShaderOptions& options = {});

// Compiles GLSL that is not a template's (the includable lookup inside a probe) without the
// optimizer, as an engine's compiler would first see it. False with the log appended.
bool compileUnoptimized(const std::string& glsl, const std::string& name, std::string& log);

}  // namespace shadowc::driver

// The emitter renders text only: the GLSL preprocessor it needs (to fold #define constants and
// strip #if'd-out code, so an emitted .glsl holds only the code the filter uses) reaches it as
// this callback. The driver supplies glslang's (driver/shader_compile.h); emit links no backend
// (docs/integration.md "Layering").
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace shadowc {

// Resolves `#include "name"` against the embedded templates (template_includes.h); the same
// function type the backend takes.
using TemplateResolver = std::function<std::optional<std::string>(const std::string& name)>;

// Preprocesses `source` (a compute shader) with #include resolved by `includes`; writes the
// result to `out` and the preprocessor's messages to `log` ("name:line: error: ..." form, and
// "WARNING:" for warnings). False when preprocessing failed. `name` labels diagnostics.
using GlslPreprocessor = std::function<bool(std::string_view source, const std::string& name,
                                            const TemplateResolver& includes, std::string& out, std::string& log)>;

}  // namespace shadowc

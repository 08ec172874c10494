// Resolves `#include "name"` in templates against the embedded templates/ tree. Names are
// relative to templates/ ("frame.glsl", "passes/sat_common.glsl"), which is also how
// `glslangValidator -I templates` resolves them when a template is compiled on its own.
#pragma once

#include <string_view>

#include "emit/glsl_preprocessor.h"

namespace shadowc {

TemplateResolver templateIncludes();

// The template's text, or an empty view when the embedded tree has no such file.
std::string_view templateText(std::string_view path);

}  // namespace shadowc

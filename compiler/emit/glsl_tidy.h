// Post-processing of glslang's preprocessor output: it keeps one empty line for every line it
// removed (so line numbers stay right), which makes emitted files mostly blank. Runs of blank
// lines become a single `#line N` directive instead, so glslang's diagnostics on the emitted
// file still point at the right template line.
#pragma once

#include <string>

namespace shadowc {

std::string tidyPreprocessed(const std::string& text);

// Removes every `#line` directive (for files engines #include into their own shaders, where
// string-form #line would need GL_GOOGLE_cpp_style_line_directive) and collapses blank runs.
std::string stripLineDirectives(const std::string& text);

}  // namespace shadowc

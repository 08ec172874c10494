// The specialization block: a pass's typed values (plan/specialization.h) rendered as the text
// that replaces the template's `// @shadowc:specialize` marker line, right after
// #version/#extension — `#define` lines, the generated tables, then `#line` back into the
// template so that diagnostics point there. The emitter then runs the glslang preprocessor so
// that every unused technique is absent and every constant folded.
#pragma once

#include <string>

#include "plan/specialization.h"

namespace shadowc {

inline constexpr const char* kSpecializeMarker = "// @shadowc:specialize";

// One generated table as GLSL (a const array with its note, or the unrolled traversal).
std::string renderTable(const Table& table);

// `#define` lines, the tables, then `#line markerLine + 1` (`markerLine` is 1-based).
std::string specializationBlock(const Specialization& s, int markerLine);

// Replaces the marker line of `templateText` with specializationBlock().
// Returns the template unchanged when no marker is present.
std::string insertSpecialization(const std::string& templateText, const Specialization& s);

}  // namespace shadowc

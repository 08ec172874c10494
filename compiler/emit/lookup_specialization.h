// Lookup specialization: FilterSpec -> the #defines and generated GLSL (Poisson taps, quadtree
// Next/Child tables or unrolled traversal) that specialize templates/lookup/shadowc_lookup.glsl
// and templates/shade.comp. The emitter (B1) inserts them at the `// @shadowc:specialize`
// marker line, right after #version/#extension, then runs the glslang preprocessor so that
// every unused technique is absent and every constant folded.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "spec/filter_spec.h"

namespace shadowc {

struct LookupSpecialization {
  // Ordered (name, value) pairs, emitted as `#define name value`. Names all start SHADOWC_.
  std::vector<std::pair<std::string, std::string>> defines;
  // GLSL placed after the defines: const arrays and functions the templates call when the
  // matching SHADOWC_HAS_GENERATED_* define is set. Deterministic (same spec -> same bytes).
  std::string generatedCode;
};

LookupSpecialization specializeLookup(const FilterSpec& spec);

// The text to put in place of the marker line: `#define` lines, the generated code, then a
// `#line` directive so that diagnostics point back into the template. `markerLine` is the
// 1-based line number of the marker in the template.
std::string specializationBlock(const LookupSpecialization& s, int markerLine);

// Replaces the `// @shadowc:specialize` line of `templateText` with specializationBlock().
// Returns the template unchanged when no marker is present.
std::string insertSpecialization(const std::string& templateText, const LookupSpecialization& s);

inline constexpr const char* kSpecializeMarker = "// @shadowc:specialize";

}  // namespace shadowc

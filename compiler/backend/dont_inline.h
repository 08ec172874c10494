// Marks GLSL functions DontInline in a SPIR-V module (SPIR-V FunctionControl, spec 3.24), so
// that the -O recipe's exhaustive inliner (spirv-opt skips DontInline functions) keeps them as
// calls. The unrolled quadtree traversal calls its node test once per node (85 call sites at
// height 3, both walks); inlined, every pass of the recipe then works on ~20k instructions
// (docs/performance.md "Compilation": 2.6 s CPU before, 0.1 s after, measured pass by pass with
// `spirv-opt --time-report`). The driver still inlines them (Mesa inlines every call).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace shadowc {

// Sets DontInline on every function whose OpName is `name(` followed by glslang's mangled
// parameter list, for each name in `names`. Returns how many functions were marked.
int markDontInline(std::vector<uint32_t>& words, const std::vector<std::string>& names);

}  // namespace shadowc

// GLSL literals for folded constants: deterministic text (same double -> same bytes on every
// run), always a float literal ("40.0", not "40"), and round-trip precision for fp32.
#pragma once

#include <string>
#include <vector>

namespace shadowc {

std::string glslFloat(double v);
std::string glslFloatArray(const std::vector<double>& values);  // "float[](a, b, c)"

}  // namespace shadowc

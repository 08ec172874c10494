// Make dependency rules for `shadowc compile -M / -MD` (glslc's habit). Templates are embedded
// in the binary, so every output depends only on the .shadow input.
#pragma once

#include <string>
#include <vector>

namespace shadowc {

// "out1 out2 ...: input\n" with spaces, '#' and '$' escaped for make.
std::string makeDependencyRule(const std::vector<std::string>& outputs, const std::string& input);

}  // namespace shadowc

#include "plan/glsl_literal.h"

#include <fmt/format.h>

#include <cmath>

namespace shadowc {

std::string glslFloat(double v) {
  if (!std::isfinite(v)) v = v > 0 ? 3.4028234663852886e38 : -3.4028234663852886e38;
  // 9 significant digits round-trip an fp32 value; '.0' keeps integers float-typed.
  std::string s = fmt::format("{:.9g}", static_cast<double>(static_cast<float>(v)));
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

std::string glslFloatArray(const std::vector<double>& values) {
  std::string s = "float[](";
  for (size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + glslFloat(values[i]);
  return s + ")";
}

}  // namespace shadowc

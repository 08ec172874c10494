#include "emit/glsl_literal.h"

#include <fmt/format.h>

#include <cmath>

#include "plan/internal_error.h"

namespace shadowc {

std::string glslFloat(double v) {
  if (!std::isfinite(v)) throw InternalError(fmt::format("non-finite constant {} reached the emitter", v));
  std::string s = fmt::format("{:.9g}", v);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string glslFloatArray(const std::vector<double>& values) {
  std::string s = "float[](";
  for (size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + glslFloat(values[i]);
  return s + ")";
}

const char* glslQualifier(ImageFormat f) { return toString(f); }

std::string glslValue(const SpecValue& value) {
  struct Render {
    std::string operator()(long long v) const { return std::to_string(v); }
    std::string operator()(bool v) const { return v ? "1" : "0"; }
    std::string operator()(const Real& v) const { return glslFloat(v.value); }
    std::string operator()(const EnumCode& v) const { return std::to_string(v.code); }
    std::string operator()(ImageFormat v) const { return glslQualifier(v); }
    std::string operator()(const RealList& v) const { return glslFloatArray(v.values); }
  };
  return std::visit(Render{}, value);
}

}  // namespace shadowc

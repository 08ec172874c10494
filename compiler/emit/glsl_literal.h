// The one GLSL literal formatter: typed specialization values (plan/specialization.h) as
// deterministic GLSL text (same value -> same bytes on every run).
#pragma once

#include <string>
#include <vector>

#include "plan/specialization.h"

namespace shadowc {

// "%.9g" of the value (9 significant digits round-trip an fp32 value), always a float literal
// ("40.0", not "40"). Non-finite values are an InternalError: the checker keeps every constant
// finite, so one reaching the emitter is a shadowc bug, never a shader with inf in it.
std::string glslFloat(double v);
std::string glslFloatArray(const std::vector<double>& values);  // "float[](a, b, c)"

// The GLSL layout qualifier of a storage-image format ("rg32f", "rgba16", "rg32ui"); the
// manifest's format names are the GLSL names.
const char* glslQualifier(ImageFormat f);

// A macro value: integers and enum codes as decimal, booleans 1/0 (read with #if), reals by
// glslFloat, formats by glslQualifier, real lists by glslFloatArray.
std::string glslValue(const SpecValue& value);

}  // namespace shadowc

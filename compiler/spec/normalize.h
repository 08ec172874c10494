// Checker phase 2, normalization: every default explicit, including those that depend on other
// settings (kernel from blocker, sampling from kernel, exponents from the storage precision,
// splits from the layer count), so nothing downstream guesses a default or needs a fallback.
#pragma once

#include "spec/filter_spec.h"
#include "spec/read_settings.h"

namespace shadowc::spec {

// Fills `spec`  from what the file set (`given`). Afterwards
// spec.moments.splits always has layers+1 boundaries (uniform unless explicit; Lloyd starts
// uniform), and layers is 1 for the depth representation.
void normalize(FilterSpec& spec, const SettingsRead& given);

}  // namespace shadowc::spec

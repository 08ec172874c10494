// `--emit cpp`: one C++ header per filter, <filter>.h, that an engine compiles in with no JSON
// parser and no file loading: every pass's SPIR-V as a uint32_t array and the manifest as
// constexpr structs (images, passes, bindings, dispatch rules, push constants, the lookup's
// interface). The types are declared once (guarded) so several filter headers can share a TU;
// each filter lives in namespace shadowc_filters::<filter>. Schema: docs/integration.md.
#pragma once

#include <map>
#include <string>

#include "manifest/manifest.h"

namespace shadowc {

// `spirv` maps each Pass::spirv file name to its bytes (little-endian words). Throws
// std::invalid_argument when a pass names a file that is not there. Deterministic.
std::string cppHeader(const Manifest& manifest, const std::map<std::string, std::string>& spirv);

// "<filter>.h"
std::string cppHeaderFileName(const std::string& filterName);

}  // namespace shadowc

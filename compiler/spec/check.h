// Checker: AST -> FilterSpec. Resolves every setting and argument (unknown names get an
// edit-distance suggestion), fills every default explicitly (defaults that depend on other
// settings are resolved after all settings are read, so order in the file never matters),
// computes layer splits, and rejects impossible combinations with the reason (E04xx).
#pragma once

#include <optional>

#include "dsl/ast.h"
#include "dsl/diagnostics.h"
#include "spec/filter_spec.h"

namespace shadowc::spec {

// Returns a spec even when errors were reported (callers look at the sink); fields that failed
// to check keep their defaults.
FilterSpec check(const dsl::FilterDecl& filter, dsl::DiagnosticSink& sink);

// The setting keywords of the language, in documentation order (docs/dsl.md).
const std::vector<std::string_view>& settingKeywords();

}  // namespace shadowc::spec

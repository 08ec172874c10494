// Checker: AST -> FilterSpec. Resolves every setting and argument (unknown names get an
// edit-distance suggestion), fills every default explicitly (defaults that depend on other
// settings are resolved after all settings are read, so order in the file never matters),
// computes layer splits, and rejects impossible combinations with the reason (E04xx).
// The phases live in read_settings.h, normalize.h and combination_rules.h.
#pragma once

#include "dsl/ast.h"
#include "dsl/diagnostics.h"
#include "spec/filter_spec.h"
#include "spec/read_settings.h"  // settingKeywords()

namespace shadowc::spec {

// Returns a spec even when errors were reported (callers look at the sink); fields that failed
// to check keep their defaults.
FilterSpec check(const dsl::FilterDecl& filter, dsl::DiagnosticSink& sink);

}  // namespace shadowc::spec

// Checker phase 3, combination rules: impossible pairs of settings are errors with the reason
// (E04xx), dubious ones warnings (W05xx). One table (combination_rules.cpp): each row is the
// rule, its code, its message arguments and the token its caret points at.
#pragma once

#include "dsl/ast.h"
#include "dsl/diagnostics.h"
#include "spec/filter_spec.h"
#include "spec/read_settings.h"

namespace shadowc::spec {

// Reports every rule of the table that `spec` (normalized) breaks, in table order; carets point
// into `filter` through the locations kept in `given`.
void checkCombinations(const FilterSpec& spec, const SettingsRead& given, const dsl::FilterDecl& filter,
                       dsl::DiagnosticSink& sink);

}  // namespace shadowc::spec

// Checker phase 3, light rules: what a light type cannot serve (E045x), beside the combination
// table (combination_rules.h). A point light's cube map has six faces that no summed-area table,
// min-max pyramid or quadtree walk can span, and omnidirectional lights and cascades are not
// built yet: each is one located error that says which, never a shader that looks wrong.
#pragma once

#include "dsl/ast.h"
#include "dsl/diagnostics.h"
#include "spec/filter_spec.h"
#include "spec/read_settings.h"

namespace shadowc::spec {

void checkLightRules(const FilterSpec& spec, const SettingsRead& given, dsl::DiagnosticSink& sink);

}  // namespace shadowc::spec

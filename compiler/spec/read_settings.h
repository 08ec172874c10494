// Checker phase 1: reading settings. Each setting of the AST becomes typed fields of a
// FilterSpec, range-checked (E03xx); where each setting and value was written is kept for the
// carets of the later phases (normalize.h, combination_rules.h).
#pragma once

#include <string_view>
#include <vector>

#include "dsl/ast.h"
#include "dsl/diagnostics.h"
#include "spec/filter_spec.h"

namespace shadowc::spec {

struct SettingsRead {
  FilterSpec spec;  // what the file says; fields it does not set keep FilterSpec's defaults
  // Where each setting was written (nullptr: absent); `representation` is `depth` or `moments`.
  const dsl::Setting *light = nullptr, *representation = nullptr, *storage = nullptr, *blur = nullptr, *mips = nullptr,
                     *blocker = nullptr, *kernel = nullptr, *sampling = nullptr, *fallback = nullptr,
                     *contact = nullptr, *bleeding = nullptr, *cascades = nullptr, *weights = nullptr,
                     *lightSamples = nullptr, *mapSize = nullptr, *resolution = nullptr;
  const dsl::Setting* bias = nullptr;
  // Arguments whose presence changes a default or that a combination rule points at.
  const dsl::Value *exponent = nullptr, *negativeExponent = nullptr, *minVariance = nullptr, *split = nullptr,
                   *layers = nullptr, *momentBias = nullptr, *kernelMax = nullptr;
  bool lightSizeGiven = false;
  bool explicitOk = false;             // `split: explicit(...)` read without error
  std::vector<double> explicitSplits;  // its boundaries, in file order
};

SettingsRead readSettings(const dsl::FilterDecl& filter, dsl::DiagnosticSink& sink);

// The setting keywords of the language, in documentation order (docs/dsl.md).
const std::vector<std::string_view>& settingKeywords();

}  // namespace shadowc::spec

// Checker: AST -> FilterSpec in three phases, one file each, so the order of settings in a
// file never matters:
//   1. read_settings.cpp: each setting's value and arguments, typed and range-checked (E03xx);
//   2. normalize.cpp: every default explicit, including those that depend on other settings;
//   3. combination_rules.cpp: the table of impossible (E04xx) and dubious (W05xx) combinations,
//      and light_rules.cpp: what a light type cannot serve (E045x).
#include "spec/check.h"

#include "spec/combination_rules.h"
#include "spec/light_rules.h"
#include "spec/normalize.h"
#include "spec/read_settings.h"

namespace shadowc::spec {

FilterSpec check(const dsl::FilterDecl& filter, dsl::DiagnosticSink& sink) {
  const int errorsBefore = sink.errors();
  SettingsRead read = readSettings(filter, sink);
  if (sink.stopped()) return std::move(read.spec);
  FilterSpec spec = std::move(read.spec);
  normalize(spec, read);
  // A setting that failed to read keeps its default, so combination rules would report
  // follow-on errors about settings the user did write: check combinations on clean input only.
  if (sink.errors() == errorsBefore && filter.badLines.empty()) {
    checkCombinations(spec, read, filter, sink);
    checkLightRules(spec, read, sink);
  }
  return spec;
}

}  // namespace shadowc::spec

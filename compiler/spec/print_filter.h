// The spec printer: FilterSpec -> an ordinary filter description (docs/dsl.md) whose load gives
// back the same normalized spec: specToJson(load(printFilter(s))) == specToJson(s) for every
// spec the checker produces. Every setting and argument is written out explicitly, so the
// result does not depend on the checker's defaults.
//
// Users: `shadowc plan` writes its plans with it, and the compiler driver re-checks hand-built
// specs by printing and loading them (a field the language cannot express then shows up as a
// difference of the two specs' JSON).
//
// Not printable: FilterSpec::naiveUnguarded (debug only, not reachable from the language; the
// stability suite sets it on a checked spec) and `location`. Fields the language has no syntax
// for in the chosen variant (e.g. blocker taps with `blocker moments`) are printed only through
// the variant that uses them.
#pragma once

#include <string>

#include "spec/filter_spec.h"

namespace shadowc {

std::string printFilter(const FilterSpec& spec);

}  // namespace shadowc

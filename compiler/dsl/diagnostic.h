// One diagnostic of the front end and its glslc-style formatter. This is the bottom of the
// front end: dsl/ and spec/ both use it, and it includes nothing of spec/ (the include rule
// tests/architecture/dsl_spec_cycle_test.cpp keeps: dsl/ never includes spec/).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "dsl/source_location.h"

namespace shadowc {

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string code;         // stable code from the diagnostics table, e.g. "E0102"
  SourceLocation location;  // file, 1-based line and column (0:0 = the whole file)
  int length = 1;           // bytes the caret line underlines (^~~~)
  std::string message;
  std::string suggestion;  // "did you mean 'quadtree'?" or empty
};

// glslc form: "file:line:col: error: message [code]", the line of `source` it points at, a
// caret line, a suggestion line when present; then "N errors generated." (and warnings) when any.
std::string formatDiagnostics(const std::vector<Diagnostic>& diagnostics, std::string_view source);

}  // namespace shadowc

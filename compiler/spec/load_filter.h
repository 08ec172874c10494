// The front end's public face: text -> diagnostics + checked FilterSpec, and the spec's JSON.
// Implemented by dsl/ (lexer, parser), spec/ (checker, normalization) and dsl/diagnostics.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "spec/filter_spec.h"

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

struct LoadOptions {
  bool warningsAsErrors = false;  // -Werror
};

struct LoadResult {
  std::optional<FilterSpec> spec;  // set only when there is no error
  std::vector<Diagnostic> diagnostics;
  std::string source;  // the text that was read (for carets)
  int errorCount() const;
  int warningCount() const;
};

LoadResult loadFilterSource(const std::string& text, const std::string& fileName, const LoadOptions& = {});
LoadResult loadFilterFile(const std::string& path, const LoadOptions& = {});  // missing file -> one error

// glslc form: "file:line:col: error: message [code]", the source line, a caret line, a
// suggestion line when present; then "N errors generated." (and warnings) when any.
std::string formatDiagnostics(const LoadResult& result);

// The normalized spec as JSON (fixed key order; every field explicit). Used by --print-spec
// and by manifest.json's "spec".
nlohmann::ordered_json specToJson(const FilterSpec& spec);

}  // namespace shadowc

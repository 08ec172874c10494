// The front end's public face: text -> diagnostics + checked FilterSpec, and the spec's JSON.
// Implemented by dsl/ (lexer, parser), spec/ (checker, normalization) and dsl/diagnostics.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dsl/diagnostic.h"
#include "spec/filter_spec.h"

namespace shadowc {

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

// formatDiagnostics(result.diagnostics, result.source) (dsl/diagnostic.h).
std::string formatDiagnostics(const LoadResult& result);

// The normalized spec as JSON (fixed key order; every field explicit). Used by --print-spec
// and by manifest.json's "spec".
nlohmann::ordered_json specToJson(const FilterSpec& spec);

}  // namespace shadowc

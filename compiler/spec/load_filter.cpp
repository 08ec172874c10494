// loadFilterSource / loadFilterFile: the front end's driver (lex -> parse -> check).
#include "spec/load_filter.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "dsl/lexer.h"
#include "dsl/parser.h"
#include "spec/check.h"

namespace shadowc {
namespace {
// Filter descriptions are a few hundred bytes; 1 MiB bounds the work on hostile input
// (the lexer is linear anyway, but nobody wants a megabyte of carets).
constexpr size_t kMaxSourceBytes = 1 << 20;

// The parser reports before the checker runs; readers expect file order (as glslc prints).
// A note stays right after the diagnostic it belongs to; file-level ones (line 0) go last.
void sortByLocation(std::vector<Diagnostic>& diagnostics) {
  std::vector<std::vector<Diagnostic>> groups;
  for (Diagnostic& d : diagnostics) {
    if (d.severity == Severity::Note && !groups.empty())
      groups.back().push_back(std::move(d));
    else
      groups.push_back({std::move(d)});
  }
  std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) {
    auto key = [](const Diagnostic& d) {
      return std::pair(d.location.line == 0 ? INT32_MAX : d.location.line, d.location.column);
    };
    return key(a.front()) < key(b.front());
  });
  diagnostics.clear();
  for (auto& g : groups)
    for (Diagnostic& d : g) diagnostics.push_back(std::move(d));
}
// Where a JSON object opens the text: a filter's first token is `filter` (docs/dsl.md "Grammar"),
// so a `{` before it, past whitespace and comments, is JSON (a manifest, a scene) that the lexer
// would answer with an error per quote. {0, 0} when the text does not start that way.
std::pair<int, int> openingBrace(const std::string& text) {
  int line = 1;
  size_t lineBegin = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '#') {
      i = text.find('\n', i);
      if (i == std::string::npos) break;
    }
    if (text[i] == '\n') {
      ++line, lineBegin = i + 1;
      continue;
    }
    if (ch == ' ' || ch == '\t' || ch == '\r') continue;
    if (ch == '{') return {line, int(i - lineBegin) + 1};
    break;
  }
  return {0, 0};
}

}  // namespace

std::string formatDiagnostics(const LoadResult& result) { return formatDiagnostics(result.diagnostics, result.source); }

int LoadResult::errorCount() const {
  int n = 0;
  for (const Diagnostic& d : diagnostics) n += d.severity == Severity::Error;
  return n;
}
int LoadResult::warningCount() const {
  int n = 0;
  for (const Diagnostic& d : diagnostics) n += d.severity == Severity::Warning;
  return n;
}

LoadResult loadFilterSource(const std::string& text, const std::string& fileName, const LoadOptions& options) {
  LoadResult result;
  dsl::DiagnosticSink sink(result.diagnostics, fileName, options.warningsAsErrors);
  if (text.size() > kMaxSourceBytes) {
    sink.report(dsl::DiagId::fileTooLarge, 0, 0, 1, text.size(), kMaxSourceBytes);
    return result;
  }
  result.source = text;
  if (const auto [line, column] = openingBrace(text); line > 0) {
    sink.report(dsl::DiagId::jsonNotFilter, line, column, 1);
    return result;
  }
  std::vector<int> badLines;
  const std::vector<dsl::Token> tokens = dsl::lex(result.source, sink, &badLines);
  if (sink.stopped()) return result;
  dsl::File file = dsl::parse(tokens, sink);
  file.filter.badLines = std::move(badLines);
  if (!file.hasFilter || sink.stopped()) return result;
  FilterSpec spec = spec::check(file.filter, sink);
  sortByLocation(result.diagnostics);
  if (result.errorCount() == 0) result.spec = std::move(spec);
  return result;
}

LoadResult loadFilterFile(const std::string& path, const LoadOptions& options) {
  std::error_code ec;
  std::ifstream in;
  if (std::filesystem::is_regular_file(path, ec)) in.open(path, std::ios::binary);
  if (!in.is_open()) {
    LoadResult result;
    dsl::DiagnosticSink sink(result.diagnostics, path, options.warningsAsErrors);
    sink.report(dsl::DiagId::cannotReadFile, 0, 0, 1, "no such file or not readable");
    return result;
  }
  // Read at most one byte past the limit: a huge file is rejected without reading it whole.
  std::string text(kMaxSourceBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  if (text.size() > kMaxSourceBytes) {
    in.seekg(0, std::ios::end);
    const auto size = static_cast<size_t>(in.tellg());
    LoadResult result;
    dsl::DiagnosticSink sink(result.diagnostics, path, options.warningsAsErrors);
    sink.report(dsl::DiagId::fileTooLarge, 0, 0, 1, size, kMaxSourceBytes);
    return result;
  }
  return loadFilterSource(text, path, options);
}

}  // namespace shadowc

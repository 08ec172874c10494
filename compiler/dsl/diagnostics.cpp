// The diagnostics table, the capped sink, typo suggestions and the glslc-style formatter.
#include "dsl/diagnostics.h"

#include <algorithm>
#include <array>
#include <sstream>

namespace shadowc::dsl {
namespace {
constexpr std::array kTable = {
#define DIAGNOSTIC(code, severity, name, format) DiagInfo{#code, Severity::severity, #name, format},
#include "dsl/diagnostics.def"
#undef DIAGNOSTIC
};
}  // namespace

const DiagInfo& diagInfo(DiagId id) { return kTable[static_cast<size_t>(id)]; }

void DiagnosticSink::emit(DiagId id, int line, int column, int length, std::string message) {
  lastKept_ = false;
  if (stopped_) return;
  const DiagInfo& info = diagInfo(id);
  Severity severity = info.severity;
  if (severity == Severity::Warning && werror_) severity = Severity::Error;
  if (severity == Severity::Error && errors_ == kMaxErrors) {
    // The cap keeps binary garbage or a 10 MB file at a readable, bounded report.
    stopped_ = true;
    const DiagInfo& cap = diagInfo(DiagId::tooManyErrors);
    out_.push_back(Diagnostic{Severity::Error, cap.code, SourceLocation{file_, 0, 0}, 0,
                              fmt::format(fmt::runtime(cap.format), kMaxErrors), ""});
    return;
  }
  if (severity == Severity::Error) ++errors_;
  out_.push_back(Diagnostic{severity, info.code, SourceLocation{file_, line, column}, std::max(length, 1),
                            std::move(message), ""});
  lastKept_ = true;
}

void DiagnosticSink::suggest(const std::string& suggestion) {
  if (lastKept_ && !suggestion.empty()) out_.back().suggestion = "did you mean '" + suggestion + "'?";
}

}  // namespace shadowc::dsl

namespace shadowc {
namespace {
const char* severityName(Severity s) {
  switch (s) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "error";
}

// Line `line` (1-based) of `source`, without its newline.
std::string_view sourceLine(std::string_view source, int line) {
  size_t start = 0;
  for (int l = 1; l < line; ++l) {
    const size_t nl = source.find('\n', start);
    if (nl == std::string_view::npos) return {};
    start = nl + 1;
  }
  size_t end = source.find('\n', start);
  if (end == std::string_view::npos) end = source.size();
  std::string_view text = source.substr(start, end - start);
  if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
  return text;
}

// Bytes that would garble a terminal become '?'; the caret line mirrors tabs so it lines up.
char printable(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u == '\t' || (u >= 0x20 && u < 0x7f) || u >= 0x80) ? c : '?';
}

void appendSnippet(std::string& out, std::string_view source, const Diagnostic& d) {
  if (d.location.line <= 0) return;
  std::string_view text = sourceLine(source, d.location.line);
  size_t col = static_cast<size_t>(std::max(d.location.column, 1)) - 1;
  // Very long lines (generated files) are cut to a window around the column.
  constexpr size_t kWindow = 100;
  size_t from = 0;
  std::string prefix;
  if (col > kWindow) from = col - kWindow / 2, prefix = "...";
  std::string_view shown = text.substr(std::min(from, text.size()), 2 * kWindow);
  std::string line = prefix, caret(prefix.size(), ' ');
  bool nonAscii = false;
  for (char c : shown) nonAscii |= static_cast<unsigned char>(c) >= 0x80;
  for (char c : shown) line += nonAscii && static_cast<unsigned char>(c) >= 0x80 ? '?' : printable(c);
  const size_t caretAt = col - from;
  for (size_t i = 0; i < caretAt && i < shown.size(); ++i) caret += shown[i] == '\t' ? '\t' : ' ';
  caret += '^';
  const size_t len = static_cast<size_t>(std::max(d.length, 1));
  for (size_t i = 1; i < len && caretAt + i < shown.size(); ++i) caret += '~';
  out += line + "\n" + caret + "\n";
}
}  // namespace

std::string formatDiagnostics(const std::vector<Diagnostic>& diagnostics, std::string_view source) {
  std::string out;
  int errors = 0, warnings = 0;
  for (const Diagnostic& d : diagnostics) {
    if (d.severity == Severity::Error) ++errors;
    if (d.severity == Severity::Warning) ++warnings;
    std::string where = d.location.file;
    if (d.location.line > 0) where += fmt::format(":{}:{}", d.location.line, d.location.column);
    out += fmt::format("{}: {}: {} [{}]\n", where, severityName(d.severity), d.message, d.code);
    appendSnippet(out, source, d);
    if (!d.suggestion.empty()) out += "note: " + d.suggestion + "\n";
  }
  auto plural = [](int n, const char* what) { return fmt::format("{} {}{}", n, what, n == 1 ? "" : "s"); };
  if (errors > 0 && warnings > 0)
    out += fmt::format("{} and {} generated.\n", plural(warnings, "warning"), plural(errors, "error"));
  else if (errors > 0)
    out += plural(errors, "error") + " generated.\n";
  else if (warnings > 0)
    out += plural(warnings, "warning") + " generated.\n";
  return out;
}

}  // namespace shadowc

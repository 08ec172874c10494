// Diagnostics of the front end: ids from the one table (diagnostics.def), a sink that collects
// them with a hard cap on the error count, edit-distance suggestions, and the glslc-style
// formatter. Tests assert on codes (Diagnostic::code), never on wording.
#pragma once

#include <fmt/format.h>

#include <string>
#include <string_view>
#include <vector>

#include "dsl/diagnostic.h"
#include "support/suggest.h"  // closestMatch for DiagnosticSink::suggest's callers

namespace shadowc::dsl {

enum class DiagId {
#define DIAGNOSTIC(code, severity, name, format) name,
#include "dsl/diagnostics.def"
#undef DIAGNOSTIC
};

struct DiagInfo {
  const char* code;
  Severity severity;
  const char* name;
  const char* format;
};
const DiagInfo& diagInfo(DiagId id);

// At most this many errors are reported per file; then E0003 and the front end stops.
inline constexpr int kMaxErrors = 20;

class DiagnosticSink {
 public:
  DiagnosticSink(std::vector<Diagnostic>& out, std::string file, bool warningsAsErrors = false)
      : out_(out), file_(std::move(file)), werror_(warningsAsErrors) {}

  template <typename... Args>
  void report(DiagId id, int line, int column, int length, const Args&... args) {
    emit(id, line, column, length, fmt::format(fmt::runtime(diagInfo(id).format), args...));
  }
  // The same with the arguments already packed (table-driven callers: spec/combination_rules.cpp).
  void vreport(DiagId id, int line, int column, int length, fmt::format_args args) {
    emit(id, line, column, length, fmt::vformat(diagInfo(id).format, args));
  }
  // Attaches "did you mean '...'?" to the last reported diagnostic (when it was kept).
  void suggest(const std::string& suggestion);

  bool stopped() const { return stopped_; }  // error cap reached: callers unwind
  int errors() const { return errors_; }
  const std::string& file() const { return file_; }

 private:
  void emit(DiagId id, int line, int column, int length, std::string message);
  std::vector<Diagnostic>& out_;
  std::string file_;
  int errors_ = 0;
  bool werror_ = false;
  bool stopped_ = false;
  bool lastKept_ = false;
};

}  // namespace shadowc::dsl

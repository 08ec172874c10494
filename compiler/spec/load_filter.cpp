// loadFilterSource / loadFilterFile: the front end's driver (lex -> parse -> check).
#include "spec/load_filter.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dsl/lexer.h"
#include "dsl/parser.h"
#include "spec/check.h"

namespace shadowc {
namespace {
// Filter descriptions are a few hundred bytes; 1 MiB bounds the work on hostile input
// (the lexer is linear anyway, but nobody wants a megabyte of carets).
constexpr size_t kMaxSourceBytes = 1 << 20;
}  // namespace

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
  const std::vector<dsl::Token> tokens = dsl::lex(result.source, sink);
  if (sink.stopped()) return result;
  const dsl::File file = dsl::parse(tokens, sink);
  if (!file.hasFilter || sink.stopped()) return result;
  FilterSpec spec = spec::check(file.filter, sink);
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

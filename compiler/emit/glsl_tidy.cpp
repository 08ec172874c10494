#include "emit/glsl_tidy.h"

#include <sstream>
#include <string_view>
#include <vector>

namespace shadowc {
namespace {

bool isBlank(std::string_view s) { return s.find_first_not_of(" \t\r") == std::string_view::npos; }

std::string_view trimLeft(std::string_view s) {
  const size_t i = s.find_first_not_of(" \t");
  return i == std::string_view::npos ? std::string_view{} : s.substr(i);
}

bool isLineDirective(std::string_view s) { return trimLeft(s).starts_with("#line"); }

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    while (!l.empty() && (l.back() == ' ' || l.back() == '\t' || l.back() == '\r')) l.pop_back();
    lines.push_back(std::move(l));
  }
  return lines;
}

// Appends a #line directive; one without a file name that it directly follows says nothing.
void appendDirective(std::string& out, const std::string& directive) {
  if (out.size() >= 2) {
    const size_t start = out.rfind('\n', out.size() - 2);
    const std::string_view last = std::string_view(out).substr(start == std::string::npos ? 0 : start + 1);
    if (isLineDirective(last) && last.find('"') == std::string_view::npos) out.resize(out.size() - last.size());
  }
  out += directive + "\n";
}

}  // namespace

std::string tidyPreprocessed(const std::string& text) {
  const std::vector<std::string> lines = splitLines(text);
  std::string out;
  int next = 1;  // line number (in the current source string) of lines[i]
  for (size_t i = 0; i < lines.size();) {
    const std::string& l = lines[i];
    if (isLineDirective(l)) {
      // "#line N" or "#line N \"file\"": the following line is number N.
      appendDirective(out, l);
      next = std::atoi(std::string(trimLeft(l).substr(5)).c_str());
      ++i;
      continue;
    }
    if (isBlank(l)) {
      size_t j = i;
      while (j < lines.size() && isBlank(lines[j])) ++j;
      const int run = static_cast<int>(j - i);
      if (j == lines.size()) break;  // trailing blanks: drop
      if (run == 1) {
        out += "\n";
      } else if (!isLineDirective(lines[j])) {
        appendDirective(out, "#line " + std::to_string(next + run));
      }
      next += run;
      i = j;
      continue;
    }
    out += l + "\n";
    ++next;
    ++i;
  }
  return out;
}

std::string stripLineDirectives(const std::string& text) {
  std::string out;
  bool lastBlank = true;
  for (const std::string& l : splitLines(text)) {
    if (isLineDirective(l)) continue;
    const bool blank = isBlank(l);
    if (blank && lastBlank) continue;
    out += blank ? "\n" : l + "\n";
    lastBlank = blank;
  }
  while (out.size() >= 2 && out[out.size() - 1] == '\n' && out[out.size() - 2] == '\n') out.pop_back();
  return out;
}

}  // namespace shadowc

#include "sweep/filter_text.h"

#include <stdexcept>

namespace shadowc::sweep {
namespace {

bool isNameChar(char c) { return std::isalnum((unsigned char)c) || c == '_'; }

// The first word of a line (after indentation), "" when the line is blank or a comment.
std::string firstWord(const std::string& line) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos) return "";
  size_t j = i;
  while (j < line.size() && isNameChar(line[j])) ++j;
  return line.substr(i, j - i);
}

// Parenthesis depth change of a line, ignoring its comment.
int parenBalance(const std::string& line) {
  int d = 0;
  for (char c : line) {
    if (c == '#') break;
    d += c == '(' ? 1 : c == ')' ? -1 : 0;
  }
  return d;
}

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t nl = text.find('\n', start);
    if (nl == std::string::npos) {
      if (start < text.size()) lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, nl - start));
    start = nl + 1;
  }
  return lines;
}

}  // namespace

std::vector<std::string> placeholders(const std::string& text) {
  std::vector<std::string> names;
  for (size_t i = text.find("${"); i != std::string::npos; i = text.find("${", i + 2)) {
    const size_t end = text.find('}', i + 2);
    if (end == std::string::npos) break;
    const std::string name = text.substr(i + 2, end - i - 2);
    bool seen = false;
    for (const auto& n : names) seen = seen || n == name;
    if (!seen) names.push_back(name);
  }
  return names;
}

std::string fillPlaceholders(const std::string& text, const std::map<std::string, std::string>& values) {
  std::string out;
  size_t pos = 0;
  for (size_t i = text.find("${"); i != std::string::npos; i = text.find("${", pos)) {
    const size_t end = text.find('}', i + 2);
    if (end == std::string::npos) break;
    const std::string name = text.substr(i + 2, end - i - 2);
    const auto it = values.find(name);
    if (it == values.end()) throw std::out_of_range("${" + name + "} has no value");
    out.append(text, pos, i - pos);
    out += it->second;
    pos = end + 1;
  }
  out.append(text, pos, std::string::npos);
  return out;
}

std::string setSetting(const std::string& text, const std::string& keyword, const std::optional<std::string>& value) {
  const std::vector<std::string> lines = splitLines(text);
  auto matches = [&](const std::string& word) {
    if (word == keyword) return true;
    const bool representation = keyword == "depth" || keyword == "moments";
    return representation && (word == "depth" || word == "moments");
  };
  std::vector<std::string> out;
  bool inFilter = false, replaced = false;
  int depth = 0;  // brace depth: settings live at depth 1
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const std::string word = firstWord(line);
    if (depth == 1 && inFilter && matches(word)) {
      // Skip the setting's continuation lines (an argument list spanning lines).
      int balance = parenBalance(line);
      while (balance > 0 && i + 1 < lines.size()) balance += parenBalance(lines[++i]);
      if (value && !replaced) out.push_back("    " + keyword + " " + *value);
      replaced = true;
      continue;
    }
    const size_t close = line.find('}');
    const bool closesFilter = inFilter && depth == 1 && close != std::string::npos && line.find('#') > close &&
                              line.find_first_not_of(" \t") == close;
    if (closesFilter && !replaced && value) {
      out.push_back("    " + keyword + " " + *value);
      replaced = true;
    }
    out.push_back(line);
    for (char c : line) {
      if (c == '#') break;
      if (c == '{') {
        ++depth;
        inFilter = true;
      } else if (c == '}') {
        --depth;
      }
    }
  }
  std::string result;
  for (const auto& l : out) result += l + "\n";
  if (!replaced && value) {  // a one-line filter ("filter f { depth }"): before its last '}'
    const size_t close = result.rfind('}');
    if (close != std::string::npos) result.insert(close, "\n    " + keyword + " " + *value + "\n");
  }
  return result;
}

}  // namespace shadowc::sweep

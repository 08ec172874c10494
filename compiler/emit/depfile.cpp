#include "emit/depfile.h"

namespace shadowc {
namespace {

std::string escapeForMake(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

}  // namespace

std::string makeDependencyRule(const std::vector<std::string>& outputs, const std::string& input) {
  std::string rule;
  for (size_t i = 0; i < outputs.size(); ++i) rule += (i ? " " : "") + escapeForMake(outputs[i]);
  return rule + ": " + escapeForMake(input) + "\n";
}

}  // namespace shadowc

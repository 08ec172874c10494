// A place in a filter description: the file and a 1-based line and column (0:0 = the whole
// file). Shared by diagnostics (dsl/diagnostic.h) and the spec (FilterSpec::location).
#pragma once

#include <string>

namespace shadowc {

struct SourceLocation {
  std::string file;
  int line = 0, column = 0;
};

}  // namespace shadowc

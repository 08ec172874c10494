// AST of a filter description: what the parser saw, with locations, before any checking.
//   filter NAME { setting* }      setting = NAME value?      value = term
//   term = NAME [ '(' arg, ... ')' ] | NUMBER | SIZE          arg = [NAME ':'] term
#pragma once

#include <string>
#include <vector>

namespace shadowc::dsl {

struct Argument;

struct Value {
  enum class Kind { Name, Number, Size };
  Kind kind = Kind::Name;
  int line = 0, column = 0, length = 1;
  std::string text;           // as written (name, number or size)
  double number = 0;          // Number
  bool integer = false;       // Number written without '.' or exponent
  int width = 0, height = 0;  // Size
  bool hasArguments = false;  // Name followed by '(' ... ')'
  std::vector<Argument> arguments;
};

struct Argument {
  std::string name;          // empty for a positional argument
  int line = 0, column = 0;  // of the name (or of the value when positional)
  Value value;
};

struct Setting {
  std::string keyword;
  int line = 0, column = 0;
  bool hasValue = false;
  Value value;
};

struct FilterDecl {
  std::string name;
  int line = 0, column = 0;  // of the `filter` keyword
  std::vector<Setting> settings;
  std::vector<int> badLines;  // lines with lexical errors: their settings are not checked
};

struct File {
  bool hasFilter = false;  // false when the parser found no `filter NAME {`
  FilterDecl filter;
};

}  // namespace shadowc::dsl

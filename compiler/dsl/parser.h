// Parser: tokens -> AST. Recovers at statement level (skips to the next line) so every
// syntax error of a file is reported in one run; nesting depth is bounded (kMaxNesting)
// so hostile input cannot exhaust the stack.
#pragma once

#include <vector>

#include "dsl/ast.h"
#include "dsl/lexer.h"

namespace shadowc::dsl {

inline constexpr int kMaxNesting = 8;

File parse(const std::vector<Token>& tokens, DiagnosticSink& sink);

}  // namespace shadowc::dsl

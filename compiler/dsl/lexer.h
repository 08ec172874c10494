// Lexer of the filter-description language (docs/dsl.md "Lexical structure").
// Tokens: names, numbers (1, 0.04, 1e-5, -2), sizes (3x3), punctuation { } ( ) , :.
// `#` starts a comment to the end of the line. Every token knows whether it is the first
// on its line: the parser uses that to end a setting (one setting per line).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "dsl/diagnostics.h"

namespace shadowc::dsl {

enum class TokenKind { Name, Number, Size, LBrace, RBrace, LParen, RParen, Comma, Colon, End };

struct Token {
  TokenKind kind = TokenKind::End;
  std::string_view text;  // view into the source
  int line = 1, column = 1;
  bool lineStart = false;     // first token on its line
  double number = 0;          // Number
  bool integer = false;       // Number written without '.', 'e'
  int width = 0, height = 0;  // Size
};

// "name 'kernel'", "number '3'", "'{'", "end of file": how diagnostics quote a token.
std::string describe(const Token& t);

inline constexpr size_t kMaxNameLength = 64;

// Lexes the whole text. Binary input (NUL byte, invalid UTF-8) is one E0102 and an empty
// token list: a garbage file gets one error, not thousands. Always ends with an End token.
// Lines that had a lexical error are added to `badLines` (when given): the checker skips the
// settings on them, because a dropped token would otherwise cause a follow-on error.
std::vector<Token> lex(std::string_view source, DiagnosticSink& sink, std::vector<int>* badLines = nullptr);

}  // namespace shadowc::dsl
